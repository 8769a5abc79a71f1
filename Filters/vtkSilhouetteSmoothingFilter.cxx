#include "vtkSilhouetteSmoothingFilter.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include "vtkSilhouetteAttributeSources.h"
#include "vtkSilhouetteFilterSupport.h"
#include "vtkSilhouetteSmoothingOutput.h"

#include "ShadingNormals.h"
#include "SilhouetteSmoother.h"
#include "WeldedSurface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <functional>
#include <new>
#include <numeric>
#include <string>
#include <unordered_map>
#include <vector>

vtkStandardNewMacro(vtkSilhouetteSmoothingFilter);

using namespace vtkSilhouetteSmoothingOutput;

vtkSilhouetteCheckedSetterMacro(
  vtkSilhouetteSmoothingFilter, Tolerance, double, 1e-3, VTK_DOUBLE_MAX);
vtkSilhouetteCheckedSetterMacro(vtkSilhouetteSmoothingFilter, MinimumSamples, int, 2, 65536);
vtkSilhouetteCheckedSetterMacro(vtkSilhouetteSmoothingFilter, MaximumSamples, int, 2, 65536);
vtkSilhouetteCheckedSetterMacro(vtkSilhouetteSmoothingFilter, NewPointBudget, double, 1.0, 1e6);
vtkSilhouetteCheckedSetterMacro(vtkSilhouetteSmoothingFilter, FeatureAngle, double, 0.0, 180.0);
vtkSilhouetteCheckedSetterMacro(
  vtkSilhouetteSmoothingFilter, WeldTolerance, double, 0.0, VTK_DOUBLE_MAX);
vtkSilhouetteCheckedSetterMacro(vtkSilhouetteSmoothingFilter, FlatCreaseAngle, double, 0.0, 180.0);
// The choices, clamped with a warning too (vtkSetClampMacro's silence left
// a ParaView user's NormalEstimation 9 unexplained).
vtkSilhouetteCheckedSetterMacro(
  vtkSilhouetteSmoothingFilter, SamplingRule, int, SECOND_DIFFERENCE, WANG_EQUATION_8);
vtkSilhouetteCheckedSetterMacro(
  vtkSilhouetteSmoothingFilter, OutputPointsPrecision, int, SINGLE_PRECISION, DEFAULT_PRECISION);
vtkSilhouetteCheckedSetterMacro(
  vtkSilhouetteSmoothingFilter, NormalEstimation, int, ANGLE_WEIGHTED, QUADRIC_FIT);
vtkSilhouetteCheckedSetterMacro(
  vtkSilhouetteSmoothingFilter, VisibilityMethod, int, PER_VERTEX, HIERARCHICAL);

namespace
{

// Feature edges marked by line cells (the core keeps those along triangle
// edges).
std::vector<silsmooth::FeatureEdge> MarkedFeatures(vtkPolyData* input, bool useLines)
{
  std::vector<silsmooth::FeatureEdge> marked;
  if (!useLines)
  {
    return marked;
  }
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  auto it = vtk::TakeSmartPointer(input->GetLines()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    it->GetCurrentCell(npts, pts);
    for (vtkIdType k = 0; k + 1 < npts; ++k)
    {
      marked.emplace_back(pts[k], pts[k + 1]);
    }
  }
  return marked;
}

// The core's loops on vtkSMPTools.
void SMPFor(std::size_t count, const std::function<void(std::size_t, std::size_t)>& body)
{
  vtkSMPTools::For(0, static_cast<vtkIdType>(count), [&body](vtkIdType begin, vtkIdType end) {
    body(static_cast<std::size_t>(begin), static_cast<std::size_t>(end));
  });
}

// Fingerprints of bytes, in four independent lanes (the multiplications of
// one would wait on each other).
struct Fingerprint
{
  std::uint64_t Lanes[4] = { 1, 2, 3, 4 };

  static std::uint64_t Mix(std::uint64_t h, std::uint64_t word)
  {
    h = (h ^ word) * 0xff51afd7ed558ccdULL;
    return h ^ (h >> 32);
  }
  void Add(const void* data, std::size_t size)
  {
    const auto* bytes = static_cast<const unsigned char*>(data);
    std::size_t i = 0;
    for (; i + 32 <= size; i += 32)
    {
      for (int k = 0; k < 4; ++k)
      {
        std::uint64_t word;
        std::memcpy(&word, bytes + i + 8 * k, 8);
        this->Lanes[k] = Mix(this->Lanes[k], word);
      }
    }
    for (; i < size; ++i)
    {
      this->Lanes[0] = Mix(this->Lanes[0], bytes[i]);
    }
    this->Lanes[1] = Mix(this->Lanes[1], size);
  }
  std::uint64_t Value() const
  {
    return Mix(Mix(Mix(this->Lanes[0], this->Lanes[1]), this->Lanes[2]), this->Lanes[3]);
  }
};

// A fingerprint of the bytes of a cell array's offsets and connectivity.
// VTK 9.1 leaves a cell array's MTime alone when its cells are edited in
// place (ReplaceCellAtId, or values written into its arrays), so the
// objects and their times cannot tell a deforming mesh from a re-wired one.
// About 7 ms at 1.3M triangles, paid only when the input changed.
std::uint64_t CellContent(vtkCellArray* cells)
{
  Fingerprint print;
  if (cells)
  {
    for (vtkDataArray* array : { cells->GetOffsetsArray(), cells->GetConnectivityArray() })
    {
      print.Add(array->GetVoidPointer(0),
        static_cast<std::size_t>(array->GetNumberOfValues()) *
          static_cast<std::size_t>(array->GetDataTypeSize()));
    }
  }
  return print.Value();
}

// A fingerprint of the points and normals smoothing read (and the normals'
// name, which the output's normals take): when it stays, so does every
// position and normal the smoothing computes, whatever else of the input
// changed.
std::uint64_t GeometryContent(const vtkSilhouetteFilterSupport::Triangles& mesh, vtkPolyData* input)
{
  Fingerprint print;
  print.Add(mesh.Points.data(), mesh.Points.size() * sizeof(glm::dvec3));
  print.Add(mesh.Normals.data(), mesh.Normals.size() * sizeof(glm::dvec3));
  vtkDataArray* normals = input->GetPointData()->GetNormals();
  const char* name = normals && normals->GetName() ? normals->GetName() : "";
  print.Add(name, std::strlen(name));
  return print.Value();
}

// The contents of the input's cell arrays and its point count: what must
// stay for a change to be one of the points (or of other arrays) only. The
// arrays' objects and times do not count: a pipeline that makes its output
// anew each update (a reader's time steps) gives new arrays of the same
// cells.
std::array<std::uint64_t, 5> CellsOf(vtkPolyData* input)
{
  return { { CellContent(input->GetVerts()), CellContent(input->GetLines()),
    CellContent(input->GetPolys()), CellContent(input->GetStrips()),
    static_cast<std::uint64_t>(input->GetNumberOfPoints()) } };
}

// Whether two views are one, value for value (a NaN never equals itself:
// such a view is smoothed again).
bool SameViewGeometry(const silsmooth::ViewGeometry& a, const silsmooth::ViewGeometry& b)
{
  return a.Parallel == b.Parallel && a.Eye == b.Eye && a.TowardViewer == b.TowardViewer &&
    a.ModelToClip == b.ModelToClip && a.ViewportWidth == b.ViewportWidth &&
    a.ViewportHeight == b.ViewportHeight;
}

} // namespace

