#include "vtkSilhouetteLineVisibility.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include "LineVisibility.h"
#include "OutlineGaps.h"
#include "vtkSilhouetteFilterSupport.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkSilhouetteLineVisibility);

namespace
{

// A gap of the outline running beside one drawn line within this share of
// its own length is a detour, left out (OutlineGaps.h's withoutDetours).
constexpr double DetourShare = 0.25;

vtkIdType FieldValue(vtkIdType value, const char* name, vtkFieldData* fields)
{
  vtkNew<vtkIdTypeArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  fields->AddArray(array);
  return value;
}

} // namespace

vtkSilhouetteLineVisibility::vtkSilhouetteLineVisibility()
{
  this->SetNumberOfInputPorts(2);
  // Visibility depends on the viewport's size only through OutlinePixels.
  this->ViewportDependent = false;
}

vtkSilhouetteLineVisibility::~vtkSilhouetteLineVisibility() = default;

void vtkSilhouetteLineVisibility::SetOutlinePixels(double pixels)
{
  if (std::memcmp(&pixels, &this->OutlinePixels, sizeof(double)) != 0)
  {
    this->OutlinePixels = pixels;
    this->ViewportDependent = pixels > 0.0 || this->OutlineGapPixels > 0.0;
    this->Modified();
  }
}

void vtkSilhouetteLineVisibility::SetOutlineGapPixels(double pixels)
{
  if (std::memcmp(&pixels, &this->OutlineGapPixels, sizeof(double)) != 0)
  {
    this->OutlineGapPixels = pixels;
    this->ViewportDependent = pixels > 0.0 || this->OutlinePixels > 0.0;
    this->Modified();
  }
}

void vtkSilhouetteLineVisibility::SetSurfaceConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

void vtkSilhouetteLineVisibility::SetSurfaceData(vtkDataObject* surface)
{
  this->SetInputData(1, surface);
}

int vtkSilhouetteLineVisibility::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

namespace
{

// The output: one polyline per piece, with the input's point data
// (interpolated at change points) and cell data, `Visible` and
// `OriginalCellId`, and the piece counts.
class PieceWriter
{
public:
  PieceWriter(vtkPolyData* lines, vtkPolyData* output, bool passHidden)
    : InPD(lines->GetPointData())
    , InCD(lines->GetCellData())
    , Output(output)
    , PassHidden(passHidden)
  {
    this->Points->SetDataTypeToDouble();
    output->GetPointData()->InterpolateAllocate(this->InPD, lines->GetNumberOfPoints());
    output->GetCellData()->CopyAllocate(this->InCD, lines->GetNumberOfLines());
    this->PointVisible->SetName("Visible");
    this->CellVisible->SetName("Visible");
    this->Original->SetName("OriginalCellId");
  }

  /// The pieces of input cell `cell`, whose point ids are `ids`.
  void append(const std::vector<silsmooth::LinePiece>& pieces, const std::vector<vtkIdType>& ids,
    vtkIdType cell)
  {
    for (const silsmooth::LinePiece& piece : pieces)
    {
      ++(piece.Visible ? this->VisiblePieces : this->HiddenPieces);
      if (piece.Visible || this->PassHidden)
      {
        this->appendPiece(piece, ids, cell);
      }
      if (piece.Visible && this->KeepVisible)
      {
        this->Visible.push_back(piece.Points);
      }
    }
  }

  /// Keep the visible pieces' points (visiblePieces) from now on.
  void keepVisiblePieces() { this->KeepVisible = true; }
  const std::vector<std::vector<glm::dvec3>>& visiblePieces() const { return this->Visible; }

