#include "PreparedMesh.h"

#include "ConeApexes.h"
#include "ShadingNormals.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <mutex>
#include <thread>
#include <tuple>
#include <unordered_map>

namespace silsmooth
{

namespace
{

// PreparedMesh::setBackgroundBuildHook's function. Never destroyed: a
// detached build may still be running when the program ends.
struct BackgroundBuildHook
{
  std::mutex Mutex;
  std::function<void()> Hook;
};

BackgroundBuildHook& backgroundBuildHook()
{
  static BackgroundBuildHook* hook = new BackgroundBuildHook;
  return *hook;
}

void runBackgroundBuildHook()
{
  std::function<void()> hook;
  {
    std::lock_guard<std::mutex> lock(backgroundBuildHook().Mutex);
    hook = backgroundBuildHook().Hook;
  }
  if (hook)
  {
    hook();
  }
}

} // namespace

void PreparedMesh::setBackgroundBuildHook(std::function<void()> hook)
{
  std::lock_guard<std::mutex> lock(backgroundBuildHook().Mutex);
  backgroundBuildHook().Hook = std::move(hook);
}

namespace
{

// The feature edges that are edges of the triangles (normalised, sorted).
std::vector<FeatureEdge> featureEdgesOfTriangles(std::vector<FeatureEdge> featureEdges,
  const std::vector<Triangle>& triangles, const EdgeTable* edges)
{
  // Only edges of the triangles can be feature edges.
  featureEdges = normalizedFeatureEdges(std::move(featureEdges));
  const EdgeTable built = edges ? EdgeTable() : EdgeTable(triangles);
  const EdgeTable& input = edges ? *edges : built;
  std::size_t e = 0;
  featureEdges.erase(
    std::remove_if(featureEdges.begin(), featureEdges.end(),
      [&](const FeatureEdge& f) {
        while (e < input.edgeCount() &&
          FeatureEdge(input.edge(static_cast<Id>(e)).low, input.edge(static_cast<Id>(e)).high) < f)
        {
          ++e;
        }
        return e == input.edgeCount() ||
          FeatureEdge(input.edge(static_cast<Id>(e)).low, input.edge(static_cast<Id>(e)).high) != f;
      }),
    featureEdges.end());
  return featureEdges;
}

} // namespace

PreparedMesh::PreparedMesh(std::vector<glm::dvec3> points, std::vector<Triangle> triangles,
  const std::vector<glm::dvec3>& normals, std::vector<FeatureEdge> featureEdges,
  const CornerNormals& cornerNormals, const EdgeTable* edges, NormalWeighting weighting)
  : Points(std::move(points))
  , Triangles(std::move(triangles))
  , InputPointCount(this->Points.size())
{
  if (!featureEdges.empty())
  {
    this->Features = FeatureCurves(
      this->Points, featureEdgesOfTriangles(std::move(featureEdges), this->Triangles, edges));
  }
  this->splitAtFeatures();
  this->Edges = this->Features.empty() && edges ? *edges : EdgeTable(this->Triangles);
  this->findBoundaries();
  this->indexFeatureEdges();
  this->findNeighbours();
  this->chooseNormals(normals, cornerNormals, weighting);
  this->Apexes = coneApexes(this->Points, this->Triangles);
}

std::unique_ptr<PreparedMesh> PreparedMesh::moved(PreparedMesh& earlier,
  std::vector<glm::dvec3>&& points, const std::vector<glm::dvec3>& normals,
  const std::vector<FeatureEdge>& featureEdges, const CornerNormals& cornerNormals,
  const EdgeTable& edges, NormalWeighting weighting)
{
  if (points.size() != earlier.InputPointCount)
  {
    return nullptr;
  }
  // The features as the constructor keeps them (FeatureCurves also drops
  // ids beyond the input's points, which no edge of the table has).
  const bool sameSplit = featureEdges.empty()
    ? earlier.Features.empty()
    : featureEdgesOfTriangles(featureEdges, {}, &edges) == earlier.Features.edges();
  if (!sameSplit)
  {
    return nullptr;
  }
  return std::unique_ptr<PreparedMesh>(
    new PreparedMesh(earlier, std::move(points), normals, cornerNormals, weighting));
}

PreparedMesh::PreparedMesh(PreparedMesh& earlier, std::vector<glm::dvec3> points,
  const std::vector<glm::dvec3>& normals, const CornerNormals& cornerNormals,
  NormalWeighting weighting)
  : Points(std::move(points))
  , InputPointCount(earlier.InputPointCount)
{
  if (!earlier.Features.empty())
  {
    this->Features = FeatureCurves(this->Points, earlier.Features.edges());
  }
  for (const Id source : earlier.CopySources)
  {
    this->Points.push_back(this->Points[static_cast<std::size_t>(source)]);
  }
  // Before the triangles are taken: adopting compares the points with
  // earlier's.
  this->adoptTriangleGridOfMoved(earlier);
  this->Triangles = std::move(earlier.Triangles);
  this->Edges = std::move(earlier.Edges);
  this->CopySources = std::move(earlier.CopySources);
  this->OnFeature = std::move(earlier.OnFeature);
  this->OnBoundary = std::move(earlier.OnBoundary);
  this->BoundaryEdges = std::move(earlier.BoundaryEdges);
  this->NeighbourOffsets = std::move(earlier.NeighbourOffsets);
  this->Neighbours = std::move(earlier.Neighbours);
  // Which feature edges are smoothed depends on the positions.
  this->indexFeatureEdges();
  this->chooseNormals(normals, cornerNormals, weighting);
  // Kept: a cone that moves stays a cone, and finding the apexes again
  // would cost a deforming frame about 35 ms at 1.3M triangles.
  this->Apexes = std::move(earlier.Apexes);
}

void PreparedMesh::splitAtFeatures()
{
  if (this->Features.empty())
  {
    return;
  }
  FeatureSplit split = splitAtFeatureEdges(this->Points.size(), this->Triangles, this->Features);
  this->Triangles = std::move(split.Triangles);
  this->CopySources = std::move(split.CopySources);
  this->OnFeature = std::move(split.OnFeature);
  for (const Id source : this->CopySources)
  {
    this->Points.push_back(this->Points[static_cast<std::size_t>(source)]);
  }
}

// Boundary edges (in one triangle) and the points on them.
void PreparedMesh::findBoundaries()
{
  std::vector<int> uses(this->Edges.edgeCount(), 0);
  for (std::size_t t = 0; t < this->Triangles.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++uses[static_cast<std::size_t>(this->Edges.sideEdge(static_cast<Id>(t), k))];
    }
  }
  this->OnBoundary.assign(this->Points.size(), 0);
  this->BoundaryEdges.assign(uses.size(), 0);
  for (std::size_t e = 0; e < uses.size(); ++e)
  {
    if (uses[e] == 1)
    {
      this->BoundaryEdges[e] = 1;
      const Edge& edge = this->Edges.edge(static_cast<Id>(e));
      this->OnBoundary[static_cast<std::size_t>(edge.low)] = 1;
      this->OnBoundary[static_cast<std::size_t>(edge.high)] = 1;
    }
  }
}