struct vtkSilhouetteSmoothingFilter::Internals
{
  // The view-independent cache, keyed on the input object, its MTime and the
  // settings that shape it; another object, or a later time, with the same
  // cells moves its points (MovePoints).
  std::unique_ptr<silsmooth::WeldedSurface> Surface;
  std::vector<vtkIdType> TriangleCell; // input cell id of each triangle
  vtkIdType NonFinitePoints = 0;
  vtkIdType FirstNonFinitePoint = -1;
  vtkIdType TooSmallPolygons = 0;
  vtkIdType UntriangulatedPolygons = 0;
  std::size_t DistinctTriangles = 0; ///< triangles with three distinct point ids
  vtkPolyData* CachedInput = nullptr;
  vtkMTimeType CachedInputTime = 0;
  std::array<double, 10> CachedSettings{};
  bool HaveSettings = false;
  // The input's cells and point count when the cache was built: while they
  // stay, in this input object or another, only the points may have
  // changed, and the surface moves them (WeldedSurface::movePoints) instead
  // of being built anew.
  std::array<std::uint64_t, 5> CachedCells{};
  // Counts the builds of the surface (not its moves), and the build the
  // base mesh BuildBaseMesh filled last was made for: while it is the same
  // build, the base mesh keeps its cell arrays and takes the new points.
  std::size_t Builds = 0;
  vtkPolyData* LastBase = nullptr;
  std::size_t LastBaseBuild = 0;
  // The geometry smoothing reads (points, normals, cells, ghost flags): a
  // fingerprint of the points and normals read, and the time any of it last
  // changed. An input whose other arrays alone changed keeps it, and what
  // BuildChanges made since then still holds for it.
  std::uint64_t GeometryPrint = 0;
  vtkTimeStamp GeometryTime;
  vtkMTimeType LastBaseGeometry = 0; // GeometryTime when the base mesh was filled
  // The last request's smoothing and what it was made for: a request for
  // the same view, settings, seam rule and geometry (the input's other
  // arrays changed: a time series of values) takes it again.
  struct LastSmoothing
  {
    silsmooth::SmoothingResult Result;
    silsmooth::ViewGeometry View;
    vtkMTimeType Settings = 0;
    vtkMTimeType Geometry = 0;
    bool Seam = false;
    bool Valid = false;
  };
  LastSmoothing Last;
  // What BuildChanges' last smoothing for one viewer (a renderer and a
  // prop, as the mapper names them; none for the public BuildChanges) left
  // whole below the tolerance and re-meshed, its feature segments drawn
  // straight, and the build of the surface they are of (Builds): the next
  // view of that surface for that viewer, its points moved or not (a
  // deforming mesh keeps its triangles), leaves what was smoothed before
  // whole only with a margin (SmoothingParameters::SubpixelBefore), and
  // raises a folding triangle at once to its fallback there
  // (SmoothingParameters::FallbacksBefore). Each
  // viewer's frames follow one another; two renderers taking turns must not
  // read each other's. The four viewers drawn last are kept.
  struct ChangesHistory
  {
    std::array<const void*, 2> Viewer{ { nullptr, nullptr } };
    std::size_t Build = 0; // 0: none yet
    std::size_t LastUse = 0;
    std::vector<silsmooth::Id> Subpixel;
    std::vector<silsmooth::Id> Remeshed;
    std::vector<silsmooth::Id> SubpixelFeatures;
    silsmooth::FoldFallbacks Fallbacks;
  };
  std::array<ChangesHistory, 4> Histories;
  std::size_t HistoryUses = 0;
  // Whether the last smoothing of this surface lowered its samples to keep
  // within NewPointBudget (its warning is given once while that goes on).
  bool BudgetBitBefore = false;
  // The history of `viewer`, or the one used longest ago, emptied for it.
  ChangesHistory& HistoryOf(const std::array<const void*, 2>& viewer)
  {
    ChangesHistory* oldest = &this->Histories[0];
    for (ChangesHistory& h : this->Histories)
    {
      if (h.Build != 0 && h.Viewer == viewer)
      {
        h.LastUse = ++this->HistoryUses;
        return h;
      }
      oldest = h.LastUse < oldest->LastUse ? &h : oldest;
    }
    *oldest = ChangesHistory();
    oldest->Viewer = viewer;
    oldest->LastUse = ++this->HistoryUses;
    return *oldest;
  }
  // Per triangle: a ghost cell (duplicate or hidden), never re-meshed; empty
  // when the input has no ghost array. Read again whenever the input changed.
  std::vector<unsigned char> Frozen;
  vtkMTimeType FrozenTime = 0;