  /// A stretch of the surface's outline that no line covers: a visible
  /// piece of no input cell (OriginalCellId -1), LineKind OutlineLine when
  /// the input has that array, the other arrays' values null.
  void appendOutlineGap(const std::vector<glm::dvec3>& points)
  {
    ++this->VisiblePieces;
    this->Cells->InsertNextCell(static_cast<vtkIdType>(points.size()));
    for (const glm::dvec3& p : points)
    {
      const vtkIdType id = this->Points->InsertNextPoint(p.x, p.y, p.z);
      this->Cells->InsertCellPoint(id);
      this->Output->GetPointData()->NullData(id);
      this->PointVisible->InsertNextValue(1);
    }
    const vtkIdType cell = this->Cells->GetNumberOfCells() - 1;
    vtkCellData* outCD = this->Output->GetCellData();
    outCD->NullData(cell);
    if (vtkDataArray* kinds = outCD->GetArray("LineKind"))
    {
      kinds->SetComponent(cell, 0, vtkSilhouetteFilterSupport::OutlineLine);
    }
    this->CellVisible->InsertNextValue(1);
    this->Original->InsertNextValue(-1);
  }

  void finish()
  {
    this->Output->SetPoints(this->Points);
    this->Output->SetLines(this->Cells);
    this->Output->GetPointData()->AddArray(this->PointVisible);
    this->Output->GetCellData()->AddArray(this->CellVisible);
    this->Output->GetCellData()->AddArray(this->Original);
    FieldValue(this->VisiblePieces, "VisiblePieceCount", this->Output->GetFieldData());
    FieldValue(this->HiddenPieces, "HiddenPieceCount", this->Output->GetFieldData());
  }

private:
  void appendPiece(
    const silsmooth::LinePiece& piece, const std::vector<vtkIdType>& ids, vtkIdType cell)
  {
    vtkPointData* outPD = this->Output->GetPointData();
    const auto n = static_cast<vtkIdType>(ids.size());
    this->Cells->InsertNextCell(static_cast<vtkIdType>(piece.Points.size()));
    for (std::size_t k = 0; k < piece.Points.size(); ++k)
    {
      const glm::dvec3& p = piece.Points[k];
      const vtkIdType id = this->Points->InsertNextPoint(p.x, p.y, p.z);
      this->Cells->InsertCellPoint(id);
      // Vertex i keeps its data; a change point interpolates its segment's.
      const double along = piece.Along[k];
      const vtkIdType i0 = std::min(static_cast<vtkIdType>(along), n - 1);
      const double fraction = along - static_cast<double>(i0);
      if (fraction > 0.0 && i0 + 1 < n)
      {
        outPD->InterpolateEdge(this->InPD, id, ids[static_cast<std::size_t>(i0)],
          ids[static_cast<std::size_t>(i0 + 1)], fraction);
      }
      else
      {
        outPD->CopyData(this->InPD, ids[static_cast<std::size_t>(i0)], id);
      }
      this->PointVisible->InsertNextValue(piece.Visible ? 1 : 0);
    }
    this->Output->GetCellData()->CopyData(this->InCD, cell, this->Cells->GetNumberOfCells() - 1);
    this->CellVisible->InsertNextValue(piece.Visible ? 1 : 0);
    this->Original->InsertNextValue(cell);
  }

  vtkPointData* InPD;
  vtkCellData* InCD;
  vtkPolyData* Output;
  bool PassHidden;
  vtkNew<vtkPoints> Points;
  vtkNew<vtkCellArray> Cells;
  vtkNew<vtkUnsignedCharArray> PointVisible;
  vtkNew<vtkUnsignedCharArray> CellVisible;
  vtkNew<vtkIdTypeArray> Original;
  vtkIdType VisiblePieces = 0;
  vtkIdType HiddenPieces = 0;
  bool KeepVisible = false;
  std::vector<std::vector<glm::dvec3>> Visible;
};

// Whether input cell `cell` lies on the surface itself (LineKind crease,
// border or intersection, as vtkCreaseAndBorderLines marks them).
class SurfaceEdgeCells
{
public:
  explicit SurfaceEdgeCells(vtkPolyData* lines)
    : Kinds(lines->GetCellData()->GetArray("LineKind"))
  {
    if (this->Kinds && this->Kinds->GetNumberOfComponents() != 1)
    {
      this->Kinds = nullptr;
    }
  }
  bool operator()(vtkIdType cell) const
  {
    if (!this->Kinds)
    {
      return false;
    }
    const double kind = this->Kinds->GetComponent(cell, 0);
    return kind == vtkSilhouetteFilterSupport::CreaseLine ||
      kind == vtkSilhouetteFilterSupport::BorderLine ||
      kind == vtkSilhouetteFilterSupport::IntersectionLine;
  }

private:
  vtkDataArray* Kinds;
};

} // namespace