// Each edge's feature curve, and the triangles with a feature side.
void PreparedMesh::indexFeatureEdges()
{
  if (this->Features.empty())
  {
    return;
  }
  this->EdgeFeatures.resize(this->Edges.edgeCount());
  for (std::size_t e = 0; e < this->Edges.edgeCount(); ++e)
  {
    const Edge& edge = this->Edges.edge(static_cast<Id>(e));
    this->EdgeFeatures[e] =
      this->Features.find(this->sourcePoint(edge.low), this->sourcePoint(edge.high));
  }
  for (std::size_t t = 0; t < this->Triangles.size(); ++t)
  {
    if (hasRepeatedCorner(this->Triangles[t]))
    {
      continue;
    }
    bool curvedSide = false;
    for (int k = 0; k < 3; ++k)
    {
      const Id f = this->edgeFeature(this->Edges.sideEdge(static_cast<Id>(t), k));
      if (f >= 0)
      {
        this->FeatureSideTriangles.emplace_back(f, static_cast<Id>(t));
        curvedSide = curvedSide || this->Features.isCurved(f);
      }
    }
    if (curvedSide)
    {
      this->FeatureTriangles.push_back(static_cast<Id>(t));
    }
  }
  std::sort(this->FeatureSideTriangles.begin(), this->FeatureSideTriangles.end());
  this->FeatureSideTriangles.erase(
    std::unique(this->FeatureSideTriangles.begin(), this->FeatureSideTriangles.end()),
    this->FeatureSideTriangles.end());
}