  // Returns an empty string, or the error to report.
  std::string Rebuild(vtkPolyData* input, bool useLines, const silsmooth::SurfaceOptions& options);
  // True when the points of the cached input's unchanged cells moved and
  // the surface took the move.
  bool MovePoints(vtkPolyData* input, bool useLines, const silsmooth::SurfaceOptions& options);

  // The cache for `input` and the filter's settings, rebuilt when either
  // changed (`rebuilt` says so); the warnings about the input are given once
  // per rebuild. False after reporting an error.
  bool Prepare(vtkSilhouetteSmoothingFilter* self, vtkPolyData* input, bool& rebuilt);
  // The frame for the view, with the filter's settings; warns when the new
  // point budget lowered the sampling.
  // `polylines`: whether the silhouette lines are wanted (not by BuildChanges);
  // `history`: the frame before (SmoothingParameters::SubpixelBefore), or null.
  silsmooth::SmoothingResult Smooth(vtkSilhouetteSmoothingFilter* self, vtkPolyData* input,
    const silsmooth::ViewGeometry& view, bool boundaryMayBeSeam, bool polylines = true,
    const ChangesHistory* history = nullptr);
};

std::string vtkSilhouetteSmoothingFilter::Internals::Rebuild(
  vtkPolyData* input, bool useLines, const silsmooth::SurfaceOptions& options)
{
  vtkSilhouetteFilterSupport::Triangles mesh;
  const std::string error = vtkSilhouetteFilterSupport::ReadTriangles(input, mesh);
  this->Surface.reset();
  this->CachedInput = nullptr;
  if (!error.empty())
  {
    return error;
  }
  this->NonFinitePoints = mesh.NonFinitePoints;
  this->FirstNonFinitePoint = mesh.FirstNonFinitePoint;
  this->TooSmallPolygons = mesh.TooSmallPolygons;
  this->UntriangulatedPolygons = mesh.UntriangulatedPolygons;
  this->DistinctTriangles =
    static_cast<std::size_t>(std::count_if(mesh.Cells.begin(), mesh.Cells.end(),
      [](const silsmooth::Triangle& t) { return !silsmooth::hasRepeatedCorner(t); }));
  this->TriangleCell = std::move(mesh.CellIds);
  if (this->NonFinitePoints > 0)
  {
    return std::string(); // reported by the caller, on every request
  }
  this->GeometryPrint = GeometryContent(mesh, input);
  this->GeometryTime.Modified();
  this->BudgetBitBefore = false;
  this->Surface = std::make_unique<silsmooth::WeldedSurface>(std::move(mesh.Points),
    std::move(mesh.Cells), mesh.Normals, MarkedFeatures(input, useLines), options, SMPFor);
  this->CachedInput = input;
  this->CachedInputTime = input->GetMTime();
  this->CachedCells = CellsOf(input);
  ++this->Builds;
  return std::string();
}

bool vtkSilhouetteSmoothingFilter::Internals::MovePoints(
  vtkPolyData* input, bool useLines, const silsmooth::SurfaceOptions& options)
{
  if (!this->Surface || this->CachedCells != CellsOf(input))
  {
    return false;
  }
  vtkSilhouetteFilterSupport::Triangles mesh;
  // The cells are those read when the surface was built (checked above):
  // only the points and normals are read again.
  vtkSilhouetteFilterSupport::ReadPoints(input, mesh);
  if (mesh.NonFinitePoints > 0)
  {
    return false;
  }
  const std::uint64_t print = GeometryContent(mesh, input);
  if (print != this->GeometryPrint &&
    !this->Surface->movePoints(
      std::move(mesh.Points), mesh.Normals, MarkedFeatures(input, useLines), options, SMPFor))
  {
    return false;
  }
  if (print != this->GeometryPrint)
  {
    this->GeometryPrint = print;
    this->GeometryTime.Modified();
  }
  // Else only the input's other arrays changed: the surface stands as it is.
  this->CachedInput = input;
  this->CachedInputTime = input->GetMTime();
  return true;
}

