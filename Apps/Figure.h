#ifndef Figure_h
#define Figure_h

#include "CameraOptions.h"
#include "RenderingBackend.h"

#include <string>

namespace cli
{

struct FigureOptions
{
  std::string Input; ///< a model of the set or a mesh file
  std::string Output;
  std::string Plot; ///< optional: the time-against-triangles plot
  int CoarseTriangles = 0;
  int FineLevel = 3;
  int Frames = 30;
  std::string DataDirectory;
  CameraOptions Camera; ///< its ViewportSize is the size of one panel
};

/// `silhouette figure`: Xing's Fig. 1 and 7 panels in one labelled image,
/// and optionally a plot of whole-frame time against triangle count.
void RunFigure(const FigureOptions& options);

std::string FigureHelp();

class ArgumentList;

/// The options of `silhouette figure ...`, and its --backend into
/// `backend`; throws UsageError.
FigureOptions ParseFigure(ArgumentList& arguments, RenderBackend& backend);

} // namespace cli

#endif