// Edge neighbours of every vertex (compressed rows), for the perturbation.
void PreparedMesh::findNeighbours()
{
  std::vector<Id> degree(this->Points.size() + 1, 0);
  for (std::size_t e = 0; e < this->Edges.edgeCount(); ++e)
  {
    const Edge& edge = this->Edges.edge(static_cast<Id>(e));
    if (edge.low != edge.high)
    {
      ++degree[static_cast<std::size_t>(edge.low) + 1];
      ++degree[static_cast<std::size_t>(edge.high) + 1];
    }
  }
  for (std::size_t v = 1; v < degree.size(); ++v)
  {
    degree[v] += degree[v - 1];
  }
  this->NeighbourOffsets = degree;
  this->Neighbours.resize(static_cast<std::size_t>(degree.back()));
  for (std::size_t e = 0; e < this->Edges.edgeCount(); ++e)
  {
    const Edge& edge = this->Edges.edge(static_cast<Id>(e));
    if (edge.low != edge.high)
    {
      this->Neighbours[static_cast<std::size_t>(degree[static_cast<std::size_t>(edge.low)]++)] =
        edge.high;
      this->Neighbours[static_cast<std::size_t>(degree[static_cast<std::size_t>(edge.high)]++)] =
        edge.low;
    }
  }
}

// Given normals for the input's points; feature points (and their copies)
// and points with no usable given normal get the computed ones.
void PreparedMesh::chooseNormals(const std::vector<glm::dvec3>& normals,
  const CornerNormals& cornerNormals, NormalWeighting weighting)
{
  std::vector<glm::dvec3> computed;
  bool needComputed = normals.size() != this->InputPointCount || !this->Features.empty();
  if (cornerNormals.covers(this->Triangles.size()))
  {
    this->Normals = this->normalsFromCorners(cornerNormals);
    needComputed = true;
  }
  else if (normals.size() == this->InputPointCount)
  {
    this->Normals.resize(this->Points.size(), glm::dvec3(0.0));
    for (std::size_t i = 0; i < normals.size(); ++i)
    {
      this->Normals[i] =
        this->onFeature(static_cast<Id>(i)) ? glm::dvec3(0.0) : safeNormalize(normals[i]);
      needComputed = needComputed || this->Normals[i] == glm::dvec3(0.0);
    }
  }
  if (needComputed)
  {
    computed = vertexNormals(this->Points, this->Triangles, weighting);
    if (this->Normals.empty())
    {
      this->Normals = std::move(computed);
    }
    else
    {
      for (std::size_t i = 0; i < this->Normals.size(); ++i)
      {
        if (this->Normals[i] == glm::dvec3(0.0))
        {
          this->Normals[i] = computed[i];
        }
      }
    }
  }
}