bool vtkSilhouetteSmoothingFilter::Internals::Prepare(
  vtkSilhouetteSmoothingFilter* self, vtkPolyData* input, bool& rebuilt)
{
  silsmooth::SurfaceOptions options;
  options.Weld = self->WeldCoincidentPoints;
  options.WeldTolerance = self->WeldTolerance;
  options.Orient = self->ConsistentOrientation;
  options.NormalSeams = self->NormalSeamFeatures;
  options.DetectFeatures = self->FeatureEdgeDetection;
  options.FeatureAngleDegrees = self->FeatureAngle;
  options.DetectFlatCreases = self->FlatCreaseDetection;
  options.FlatCreaseAngleDegrees = self->FlatCreaseAngle;
  options.Normals = static_cast<silsmooth::NormalWeighting>(self->NormalEstimation);
  const std::array<double, 10> settings{ { self->FeatureLines ? 1.0 : 0.0,
    options.DetectFeatures ? 1.0 : 0.0, options.FeatureAngleDegrees, options.Weld ? 1.0 : 0.0,
    options.WeldTolerance, options.Orient ? 1.0 : 0.0, options.NormalSeams ? 1.0 : 0.0,
    options.DetectFlatCreases ? 1.0 : 0.0, options.FlatCreaseAngleDegrees,
    static_cast<double>(self->NormalEstimation) } };
  rebuilt = !this->Surface || this->CachedInput != input ||
    this->CachedInputTime != input->GetMTime() || !this->HaveSettings ||
    this->CachedSettings != settings;
  if (rebuilt && this->HaveSettings && this->CachedSettings == settings &&
    this->MovePoints(input, self->FeatureLines, options))
  {
    rebuilt = false; // a deforming mesh: the same topology, the points moved
  }
  if (rebuilt)
  {
    this->HaveSettings = false;
    const std::string error = this->Rebuild(input, self->FeatureLines, options);
    if (!error.empty())
    {
      vtkErrorWithObjectMacro(self, << error);
      return false;
    }
    this->CachedSettings = settings;
    this->HaveSettings = this->Surface != nullptr;
  }
  if (this->FrozenTime != input->GetMTime() || rebuilt)
  {
    // Ghost cells (a piece's copies of its neighbours' cells) count for the
    // normals and the adjacency but are the other piece's to re-mesh.
    std::vector<unsigned char> frozen;
    vtkUnsignedCharArray* ghosts = vtkArrayDownCast<vtkUnsignedCharArray>(
      input->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName()));
    if (ghosts && ghosts->GetNumberOfValues() == input->GetNumberOfCells())
    {
      const unsigned char skip =
        vtkDataSetAttributes::DUPLICATECELL | vtkDataSetAttributes::HIDDENCELL;
      frozen.resize(this->TriangleCell.size());
      for (std::size_t t = 0; t < this->TriangleCell.size(); ++t)
      {
        frozen[t] = (ghosts->GetValue(this->TriangleCell[t]) & skip) != 0 ? 1 : 0;
      }
    }
    if (frozen != this->Frozen)
    {
      this->Frozen = std::move(frozen);
      this->GeometryTime.Modified();
    }
    this->FrozenTime = input->GetMTime();
  }
  if (this->NonFinitePoints > 0)
  {
    vtkErrorWithObjectMacro(self,
      "Input has " << this->NonFinitePoints
                   << " points with NaN or infinite coordinates (the first is point "
                   << this->FirstNonFinitePoint << ").");
    return false;
  }
  if (rebuilt && this->DistinctTriangles == 0 && input->GetNumberOfPoints() > 0)
  {
    // An empty input (an empty piece of a parallel pipeline) passes silently.
    vtkWarningWithObjectMacro(self,
      "The input has no triangles (no polygon or strip with three distinct points): there is "
      "no surface to smooth, and its other cells pass through unchanged.");
  }
  const silsmooth::SurfaceStatistics& statistics = this->Surface->statistics();
  if (rebuilt && statistics.FlatShadedNormals)
  {
    vtkWarningWithObjectMacro(self,
      "The input's point normals are its triangles' own normals (flat shading): "
      "they say nothing about the smooth surface, so they are not used; shading "
      "normals are computed, and creases come from FlatCreaseDetection and "
      "FeatureEdgeDetection.");
  }
  if (rebuilt && statistics.NearCopyEdgeCount > 0)
  {
    // Twice the longest: a tolerance that joins them with room for rounding.
    const bool one = statistics.NearCopyEdgeCount == 1;
    vtkWarningWithObjectMacro(
      self, << statistics.NearCopyEdgeCount << (one ? " edge is" : " edges are")
            << " shorter than 1e-5 of the mesh's size (near copies of points, as some exporters "
               "write them): their ends stay apart, with the normals of one side each, which bends "
               "the silhouette near them; WeldTolerance "
            << 2.0 * statistics.LongestNearCopyEdge << " welds them.");
  }
  const double diagonal = input->GetLength();
  if (rebuilt && options.Weld && options.WeldTolerance > 0.01 * diagonal &&
    input->GetNumberOfPoints() > 0)
  {
    // A tolerance in the mesh's units that is a good part of its size joins
    // points across its features: a ParaView user's WeldTolerance 100 drew
    // the bunny as one flat shape, silently.
    vtkWarningWithObjectMacro(self,
      "WeldTolerance " << options.WeldTolerance << " is "
                       << 100.0 * options.WeldTolerance / std::max(diagonal, 1e-300)
                       << "% of the mesh's diagonal (" << diagonal << "; the tolerance is in the "
                       << "mesh's units): it joined " << statistics.WeldedPointCount << " of "
                       << input->GetNumberOfPoints() << " points.");
  }
  if (rebuilt && statistics.BackToBackTriangleCount > 0)
  {
    // Sides written with a copy of each point are kept apart (welding
    // within sheets); sides on the same points cannot be.
    vtkWarningWithObjectMacro(self,
      << statistics.BackToBackTriangleCount
      << " triangles lie back to back with a twin on the same points (a double-sided sheet "
         "whose sides share their points): their normals cancel, so they are shaded dark. Give "
         "each side points of its own, or keep one side.");
  }
  if (rebuilt && statistics.InconsistentEdgeCount > 0)
  {
    vtkWarningWithObjectMacro(
      self, << statistics.InconsistentEdgeCount
            << " edges join triangles that cannot be oriented consistently (a "
               "non-orientable surface, such as a Moebius strip): shading normals "
               "and visibility are unreliable next to them.");
  }
  return true;
}

