// Holds the prepared meshes' background index builds (the silhouette triangle
// tree, the fold guard's grid) at their start while a test looks at frames
// run without them: a build cannot finish before the test releases it, so
// what is checked meanwhile does not depend on how fast the thread is.
#pragma once

#include "PreparedMesh.h"

#include <future>

namespace coretest
{

class HeldBackgroundBuilds
{
public:
  HeldBackgroundBuilds()
  {
    std::shared_future<void> go = this->Gate.get_future().share();
    silsmooth::PreparedMesh::setBackgroundBuildHook([go] { go.wait(); });
  }
  /// Lets every held build and every later one go.
  void release()
  {
    if (!this->Released)
    {
      this->Released = true;
      this->Gate.set_value();
    }
  }
  ~HeldBackgroundBuilds()
  {
    this->release();
    silsmooth::PreparedMesh::setBackgroundBuildHook({});
  }
  HeldBackgroundBuilds(const HeldBackgroundBuilds&) = delete;
  HeldBackgroundBuilds& operator=(const HeldBackgroundBuilds&) = delete;

private:
  std::promise<void> Gate;
  bool Released = false;
};

} // namespace coretest