std::vector<glm::dvec3> PreparedMesh::normalsFromCorners(const CornerNormals& cornerNormals) const
{
  const std::size_t count = this->Points.size();
  std::vector<glm::dvec3> first(count, glm::dvec3(0.0));
  std::vector<glm::dvec3> sum(count, glm::dvec3(0.0));
  std::vector<unsigned char> mixed(count, 0);
  for (std::size_t t = 0; t < this->Triangles.size(); ++t)
  {
    for (std::size_t k = 0; k < 3; ++k)
    {
      const std::size_t p = static_cast<std::size_t>(this->Triangles[t][k]);
      const glm::dvec3 n = safeNormalize(cornerNormals(t, k));
      if (n == glm::dvec3(0.0))
      {
        continue;
      }
      if (first[p] == glm::dvec3(0.0))
      {
        first[p] = n;
        sum[p] = n;
      }
      else if (n != first[p])
      {
        mixed[p] = 1;
        sum[p] += n;
      }
    }
  }
  std::vector<glm::dvec3> result(count);
  for (std::size_t p = 0; p < count; ++p)
  {
    result[p] = mixed[p] ? safeNormalize(sum[p]) : first[p];
  }
  if (this->Features.empty())
  {
    return result;
  }
  // A feature point's groups keep their corners' normals only where those
  // tell the sides of the crease apart.
  const double cosLimit = std::cos(NormalSeamAngleDegrees * 3.14159265358979323846 / 180.0);
  std::vector<unsigned char> distinct(this->InputPointCount, 0);
  for (std::size_t p = this->InputPointCount; p < count; ++p)
  {
    const std::size_t s = static_cast<std::size_t>(this->sourcePoint(static_cast<Id>(p)));
    const glm::dvec3& a = result[s];
    const glm::dvec3& b = result[p];
    if (a == glm::dvec3(0.0) || b == glm::dvec3(0.0) || glm::dot(a, b) < cosLimit)
    {
      distinct[s] = 1;
    }
  }
  for (std::size_t p = 0; p < count; ++p)
  {
    const std::size_t s = static_cast<std::size_t>(this->sourcePoint(static_cast<Id>(p)));
    if (this->onFeature(static_cast<Id>(p)) && !distinct[s])
    {
      result[p] = glm::dvec3(0.0);
    }
  }
  return result;
}

std::vector<double> vertexVisibility(
  const PreparedMesh& mesh, const ViewGeometry& view, const ParallelFor& parallelFor)
{
  const std::vector<glm::dvec3>& points = mesh.points();
  const std::vector<glm::dvec3>& normals = mesh.normals();
  std::vector<double> g(points.size());
  parallelFor(points.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
    {
      g[i] = view.visibility(points[i], normals[i]);
    }
  });
  return g;
}

const TriangleGrid& PreparedMesh::triangleGrid() const
{
  LazyGrid& lazy = *this->Grid;
  // Under the same flag as a background build's hand-over: whichever comes
  // first writes the grid, and this call returns only once it is written.
  std::call_once(lazy.Once, [&] {
    lazy.Grid = TriangleGrid(this->Points, this->Triangles);
    lazy.Built.store(true, std::memory_order_release);
  });
  return lazy.Grid;
}

const TriangleGrid* PreparedMesh::foldGuardGridForFrame(IndexBuild build) const
{
  const std::shared_ptr<LazyGrid>& shared = this->Grid;
  LazyGrid& lazy = *shared;
  const int earlierFrames = lazy.Frames.fetch_add(1);
  if (lazy.Built.load(std::memory_order_acquire))
  {
    return &lazy.Grid;
  }
  if (earlierFrames == 0 || lazy.Outrun)
  {
    return nullptr; // the first frame scans: maybe the only one
  }
  if (build == IndexBuild::InCall || lazy.Deforming)
  {
    return &this->triangleGrid();
  }
  // Once per mesh; a grid that fails on its thread leaves the frames scanning.
  if (!lazy.BackgroundStarted.exchange(true) &&
    !this->startBackgroundBuild([shared](const BuildArrays& arrays) {
      TriangleGrid grid(arrays.Points, arrays.Triangles);
      std::call_once(shared->Once, [&] {
        shared->Grid = std::move(grid);
        shared->Built.store(true, std::memory_order_release);
      });
    }))
  {
    return &this->triangleGrid();
  }
  return lazy.Built.load(std::memory_order_acquire) ? &lazy.Grid : nullptr;
}

bool PreparedMesh::adoptTriangleGrid(const PreparedMesh& earlier)
{
  return earlier.Triangles == this->Triangles && this->adoptTriangleGridOfMoved(earlier);
}