silsmooth::SmoothingResult vtkSilhouetteSmoothingFilter::Internals::Smooth(
  vtkSilhouetteSmoothingFilter* self, vtkPolyData* input, const silsmooth::ViewGeometry& view,
  bool boundaryMayBeSeam, bool polylines, const ChangesHistory* history)
{
  silsmooth::SmoothingParameters parameters;
  parameters.SilhouettePolylines = polylines;
  parameters.SubpixelBefore = history ? &history->Subpixel : nullptr;
  parameters.RemeshedBefore = history ? &history->Remeshed : nullptr;
  parameters.SubpixelFeaturesBefore = history ? &history->SubpixelFeatures : nullptr;
  parameters.FallbacksBefore = history && self->ReuseFoldFallbacks ? &history->Fallbacks : nullptr;
  parameters.PerturbConcaveSilhouettes = self->PerturbVertices;
  parameters.PreventFolds = self->FoldPrevention;
  parameters.KeepApexesPointed = self->KeepApexesPointed;
  parameters.CullOutsideFrustum = self->FrustumCulling;
  parameters.SkipSubpixelSmoothing = self->SkipSubpixelSmoothing;
  parameters.FrozenTriangles = this->Frozen.empty() ? nullptr : &this->Frozen;
  parameters.BoundaryMayBeSeam = boundaryMayBeSeam;
  parameters.Visibility = self->VisibilityMethod == HIERARCHICAL
    ? silsmooth::VisibilityMethod::Hierarchical
    : silsmooth::VisibilityMethod::PerVertex;
  silsmooth::SamplingParameters& sampling = parameters.Sampling;
  sampling.TolerancePixels = self->Tolerance;
  sampling.MinimumSamples = self->MinimumSamples;
  sampling.MaximumSamples = self->MaximumSamples;
  parameters.MaximumSampledPoints = static_cast<std::size_t>(std::max(
    1e5, std::min(self->NewPointBudget * static_cast<double>(input->GetNumberOfPoints()), 1e15)));
  sampling.Rule = self->SamplingRule == WANG_EQUATION_8 ? silsmooth::SamplingRule::WangEquation8
                                                        : silsmooth::SamplingRule::SecondDifference;
  silsmooth::SmoothingResult result =
    silsmooth::smoothSilhouettes(this->Surface->prepared(), view, parameters, SMPFor);
  // Once while the budget bites frame after frame (a mapper's orbit close
  // to a finely divided part warned on most frames, a user's trial), and
  // again after a frame within it or a new surface.
  const bool budgetBit = result.SampleBudgetMaximum > 0;
  const bool warnBudget = budgetBit && !this->BudgetBitBefore;
  this->BudgetBitBefore = budgetBit;
  if (warnBudget)
  {
    vtkWarningWithObjectMacro(self,
      "Sampled this frame's segments with at most "
        << result.SampleBudgetMaximum << " points each (MaximumSamples " << self->MaximumSamples
        << "), so that its " << result.SilhouetteTriangleCount
        << " silhouette triangles stay within NewPointBudget's " << parameters.MaximumSampledPoints
        << " new points (said once while it goes on).");
  }
  // Re-meshed straight, untested: the fold guard tests no more than a
  // bounded number of triangles near one triangle's new ones. A user's trial
  // raised MinimumSamples to 400 and got the coarse outline back, silently.
  if (result.CrowdedTriangles > 0 && self->FoldPrevention)
  {
    vtkWarningWithObjectMacro(self,
      << result.CrowdedTriangles
      << " silhouette triangles were re-meshed along the chord, not the curve: the fold check "
         "does not test new triangles with more than 2048 triangles near them (at the centre of "
         "a fan of thousands of triangles, or with MinimumSamples "
      << self->MinimumSamples << " making that many new triangles per triangle).");
  }
  return result;
}

vtkSilhouetteSmoothingFilter::vtkSilhouetteSmoothingFilter()
  : Internal(new Internals)
{
  this->SetNumberOfOutputPorts(2);
  // The renderer asks for the bounds before it creates its camera (to reset
  // it): give the input, and run for real once the camera exists.
  this->PassInputWithoutCamera = true;
}

vtkSilhouetteSmoothingFilter::~vtkSilhouetteSmoothingFilter() = default;

vtkPolyData* vtkSilhouetteSmoothingFilter::GetSilhouetteOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