std::string vtkSilhouetteLineVisibility::CheckSettings() const
{
  // Each a length or a number of pixels: 0 or positive, and finite (an
  // infinite OutlineGapPixels drew stray contour pieces, a user's trial).
  const std::pair<const char*, double> settings[] = {
    { "Tolerance must be 0 (automatic)", this->Tolerance },
    { "EdgeTolerance must be 0 (automatic)", this->EdgeTolerance },
    { "OutlinePixels must be 0 (off)", this->OutlinePixels },
    { "OutlineGapPixels must be 0 (off)", this->OutlineGapPixels },
  };
  std::ostringstream message;
  for (const auto& [rule, value] : settings)
  {
    if (!(value >= 0.0) || !std::isfinite(value))
    {
      message << rule << " or a positive finite number, not " << value << ".";
      break;
    }
  }
  return message.str();
}

int vtkSilhouetteLineVisibility::RequestViewData(vtkInformation*,
  vtkInformationVector** inputVector, vtkInformationVector* outputVector,
  const vtkSilhouetteFilterSupport::View& view)
{
  vtkPolyData* lines = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* surface = vtkPolyData::GetData(inputVector[1]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  const std::string settingsError = this->CheckSettings();
  if (!settingsError.empty())
  {
    vtkErrorMacro(<< settingsError);
    return 0;
  }
  if (lines->GetNumberOfVerts() + lines->GetNumberOfPolys() + lines->GetNumberOfStrips() > 0)
  {
    vtkWarningMacro("Only line cells are split; the input's vertex, polygon and strip cells are "
                    "left out.");
  }

  // The surface as triangles; without one, nothing hides anything.
  vtkSilhouetteFilterSupport::Triangles triangles;
  if (surface && surface->GetNumberOfCells() > 0)
  {
    const std::string readError = vtkSilhouetteFilterSupport::ReadTriangles(surface, triangles);
    if (!readError.empty())
    {
      vtkErrorMacro(<< "Surface: " << readError);
      return 0;
    }
  }
  // The silhouette's rule, and the one for the surface's own edges.
  silsmooth::LineVisibilityParameters parameters =
    silsmooth::LineVisibilityParameters::forMesh(triangles.Points, triangles.Cells);
  if (this->Tolerance > 0.0)
  {
    parameters.Tolerance = this->Tolerance;
  }
  parameters.OutlinePixels = this->OutlinePixels;
  // Where the gaps' contour closes the outline, a short dip is left to it:
  // drawn, the dip's chord ran across a tip inside the outline (up to 3.2 px
  // off it on the coarse bunny, docs/line-drawings.md).
  parameters.DrawShortDips = !(this->OutlineGapPixels > 0.0);
  silsmooth::LineVisibilityParameters edgeParameters = parameters;
  edgeParameters.OutlinePixels = 0.0;
  edgeParameters.Tolerance =
    this->EdgeTolerance > 0.0 ? this->EdgeTolerance : 10.0 * parameters.Precision;
  // The stubs a tolerance leaves where an occluder meets the line.
  edgeParameters.MinimumPieceLength = 10.0 * edgeParameters.Tolerance;
  const SurfaceEdgeCells isSurfaceEdge(lines);
  const silsmooth::OcclusionMesh occluder(
    std::move(triangles.Points), std::move(triangles.Cells), triangles.Normals);

  PieceWriter writer(lines, output, this->PassHiddenLines != 0);
  const bool fillGaps = this->OutlineGapPixels > 0.0 && !occluder.empty();
  if (fillGaps)
  {
    writer.keepVisiblePieces();
  }
  const vtkIdType lineCount = lines->GetNumberOfLines();
  const vtkIdType firstLineId = lines->GetNumberOfVerts(); // cells: verts, then lines
  std::vector<glm::dvec3> polyline;
  std::vector<vtkIdType> polylineIds;
  auto it = vtk::TakeSmartPointer(lines->GetLines()->NewIterator());
  vtkIdType line = 0;
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++line)
  {
    if (line % 256 == 0)
    {
      if (!vtkSilhouetteFilterSupport::ReportProgress(
            this, static_cast<double>(line) / static_cast<double>(lineCount)))
      {
        break;
      }
    }
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(n, ids);
    if (n < 2)
    {
      continue;
    }
    polylineIds.assign(ids, ids + n);
    polyline.resize(static_cast<std::size_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
    {
      double x[3];
      lines->GetPoint(ids[i], x);
      polyline[static_cast<std::size_t>(i)] = glm::dvec3(x[0], x[1], x[2]);
    }
    const vtkIdType cell = firstLineId + line;
    writer.append(silsmooth::splitByVisibility(occluder, view.Geometry, polyline,
                    isSurfaceEdge(cell) ? edgeParameters : parameters),
      polylineIds, cell);
  }
  if (fillGaps && !this->GetAbortExecute())
  {
    // The outline the drawn lines leave open, with the surface's contour
    // (OutlineGaps.h): lying on the surface, it is visible by the rule of
    // the lines that lie on it exactly.
    silsmooth::OutlineGapParameters gapParameters;
    gapParameters.GapPixels = this->OutlineGapPixels;
    gapParameters.JoinPixels = std::min(1.5, this->OutlineGapPixels);
    // A part two tolerances (mean edges) or more behind the contour leaves
    // it an outline (a depth jump); the re-meshing's own folds lie nearer.
    // One tolerance drew 5 more stray pixels on the Wuson's second view of
    // TestLineDrawingAccuracy, half of one 14 and 34 more on its two views;
    // 2, 4 and the whole line of sight none (docs/line-drawings.md).
    gapParameters.DepthJump = 2.0 * parameters.Tolerance;
    gapParameters.Visibility = edgeParameters;
    // Each gap joined to the lines at its ends: it stops where they cover
    // the contour (1.5 px from a line's end, or beside one within
    // OutlineGapPixels), which left a break of a pixel or two at each end of
    // a filled gap (a user's trial: the Wuson's back read as a dashed line).
    // Gaps beside a drawn line all along are left out (OutlineGaps.h's
    // withoutDetours): within a quarter of their length of it, they closed
    // boxes beside a zoomed-in outline.
    // Where a gap stops, the contour has come within OutlineGapPixels of a
    // line: a pixel more finds that line from the gap's end.
    const double reach = this->OutlineGapPixels + 1.0;
    const std::vector<std::vector<glm::dvec3>>& drawn = writer.visiblePieces();
    for (const std::vector<glm::dvec3>& gap : silsmooth::joinedToDrawnLines(
           silsmooth::withoutDetours(
             silsmooth::outlineGaps(occluder, view.Geometry, drawn, gapParameters), view.Geometry,
             drawn, reach, DetourShare),
           view.Geometry, drawn, reach))
    {
      writer.appendOutlineGap(gap);
    }
  }
  if (!this->GetAbortExecute())
  {
    this->UpdateProgress(1.0);
  }
  writer.finish(); // aborted: the lines done so far
  return 1;
}

void vtkSilhouetteLineVisibility::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Tolerance: " << this->Tolerance << (this->Tolerance > 0 ? "" : " (automatic)")
     << "\n";
  os << indent << "EdgeTolerance: " << this->EdgeTolerance
     << (this->EdgeTolerance > 0 ? "" : " (automatic)") << "\n";
  os << indent << "OutlinePixels: " << this->OutlinePixels << "\n";
  os << indent << "OutlineGapPixels: " << this->OutlineGapPixels << "\n";
  os << indent << "PassHiddenLines: " << (this->PassHiddenLines ? "On" : "Off") << "\n";
}