bool PreparedMesh::adoptTriangleGridOfMoved(const PreparedMesh& earlier)
{
  if (earlier.Points.size() != this->Points.size())
  {
    return false;
  }
  const LazyGrid& before = *earlier.Grid;
  const bool built = before.Built.load(std::memory_order_acquire) && !before.Grid.empty();
  // The largest coordinate change of any point (NaN for a non-finite one),
  // which only a grid to adopt asks for.
  double step = 0.0;
  for (std::size_t i = 0; built && i < this->Points.size() && !std::isnan(step); ++i)
  {
    const glm::dvec3 d = glm::abs(this->Points[i] - earlier.Points[i]);
    step = std::isnan(d.x + d.y + d.z) ? std::nan("") : std::max({ step, d.x, d.y, d.z });
  }
  const double half = built ? 0.5 * before.Grid.cellSize() : 0.0;
  // Each coordinate's move must be known to be small: a NaN (a point that
  // was or is not finite, which the grid left out or would) refuses.
  if (built && step <= half - earlier.GridSlack)
  {
    this->Grid = earlier.Grid;
    this->GridSlack = earlier.GridSlack + step;
    return true;
  }
  // Not adopted. A deforming mesh's frames are one sequence: the count goes
  // on; a grid that this one move outran is not built again (scanning
  // costs less), one that the moves outran only added up is.
  this->Grid = std::make_shared<LazyGrid>(); // never a copy's shared state
  this->Grid->Deforming = true;
  this->Grid->Frames = before.Frames.load();
  this->Grid->Outrun = built ? !(step <= half) : before.Outrun.load();
  return false;
}

bool PreparedMesh::findSilhouetteTriangles(const ViewGeometry& view, const ParallelFor& parallelFor,
  std::vector<Id>& out, IndexBuild build) const
{
  const std::shared_ptr<LazyTriangleHierarchy>& shared =
    this->TriangleHierarchies[view.Parallel ? 0 : 1];
  LazyTriangleHierarchy& lazy = *shared;
  if (lazy.Searches.fetch_add(1) == 0)
  {
    return false; // the first search scans: maybe the only one
  }
  const bool perspective = !view.Parallel;
  std::call_once(lazy.Once, [&] {
    // A tree that fails on its thread leaves every search scanning.
    if (build == IndexBuild::Background &&
      this->startBackgroundBuild([shared, perspective](const BuildArrays& arrays) {
        shared->Tree =
          SilhouetteTriangleHierarchy(arrays.Points, arrays.Normals, arrays.Triangles, perspective);
        shared->Ready.store(true, std::memory_order_release);
      }))
    {
      return;
    }
    lazy.Tree =
      SilhouetteTriangleHierarchy(this->Points, this->Normals, this->Triangles, perspective);
    lazy.Ready.store(true, std::memory_order_release);
  });
  if (!lazy.Ready.load(std::memory_order_acquire))
  {
    return false;
  }
  return lazy.Tree.find(view, this->Points, this->Normals, this->Triangles, parallelFor, out);
}

std::shared_ptr<const PreparedMesh::BuildArrays> PreparedMesh::buildArrays() const
{
  std::lock_guard<std::mutex> lock(this->SharedBuildArrays->Mutex);
  std::shared_ptr<const BuildArrays> arrays = this->SharedBuildArrays->Arrays.lock();
  if (!arrays)
  {
    arrays = std::make_shared<const BuildArrays>(
      BuildArrays{ this->Points, this->Normals, this->Triangles });
    this->SharedBuildArrays->Arrays = arrays;
  }
  return arrays;
}

bool PreparedMesh::startBackgroundBuild(std::function<void(const BuildArrays&)> build) const
{
  try
  {
    std::thread([arrays = this->buildArrays(), build = std::move(build)] {
      try
      {
        runBackgroundBuildHook();
        build(*arrays);
      }
      catch (...)
      {
        // Nothing built: the frames keep scanning.
      }
    }).detach();
    return true;
  }
  catch (const std::exception&)
  {
    return false;
  }
}

bool PreparedMesh::silhouetteTreeReady(bool parallel) const
{
  return this->TriangleHierarchies[parallel ? 0 : 1]->Ready.load(std::memory_order_acquire);
}

const VisibilityHierarchy& PreparedMesh::visibilityHierarchy() const
{
  std::call_once(this->Hierarchy->Once,
    [this] { this->Hierarchy->Hierarchy = VisibilityHierarchy(this->Points, this->Normals); });
  return this->Hierarchy->Hierarchy;
}

} // namespace silsmooth