int vtkSilhouetteSmoothingFilter::RequestViewData(vtkInformation*,
  vtkInformationVector** inputVector, vtkInformationVector* outputVector,
  const vtkSilhouetteFilterSupport::View& view)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* lines = vtkPolyData::GetData(outputVector, 1);

  if (this->MinimumSamples > this->MaximumSamples)
  {
    vtkErrorMacro("MinimumSamples (" << this->MinimumSamples << ") is more than MaximumSamples ("
                                     << this->MaximumSamples
                                     << "): nothing is smoothed until one of them changes.");
    return 0;
  }
  // (Arrays of the wrong length were refused before: vtkSilhouettePolyDataAlgorithm.)

  Internals& internal = *this->Internal;
  bool rebuilt = false;
  if (!internal.Prepare(this, input, rebuilt))
  {
    return 0; // reported
  }
  this->UpdateProgress(0.2);

  // A piece of a distributed mesh: its boundary may be a seam with another
  // piece, whose silhouette points there must stay the same as ours.
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const bool boundaryMayBeSeam =
    outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()) &&
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()) > 1;
  Internals::LastSmoothing& last = internal.Last;
  const vtkMTimeType settings = this->vtkObject::GetMTime();
  if (!(last.Valid && last.Settings == settings &&
        last.Geometry == internal.GeometryTime.GetMTime() && last.Seam == boundaryMayBeSeam &&
        SameViewGeometry(last.View, view.Geometry)))
  {
    last.Valid = false;
    last.Result = internal.Smooth(this, input, view.Geometry, boundaryMayBeSeam);
    last.View = view.Geometry;
    last.Settings = settings;
    last.Geometry = internal.GeometryTime.GetMTime();
    last.Seam = boundaryMayBeSeam;
    last.Valid = true;
  }
  const silsmooth::SmoothingResult& result = last.Result;
  const silsmooth::PreparedMesh& mesh = internal.Surface->prepared();
  const silsmooth::SurfaceStatistics& statistics = internal.Surface->statistics();
  if (!vtkSilhouetteFilterSupport::ReportProgress(this, 0.6))
  {
    return 1;
  }

  const vtkIdType numPoints = input->GetNumberOfPoints();
  vtkIdType droppedCells = 0;
  const silsmooth::SurfaceFrame frame =
    BuildCells(input, output, internal.TriangleCell, *internal.Surface, result, droppedCells);
  this->UpdateProgress(0.7);
  output->SetPoints(BuildPoints(
    input, OutputPointType(input, this->OutputPointsPrecision), *internal.Surface, result, frame));
  BuildPointData(
    input->GetPointData(), output->GetPointData(), numPoints, *internal.Surface, result, frame);
  if (internal.TooSmallPolygons > 0)
  {
    vtkWarningMacro(<< internal.TooSmallPolygons
                    << " polygons with fewer than 3 points make no triangle and were dropped.");
  }
  if (rebuilt && internal.UntriangulatedPolygons > 0) // once per input
  {
    vtkWarningMacro(<< internal.UntriangulatedPolygons
                    << " concave polygons could not be triangulated (they cross themselves) and "
                       "were split as fans from their first corner, which cover more than the "
                       "polygon.");
  }
  if (rebuilt && droppedCells > 0) // said once per input, not every frame
  {
    vtkWarningMacro(<< droppedCells
                    << " vertex cells without points or lines with one point draw nothing and "
                       "were dropped.");
  }

  vtkFieldData* fd = output->GetFieldData();
  fd->PassData(input->GetFieldData());
  const vtkIdType inputTriangles = static_cast<vtkIdType>(mesh.triangles().size());
  const vtkIdType remeshedTriangles = static_cast<vtkIdType>(result.RemeshedTriangles.size());
  const vtkIdType newTriangles = static_cast<vtkIdType>(result.newTriangleCount());
  AddCount(fd, "SilhouetteTriangleCount", static_cast<vtkIdType>(result.SilhouetteTriangleCount));
  AddCount(fd, "FeatureTriangleCount", static_cast<vtkIdType>(mesh.featureTriangles().size()));
  AddCount(fd, "FeatureEdgeCount", static_cast<vtkIdType>(mesh.features().edges().size()));
  AddCount(fd, "SplitPointCount",
    static_cast<vtkIdType>(
      internal.Surface->outputPointCount() - internal.Surface->inputPointCount()));
  AddCount(fd, "WeldedPointCount", static_cast<vtkIdType>(statistics.WeldedPointCount));
  AddCount(fd, "ReversedTriangleCount", static_cast<vtkIdType>(statistics.ReversedTriangleCount));
  AddCount(fd, "NormalSeamEdgeCount", static_cast<vtkIdType>(statistics.NormalSeamEdgeCount));
  AddCount(fd, "FlatCreaseEdgeCount", static_cast<vtkIdType>(statistics.FlatCreaseEdgeCount));
  AddCount(fd, "NewTriangleCount", newTriangles);
  AddCount(fd, "NewPointCount", static_cast<vtkIdType>(frame.Added.size()));
  AddCount(fd, "ConcaveSegmentCount", static_cast<vtkIdType>(result.ConcaveSegmentCount));
  AddCount(fd, "PerturbedPointCount", static_cast<vtkIdType>(result.MovedPoints.size()));
  AddCount(fd, "ApexTriangleCount", static_cast<vtkIdType>(result.ApexTriangles));
  AddCount(fd, "ChordFallbackCount", static_cast<vtkIdType>(result.ChordFallbackTriangles));
  AddCount(
    fd, "StraightSilhouettePointCount", static_cast<vtkIdType>(result.StraightSilhouettePoints));
  AddCount(
    fd, "StraightFeatureSegmentCount", static_cast<vtkIdType>(result.StraightFeatureSegments));
  AddCount(fd, "PinnedPointCount", static_cast<vtkIdType>(result.PinnedPoints));
  AddCount(fd, "CrowdedTriangleCount", static_cast<vtkIdType>(result.CrowdedTriangles));
  AddCount(fd, "UnresolvedFoldCount", static_cast<vtkIdType>(result.UnresolvedFolds));
  AddCount(fd, "FoldGuardRoundCount", static_cast<vtkIdType>(result.FoldGuardRounds));
  AddCount(fd, "SampleBudgetMaximum", static_cast<vtkIdType>(result.SampleBudgetMaximum));
  AddCount(fd, "CulledTriangleCount", static_cast<vtkIdType>(result.CulledTriangles));
  AddCount(fd, "SubpixelTriangleCount", static_cast<vtkIdType>(result.SubpixelTriangles));
  AddCount(
    fd, "SubpixelFeatureSegmentCount", static_cast<vtkIdType>(result.SubpixelFeatureIds.size()));
  AddCount(fd, "InputTriangleCount", inputTriangles);
  AddCount(fd, "OutputTriangleCount", inputTriangles - remeshedTriangles + newTriangles);

  BuildSilhouetteLines(output, frame, lines);
  this->UpdateProgress(1.0);
  return 1;
}

namespace
{
// For the calls a mapper makes outside the pipeline, what RequestData has
// from vtkSilhouettePolyDataAlgorithm::ProcessRequest: arrays of the wrong
// length kept out (they would be read past their end; the caller leaves them
// out, as the mapper does with FittingArrays, or the call is refused), and
// an exception turned into an error and a failed call (it would leave a
// render).
template<typename Build>
int GuardedBuild(vtkSilhouetteSmoothingFilter* self, vtkPolyData* input, Build build)
{
  const std::string mismatched = vtkSilhouetteFilterSupport::MismatchedArrays(input);
  if (!mismatched.empty())
  {
    vtkErrorWithObjectMacro(
      self, "The input has arrays of the wrong length: " << mismatched << ".");
    return 0;
  }
  try
  {
    return build();
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorWithObjectMacro(
      self, "Out of memory: smoothing needs more memory than the system gives.");
  }
  catch (const std::exception& error)
  {
    vtkErrorWithObjectMacro(self, "Smoothing failed: " << error.what());
  }
  return 0;
}
} // namespace

int vtkSilhouetteSmoothingFilter::BuildBaseMesh(vtkPolyData* input, vtkPolyData* base)
{
  if (!input || !base)
  {
    vtkErrorMacro("BuildBaseMesh needs an input and a mesh to fill.");
    return 0;
  }
  return GuardedBuild(this, input, [&] { return this->BuildBaseMeshUnguarded(input, base); });
}

int vtkSilhouetteSmoothingFilter::BuildBaseMeshUnguarded(vtkPolyData* input, vtkPolyData* base)
{
  bool rebuilt = false;
  if (!this->Internal->Prepare(this, input, rebuilt))
  {
    return 0;
  }
  Internals& internal = *this->Internal;
  const silsmooth::SmoothingResult nothing;
  // The same build of the surface as `base` holds (only points moved
  // since): the same cells, so `base` keeps its cell arrays, and a renderer
  // its index buffers; the points and every attribute are new. With the
  // same geometry too (the input's other arrays alone changed), `base` also
  // keeps its points and normals, and a renderer their buffers.
  const bool sameCells = base == internal.LastBase && internal.LastBaseBuild == internal.Builds &&
    base->GetNumberOfPoints() == static_cast<vtkIdType>(internal.Surface->outputPointCount());
  const bool sameGeometry = sameCells && base->GetPoints() && base->GetPointData()->GetNormals() &&
    internal.LastBaseGeometry == internal.GeometryTime.GetMTime();
  vtkNew<vtkPolyData> fresh;
  // A frame that re-meshes nothing adds and moves no point: only BuildCells'
  // triangles, which the same cells need not build again, are in it.
  silsmooth::SurfaceFrame frame;
  if (sameCells)
  {
    BuildBaseCellData(input, fresh->GetCellData(), internal.TriangleCell);
  }
  else
  {
    vtkIdType droppedCells = 0;
    frame =
      BuildCells(input, fresh, internal.TriangleCell, *internal.Surface, nothing, droppedCells);
  }
  if (sameGeometry)
  {
    const vtkIdType numPoints = std::min(input->GetNumberOfPoints(), base->GetNumberOfPoints());
    vtkSilhouetteFilterSupport::FillPointData(input->GetPointData(), fresh->GetPointData(),
      numPoints,
      PointSourcesOf(*internal.Surface, nothing, frame, numPoints, base->GetNumberOfPoints()));
    fresh->GetPointData()->SetNormals(base->GetPointData()->GetNormals());
  }
  else
  {
    fresh->SetPoints(BuildPoints(input, OutputPointType(input, this->OutputPointsPrecision),
      *internal.Surface, nothing, frame));
    BuildPointData(input->GetPointData(), fresh->GetPointData(), input->GetNumberOfPoints(),
      *internal.Surface, nothing, frame);
  }
  fresh->GetFieldData()->PassData(input->GetFieldData());
  internal.LastBaseGeometry = internal.GeometryTime.GetMTime();
  if (sameCells)
  {
    if (!sameGeometry)
    {
      base->SetPoints(fresh->GetPoints());
    }
    base->GetPointData()->ShallowCopy(fresh->GetPointData());
    base->GetCellData()->ShallowCopy(fresh->GetCellData());
    base->GetFieldData()->ShallowCopy(fresh->GetFieldData());
    return 1;
  }
  base->ShallowCopy(fresh);
  internal.LastBase = base;
  internal.LastBaseBuild = internal.Builds;
  return 1;
}

int vtkSilhouetteSmoothingFilter::BuildChanges(vtkPolyData* input, vtkCamera* camera,
  const double modelMatrix[16], int width, int height, vtkPolyData* changes,
  vtkIdTypeArray* replacedTriangles)
{
  return this->BuildChanges(
    input, camera, modelMatrix, width, height, changes, replacedTriangles, nullptr, {});
}

int vtkSilhouetteSmoothingFilter::BuildChanges(vtkPolyData* input, vtkCamera* camera,
  const double modelMatrix[16], int width, int height, vtkPolyData* changes,
  vtkIdTypeArray* replacedTriangles, vtkSilhouetteFilterSupport::AttributeSources* sources,
  const std::array<const void*, 2>& viewer)
{
  if (!input || !camera || !changes || !replacedTriangles)
  {
    vtkErrorMacro("BuildChanges needs an input, a camera, a mesh and an array to fill.");
    return 0;
  }
  return GuardedBuild(this, input, [&] {
    return this->BuildChangesUnguarded(
      input, camera, modelMatrix, width, height, changes, replacedTriangles, sources, viewer);
  });
}

vtkMTimeType vtkSilhouetteSmoothingFilter::GetGeometryTime() const
{
  return this->Internal->GeometryTime.GetMTime();
}

int vtkSilhouetteSmoothingFilter::BuildChangesUnguarded(vtkPolyData* input, vtkCamera* camera,
  const double modelMatrix[16], int width, int height, vtkPolyData* changes,
  vtkIdTypeArray* replacedTriangles, vtkSilhouetteFilterSupport::AttributeSources* sources,
  const std::array<const void*, 2>& viewer)
{
  if (this->MinimumSamples > this->MaximumSamples)
  {
    vtkErrorMacro("MinimumSamples ("
      << this->MinimumSamples << ") is more than MaximumSamples (" << this->MaximumSamples
      << "): the mesh is drawn unsmoothed until one of them changes.");
    return 0;
  }
  silsmooth::ViewGeometry view;
  const std::string viewError =
    vtkSilhouetteFilterSupport::MakeViewGeometry(camera, modelMatrix, { { width, height } }, view);
  if (!viewError.empty())
  {
    vtkErrorMacro(<< viewError);
    return 0;
  }
  bool rebuilt = false;
  if (!this->Internal->Prepare(this, input, rebuilt))
  {
    return 0;
  }
  Internals& internal = *this->Internal;
  Internals::ChangesHistory& history = internal.HistoryOf(viewer);
  const silsmooth::SmoothingResult result = internal.Smooth(
    this, input, view, false, false, history.Build == internal.Builds ? &history : nullptr);
  history.Subpixel = result.SubpixelTriangleIds;
  history.Remeshed = result.RemeshedTriangles;
  history.SubpixelFeatures = result.SubpixelFeatureIds;
  history.Fallbacks = result.Fallbacks;
  history.Build = internal.Builds;
  const silsmooth::SurfaceFrame frame = internal.Surface->assembleChanges(result);
  const UsedPoints used(frame.Triangles, internal.Surface->outputPointCount() + frame.Added.size());
  changes->Initialize();
  std::vector<vtkIdType> cellSources =
    BuildChangedCells(input, changes, internal.TriangleCell, frame, used);
  changes->SetPoints(BuildPoints(input, OutputPointType(input, this->OutputPointsPrecision),
    *internal.Surface, result, frame, &used.ids()));
  std::vector<vtkSilhouetteFilterSupport::PointSource> pointSources = PointSourcesOf(
    *internal.Surface, result, frame, 0, static_cast<vtkIdType>(used.ids().size()), &used.ids());
  vtkSilhouetteFilterSupport::FillPointData(
    input->GetPointData(), changes->GetPointData(), 0, pointSources);
  changes->GetPointData()->SetNormals(
    ShadingNormals(input->GetPointData(), *internal.Surface, result, frame, &used.ids()));
  if (sources)
  {
    sources->Points = std::move(pointSources);
    sources->Cells = std::move(cellSources);
  }
  replacedTriangles->SetNumberOfComponents(1);
  replacedTriangles->SetNumberOfValues(static_cast<vtkIdType>(frame.ReplacedTriangles.size()));
  std::copy(frame.ReplacedTriangles.begin(), frame.ReplacedTriangles.end(),
    replacedTriangles->GetPointer(0));
  vtkFieldData* fd = changes->GetFieldData();
  AddCount(fd, "SilhouetteTriangleCount", static_cast<vtkIdType>(result.SilhouetteTriangleCount));
  AddCount(fd, "ChordFallbackCount", static_cast<vtkIdType>(result.ChordFallbackTriangles));
  AddCount(fd, "UnresolvedFoldCount", static_cast<vtkIdType>(result.UnresolvedFolds));
  AddCount(fd, "FoldGuardRoundCount", static_cast<vtkIdType>(result.FoldGuardRounds));
  AddCount(fd, "ReusedFallbackCount", static_cast<vtkIdType>(result.ReusedFallbacks));
  AddCount(fd, "CulledTriangleCount", static_cast<vtkIdType>(result.CulledTriangles));
  AddCount(fd, "SubpixelTriangleCount", static_cast<vtkIdType>(result.SubpixelTriangles));
  AddCount(
    fd, "SubpixelFeatureSegmentCount", static_cast<vtkIdType>(result.SubpixelFeatureIds.size()));
  return 1;
}

void vtkSilhouetteSmoothingFilter::CopySmoothingSettings(vtkSilhouetteSmoothingFilter* other)
{
  if (!other || other == this)
  {
    return;
  }
  this->SetTolerance(other->GetTolerance());
  this->SetMinimumSamples(other->GetMinimumSamples());
  this->SetMaximumSamples(other->GetMaximumSamples());
  this->SetNewPointBudget(other->GetNewPointBudget());
  this->SetSamplingRule(other->GetSamplingRule());
  this->SetPerturbVertices(other->GetPerturbVertices());
  this->SetFoldPrevention(other->GetFoldPrevention());
  this->SetReuseFoldFallbacks(other->GetReuseFoldFallbacks());
  this->SetKeepApexesPointed(other->GetKeepApexesPointed());
  this->SetFrustumCulling(other->GetFrustumCulling());
  this->SetSkipSubpixelSmoothing(other->GetSkipSubpixelSmoothing());
  this->SetFeatureLines(other->GetFeatureLines());
  this->SetFeatureEdgeDetection(other->GetFeatureEdgeDetection());
  this->SetFeatureAngle(other->GetFeatureAngle());
  this->SetFlatCreaseDetection(other->GetFlatCreaseDetection());
  this->SetFlatCreaseAngle(other->GetFlatCreaseAngle());
  this->SetNormalSeamFeatures(other->GetNormalSeamFeatures());
  this->SetWeldCoincidentPoints(other->GetWeldCoincidentPoints());
  this->SetWeldTolerance(other->GetWeldTolerance());
  this->SetConsistentOrientation(other->GetConsistentOrientation());
  this->SetNormalEstimation(other->GetNormalEstimation());
  this->SetVisibilityMethod(other->GetVisibilityMethod());
}

void vtkSilhouetteSmoothingFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "MinimumSamples: " << this->MinimumSamples << "\n";
  os << indent << "MaximumSamples: " << this->MaximumSamples << "\n";
  os << indent << "NewPointBudget: " << this->NewPointBudget << "\n";
  os << indent << "PerturbVertices: " << (this->PerturbVertices ? "On" : "Off") << "\n";
  os << indent << "FoldPrevention: " << (this->FoldPrevention ? "On" : "Off") << "\n";
  os << indent << "ReuseFoldFallbacks: " << (this->ReuseFoldFallbacks ? "On" : "Off") << "\n";
  os << indent << "KeepApexesPointed: " << (this->KeepApexesPointed ? "On" : "Off") << "\n";
  os << indent << "FrustumCulling: " << (this->FrustumCulling ? "On" : "Off") << "\n";
  os << indent << "SkipSubpixelSmoothing: " << (this->SkipSubpixelSmoothing ? "On" : "Off") << "\n";
  os << indent << "FeatureLines: " << (this->FeatureLines ? "On" : "Off") << "\n";
  os << indent << "FeatureEdgeDetection: " << (this->FeatureEdgeDetection ? "On" : "Off") << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "SamplingRule: "
     << (this->SamplingRule == SECOND_DIFFERENCE ? "SecondDifference" : "WangEquation8") << "\n";
  os << indent << "WeldCoincidentPoints: " << (this->WeldCoincidentPoints ? "On" : "Off") << "\n";
  os << indent << "WeldTolerance: " << this->WeldTolerance << "\n";
  os << indent << "ConsistentOrientation: " << (this->ConsistentOrientation ? "On" : "Off") << "\n";
  os << indent << "NormalSeamFeatures: " << (this->NormalSeamFeatures ? "On" : "Off") << "\n";
  os << indent << "FlatCreaseDetection: " << (this->FlatCreaseDetection ? "On" : "Off") << "\n";
  os << indent << "FlatCreaseAngle: " << this->FlatCreaseAngle << "\n";
  static const char* const estimations[] = { "AngleWeighted", "AreaWeighted", "MaxWeighted",
    "QuadricFit" };
  os << indent << "NormalEstimation: "
     << (this->NormalEstimation >= ANGLE_WEIGHTED && this->NormalEstimation <= QUADRIC_FIT
            ? estimations[this->NormalEstimation]
            : "?")
     << "\n";
  os << indent << "OutputPointsPrecision: "
     << (this->OutputPointsPrecision == vtkAlgorithm::SINGLE_PRECISION      ? "Single"
            : this->OutputPointsPrecision == vtkAlgorithm::DOUBLE_PRECISION ? "Double"
                                                                            : "Default")
     << "\n";
  os << indent << "VisibilityMethod: "
     << (this->VisibilityMethod == HIERARCHICAL ? "Hierarchical" : "PerVertex") << "\n";
}
