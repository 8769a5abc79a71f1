#include "vtkSilhouettePatchedMapper.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLCellToVTKCellMap.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLIndexBufferObject.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkShader.h"
#include "vtkShaderProgram.h"
#include "vtkUnsignedIntArray.h"
#include "vtk_glew.h"

#include <algorithm>
#include <iterator>
#include <string>

// The helper that draws the patch. It differs from its superclass in one
// thing: in hardware-selection passes its cell ids start at CellIdOffset and
// its point ids at PointIdOffset, so that the owner can tell its pixels
// from the mesh's.
class vtkSilhouettePatchedMapper::PatchMapper : public vtkOpenGLPolyDataMapper
{
public:
  static PatchMapper* New();
  vtkTypeMacro(PatchMapper, vtkOpenGLPolyDataMapper);
  int CellIdOffset = 0;
  int PointIdOffset = 0;

protected:
  PatchMapper() = default;
  ~PatchMapper() override = default;

  // The strings replaced are those of vtkOpenGLPolyDataMapper's picking
  // shader code (VTK 9.1; the same in ParaView 5.11's VTK).
  void ReplaceShaderPicking(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override
  {
    // Declarations first, while //VTK::Picking::Dec is still in the templates.
    vtkShaderProgram::Substitute(shaders[vtkShader::Fragment], "//VTK::Picking::Dec",
      "uniform int patchCellIdOffset;\n//VTK::Picking::Dec");
    vtkShaderProgram::Substitute(shaders[vtkShader::Vertex], "//VTK::Picking::Dec",
      "uniform int patchPointIdOffset;\n//VTK::Picking::Dec");
    this->Superclass::ReplaceShaderPicking(shaders, ren, act);
    vtkShaderProgram::Substitute(shaders[vtkShader::Fragment],
      "int idx = gl_PrimitiveID + PrimitiveIDOffset;",
      "int idx = gl_PrimitiveID + PrimitiveIDOffset + patchCellIdOffset;");
    vtkShaderProgram::Substitute(shaders[vtkShader::Fragment],
      "int idx = (gl_PrimitiveID + PrimitiveIDOffset);",
      "int idx = (gl_PrimitiveID + PrimitiveIDOffset + patchCellIdOffset);");
    vtkShaderProgram::Substitute(shaders[vtkShader::Vertex], "vertexIDVSOutput = gl_VertexID;",
      "vertexIDVSOutput = gl_VertexID + patchPointIdOffset;");
  }

  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override
  {
    this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
    if (cellBO.Program->IsUniformUsed("patchCellIdOffset"))
    {
      cellBO.Program->SetUniformi("patchCellIdOffset", this->CellIdOffset);
    }
    if (cellBO.Program->IsUniformUsed("patchPointIdOffset"))
    {
      cellBO.Program->SetUniformi("patchPointIdOffset", this->PointIdOffset);
    }
  }

private:
  PatchMapper(const PatchMapper&) = delete;
  void operator=(const PatchMapper&) = delete;
};

vtkStandardNewMacro(vtkSilhouettePatchedMapper::PatchMapper);
vtkStandardNewMacro(vtkSilhouettePatchedMapper);

namespace
{

// Two runs of changed triangles at most this many unchanged triangles apart
// go into one glBufferSubData (the unchanged ones written as they are): the
// call count, not the bytes, is what a frame's update costs (about 2,000
// calls against 1,200 on a 1.3M-triangle orbit; research notes of issue 15).
constexpr vtkIdType MergeGap = 16;

vtkIdType RawId(vtkHardwareSelector* sel, int lowPass, int highPass, unsigned int pos)
{
  unsigned char* low = sel->GetRawPixelBuffer(lowPass);
  unsigned char* high = sel->GetRawPixelBuffer(highPass);
  if (!low)
  {
    return -1;
  }
  vtkIdType v = high ? high[pos] : 0;
  v = (v << 8) | low[pos + 2];
  v = (v << 8) | low[pos + 1];
  v = (v << 8) | low[pos];
  return v;
}

void Write24(unsigned char* buffer, unsigned int pos, vtkIdType value, bool high)
{
  if (high)
  {
    value >>= 24;
  }
  buffer[pos] = value & 0xff;
  buffer[pos + 1] = (value >> 8) & 0xff;
  buffer[pos + 2] = (value >> 16) & 0xff;
}

} // namespace

vtkSilhouettePatchedMapper::vtkSilhouettePatchedMapper()
  : Patch(vtkSmartPointer<PatchMapper>::New())
{
  this->Patch->SetStatic(1);
  // This mapper reports the selection ids and their maximum; the helper
  // must not begin or end a prop of its own.
  this->Patch->SetPopulateSelectionSettings(0);
  this->Patch->SetInputData(this->PatchData);
}

vtkSilhouettePatchedMapper::~vtkSilhouettePatchedMapper() = default;

void vtkSilhouettePatchedMapper::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Patch->ReleaseGraphicsResources(win);
  this->SelectionPatches.clear();
  this->Applied.clear();
  this->LayoutKnown = false;
  this->Superclass::ReleaseGraphicsResources(win);
}

void vtkSilhouettePatchedMapper::SetPatch(const std::vector<vtkIdType>& hidden, vtkPolyData* patch,
  vtkIdTypeArray* patchCellIds, const std::vector<vtkIdType>& patchPointSources)
{
  this->Wanted = hidden;
  if (patch)
  {
    this->PatchData->ShallowCopy(patch); // new time: the helper uploads its small buffers
  }
  else
  {
    this->PatchData->Initialize();
  }
  this->PatchCellIds = patchCellIds;
  this->PatchPointSources = patchPointSources;
  this->PatchFieldsCopied = false;
}

// Called when the superclass builds its buffers (an input or representation
// change). When it really rebuilt the index buffer, every triangle is drawn
// again: forget what was hidden and record the layout.
void vtkSilhouettePatchedMapper::BuildIBO(vtkRenderer* ren, vtkActor* act, vtkPolyData* poly)
{
  vtkStateStorage before; // its copy constructor is deleted, its assignment is not
  before = this->IBOBuildState;
  this->Superclass::BuildIBO(ren, act, poly);
  if (!(this->IBOBuildState != before) && this->LayoutKnown)
  {
    return;
  }
  this->Applied.clear();
  // Surface and surface with edges share the triangle layout; the others
  // draw points or lines, and the input whole.
  const bool surface = act->GetProperty()->GetRepresentation() == VTK_SURFACE;
  if (surface && this->LayoutKnown && this->LayoutUnchanged(poly))
  {
    // Only the points moved (a deforming mesh): the new buffer holds the
    // recorded triangles, none of them hidden.
    std::fill(this->TriangleHidden.begin(), this->TriangleHidden.end(), 0);
    this->LayoutKnown = this->Pristine.size() == this->Primitives[PrimitiveTris].IBO->IndexCount;
    return;
  }
  this->LayoutKnown = false;
  if (surface)
  {
    this->RecordTriangleLayout(poly);
  }
}

namespace
{

// The superclass's rule for the triangles it draws of polygon `ids` (n
// points): the fan (ids[0], ids[i], ids[i + 1]), i = 1 .. n - 2, less the
// triangles with two corners at one position (AppendTrianglesWorker in
// vtkOpenGLIndexBufferObject.cxx). Calls kept(a, b, c) for each triangle
// kept, in order, and counted(cell, count) after each polygon; either
// returning false stops the walk, which then returns false. `same(a, b)`:
// whether points a and b have one position.
template<typename Same, typename Kept, typename Counted>
bool WalkKeptTriangles(
  vtkCellArray* polys, const Same& same, const Kept& kept, const Counted& counted)
{
  vtkIdType c = 0;
  auto it = vtk::TakeSmartPointer(polys->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++c)
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(n, ids);
    int count = 0;
    for (vtkIdType i = 1; i + 1 < n; ++i)
    {
      if (same(ids[0], ids[i]) || same(ids[i + 1], ids[i]) || same(ids[i + 1], ids[0]))
      {
        continue;
      }
      if (!kept(ids[0], ids[i], ids[i + 1]))
      {
        return false;
      }
      ++count;
    }
    if (!counted(c, count))
    {
      return false;
    }
  }
  return true;
}

// WalkKeptTriangles over `points`: positions compared in place for float and
// double points (the deforming mesh's every frame), through GetPoint else.
template<typename Kept, typename Counted>
bool WalkKeptTriangles(
  vtkCellArray* polys, vtkPoints* points, const Kept& kept, const Counted& counted)
{
  vtkDataArray* data = points->GetData();
  const auto inPlace = [&](const auto* x) {
    const auto same = [x](vtkIdType a, vtkIdType b) {
      return x[3 * a] == x[3 * b] && x[3 * a + 1] == x[3 * b + 1] && x[3 * a + 2] == x[3 * b + 2];
    };
    return WalkKeptTriangles(polys, same, kept, counted);
  };
  if (data->GetNumberOfComponents() == 3)
  {
    if (auto* doubles = vtkDoubleArray::FastDownCast(data))
    {
      return inPlace(doubles->GetPointer(0));
    }
    if (auto* floats = vtkFloatArray::FastDownCast(data))
    {
      return inPlace(floats->GetPointer(0));
    }
  }
  const auto same = [points](vtkIdType a, vtkIdType b) {
    double p[3];
    double q[3];
    points->GetPoint(a, p);
    points->GetPoint(b, q);
    return p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
  };
  return WalkKeptTriangles(polys, same, kept, counted);
}

} // namespace

// Whether the superclass's new triangle buffer is the recorded one: the same
// polygons (the same cell array, unmodified) whose kept triangles are the
// recorded ones, as many from each polygon as recorded (a cell array edited
// in place keeps its modification time in VTK 9.1, and two polygons could
// trade a kept triangle with the list unchanged). A deforming mesh's points
// change every frame, and the superclass then builds its buffer again (which
// triangles it leaves out depends on the positions); recording the layout
// again each time cost about a fifth of such a frame at 1.3M triangles.
bool vtkSilhouettePatchedMapper::LayoutUnchanged(vtkPolyData* poly) const
{
  vtkCellArray* polys = poly->GetPolys();
  vtkPoints* points = poly->GetPoints();
  if (!polys || !points || polys != this->LayoutPolys ||
    polys->GetMTime() != this->LayoutPolysTime ||
    polys->GetNumberOfCells() != static_cast<vtkIdType>(this->FirstTriangle.size()))
  {
    return false;
  }
  const std::vector<unsigned int>& pristine = this->Pristine;
  std::size_t next = 0;
  const auto kept = [&](vtkIdType a, vtkIdType b, vtkIdType c) {
    const bool same = next + 3 <= pristine.size() &&
      pristine[next] == static_cast<unsigned int>(a) &&
      pristine[next + 1] == static_cast<unsigned int>(b) &&
      pristine[next + 2] == static_cast<unsigned int>(c);
    next += 3;
    return same;
  };
  const auto counted = [this](vtkIdType cell, int count) {
    return this->TriangleCount[static_cast<std::size_t>(cell)] == count;
  };
  return WalkKeptTriangles(polys, points, kept, counted) && next == pristine.size();
}

void vtkSilhouettePatchedMapper::RecordTriangleLayout(vtkPolyData* poly)
{
  this->Pristine.clear();
  this->LayoutPolys = nullptr;
  vtkCellArray* polys = poly->GetPolys();
  vtkPoints* points = poly->GetPoints();
  if (!points)
  {
    return;
  }
  vtkOpenGLIndexBufferObject::AppendTriangleIndexBuffer(
    this->Pristine, polys, points, 0, nullptr, nullptr);
  const vtkIdType cells = polys->GetNumberOfCells();
  this->FirstTriangle.resize(static_cast<std::size_t>(cells));
  this->TriangleCount.resize(static_cast<std::size_t>(cells));
  vtkIdType triangle = 0;
  WalkKeptTriangles(
    polys, points, [](vtkIdType, vtkIdType, vtkIdType) { return true; },
    [this, &triangle](vtkIdType cell, int count) {
      this->FirstTriangle[static_cast<std::size_t>(cell)] = triangle;
      this->TriangleCount[static_cast<std::size_t>(cell)] = count;
      triangle += count;
      return true;
    });
  this->TriangleHidden.assign(static_cast<std::size_t>(triangle), 0);
  vtkOpenGLIndexBufferObject* ibo = this->Primitives[PrimitiveTris].IBO;
  this->LayoutKnown = static_cast<std::size_t>(triangle) * 3 == this->Pristine.size() &&
    this->Pristine.size() == ibo->IndexCount;
  this->LayoutPolys = polys;
  this->LayoutPolysTime = polys ? polys->GetMTime() : 0;
  if (!this->LayoutKnown)
  {
    vtkWarningMacro("The triangle index buffer is not laid out as expected; the mesh is drawn "
                    "without its silhouette patch.");
  }
}

bool vtkSilhouettePatchedMapper::PatchDrawn(vtkRenderer* ren, vtkActor* act)
{
  vtkHardwareSelector* sel = ren->GetSelector();
  const bool pointPicking =
    sel && sel->GetFieldAssociation() == vtkDataObject::FIELD_ASSOCIATION_POINTS;
  return this->LayoutKnown && !pointPicking &&
    act->GetProperty()->GetRepresentation() == VTK_SURFACE;
}

// Makes the buffer's degenerate set the wanted one (or none, where the patch
// is not drawn in this pass), writing only the triangles that change.
void vtkSilhouettePatchedMapper::ApplyHidden(vtkRenderer* ren, vtkActor* act)
{
  this->LastPatchedTriangles = 0;
  this->LastPatchCalls = 0;
  if (!this->LayoutKnown)
  {
    return;
  }
  std::vector<vtkIdType> target;
  if (this->PatchDrawn(ren, act))
  {
    target = this->Wanted;
  }
  const vtkIdType polygons = static_cast<vtkIdType>(this->FirstTriangle.size());
  target.erase(std::remove_if(target.begin(), target.end(),
                 [polygons](vtkIdType c) { return c < 0 || c >= polygons; }),
    target.end());
  if (target == this->Applied)
  {
    return;
  }
  std::vector<vtkIdType> restore, hide;
  std::set_difference(this->Applied.begin(), this->Applied.end(), target.begin(), target.end(),
    std::back_inserter(restore));
  std::set_difference(target.begin(), target.end(), this->Applied.begin(), this->Applied.end(),
    std::back_inserter(hide));
  std::vector<std::pair<vtkIdType, bool>> changes; // polygon, hidden after
  changes.reserve(restore.size() + hide.size());
  for (const vtkIdType c : restore)
  {
    changes.emplace_back(c, false);
  }
  for (const vtkIdType c : hide)
  {
    changes.emplace_back(c, true);
  }
  std::sort(changes.begin(), changes.end());

  // GL_COPY_WRITE_BUFFER, not GL_ELEMENT_ARRAY_BUFFER: binding the latter
  // would change the element buffer of whatever vertex array is bound.
  vtkOpenGLIndexBufferObject* ibo = this->Primitives[PrimitiveTris].IBO;
  glBindBuffer(GL_COPY_WRITE_BUFFER, static_cast<GLuint>(ibo->GetHandle()));
  std::vector<unsigned int> run;
  vtkIdType runStart = -1; // first triangle of the run
  vtkIdType runEnd = -1;   // one past its last
  auto flush = [&]() {
    if (!run.empty())
    {
      glBufferSubData(GL_COPY_WRITE_BUFFER,
        static_cast<GLintptr>(runStart * 3 * static_cast<vtkIdType>(sizeof(unsigned int))),
        static_cast<GLsizeiptr>(run.size() * sizeof(unsigned int)), run.data());
      ++this->LastPatchCalls;
      this->LastPatchedTriangles += static_cast<vtkIdType>(run.size() / 3);
      run.clear();
    }
  };
  auto write = [&](vtkIdType triangle, bool hidden) {
    const unsigned int* t = &this->Pristine[static_cast<std::size_t>(3 * triangle)];
    run.push_back(t[0]);
    run.push_back(hidden ? t[0] : t[1]);
    run.push_back(hidden ? t[0] : t[2]);
  };
  for (const auto& [polygon, hidden] : changes)
  {
    const vtkIdType first = this->FirstTriangle[static_cast<std::size_t>(polygon)];
    const int count = this->TriangleCount[static_cast<std::size_t>(polygon)];
    if (count == 0)
    {
      continue;
    }
    if (!run.empty() && first >= runEnd && first - runEnd <= MergeGap)
    {
      for (vtkIdType g = runEnd; g < first; ++g) // unchanged: as they are now
      {
        write(g, this->TriangleHidden[static_cast<std::size_t>(g)] != 0);
      }
    }
    else
    {
      flush();
      runStart = first;
    }
    for (int k = 0; k < count; ++k)
    {
      write(first + k, hidden);
      this->TriangleHidden[static_cast<std::size_t>(first + k)] = hidden ? 1 : 0;
    }
    runEnd = first + count;
  }
  flush();
  glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
  this->Applied = target;
}

void vtkSilhouettePatchedMapper::RenderPieceStart(vtkRenderer* ren, vtkActor* act)
{
  // Builds the buffers when the input changed (BuildIBO above), then the
  // selection's maximum ids (UpdateMaximumPointCellIds below).
  this->Superclass::RenderPieceStart(ren, act);
  this->ApplyHidden(ren, act);
}

void vtkSilhouettePatchedMapper::MapDataArrayToVertexAttribute(
  const char* vertexAttributeName, const char* dataArrayName, int fieldAssociation, int componentno)
{
  this->Superclass::MapDataArrayToVertexAttribute(
    vertexAttributeName, dataArrayName, fieldAssociation, componentno);
  this->Patch->MapDataArrayToVertexAttribute(
    vertexAttributeName, dataArrayName, fieldAssociation, componentno);
}

void vtkSilhouettePatchedMapper::MapDataArrayToMultiTextureAttribute(
  const char* textureName, const char* dataArrayName, int fieldAssociation, int componentno)
{
  this->Superclass::MapDataArrayToMultiTextureAttribute(
    textureName, dataArrayName, fieldAssociation, componentno);
  this->Patch->MapDataArrayToMultiTextureAttribute(
    textureName, dataArrayName, fieldAssociation, componentno);
}

void vtkSilhouettePatchedMapper::RemoveVertexAttributeMapping(const char* vertexAttributeName)
{
  this->Superclass::RemoveVertexAttributeMapping(vertexAttributeName);
  this->Patch->RemoveVertexAttributeMapping(vertexAttributeName);
}

void vtkSilhouettePatchedMapper::RemoveAllVertexAttributeMappings()
{
  this->Superclass::RemoveAllVertexAttributeMappings();
  this->Patch->RemoveAllVertexAttributeMappings();
}

void vtkSilhouettePatchedMapper::ReplaceShaderNormal(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::ReplaceShaderNormal(shaders, ren, act);
  // The point normals' line of the fragment shader, as VTK 9.1 writes it;
  // where it is not there (no point normals), nothing is replaced.
  vtkShader* fragment = shaders[vtkShader::Fragment];
  if (!fragment)
  {
    return;
  }
  std::string source = fragment->GetSource();
  if (vtkShaderProgram::Substitute(source, "vec3 normalVCVSOutput = normalize(normalVCVSOutput);",
        "vec3 normalVCVSOutput = dot(normalVCVSOutput, normalVCVSOutput) > 0.0 ?\n"
        "    normalize(normalVCVSOutput) : vec3(0.0, 0.0, 1.0);",
        false))
  {
    fragment->SetSource(source);
  }
}

void vtkSilhouettePatchedMapper::UpdateMaximumPointCellIds(vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::UpdateMaximumPointCellIds(ren, act);
  // The helper's ids start past every id the mesh can write.
  this->PatchCellOffset = this->CellCellMap->GetFinalOffset();
  this->PatchPointOffset = this->CurrentInput->GetNumberOfPoints();
  if (this->PatchDrawn(ren, act) && this->PatchData->GetNumberOfCells() > 0)
  {
    vtkHardwareSelector* sel = ren->GetSelector();
    sel->UpdateMaximumCellId(this->PatchCellOffset + this->PatchData->GetNumberOfCells());
    sel->UpdateMaximumPointId(this->PatchPointOffset + this->PatchData->GetNumberOfPoints());
  }
}

void vtkSilhouettePatchedMapper::RenderPieceDraw(vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::RenderPieceDraw(ren, act);
  this->PatchDrawnThisPass = this->PatchDrawn(ren, act) && this->PatchData->GetNumberOfCells() > 0;
  if (ren->GetSelector())
  {
    DrawnPatch& drawn = this->SelectionPatches[act];
    drawn.CellIds = this->PatchCellIds;
    drawn.PointSources = this->PatchPointSources;
    drawn.CellOffset = this->PatchCellOffset;
    drawn.PointOffset = this->PatchPointOffset;
    drawn.Drawn = this->PatchDrawnThisPass;
  }
  if (!this->PatchDrawnThisPass)
  {
    return;
  }
  // The same colouring (lookup table, scalar mode and range, colour mode,
  // array, clipping planes, coincident-topology offsets): vtkMapper's
  // settings only, not the input.
  if (this->GetMTime() > this->PatchSettingsTime)
  {
    this->Patch->vtkMapper::ShallowCopy(this);
    this->Patch->SetSeamlessU(this->GetSeamlessU());
    this->Patch->SetSeamlessV(this->GetSeamlessV());
    this->Patch->SetVBOShiftScaleMethod(this->GetVBOShiftScaleMethod());
    this->PatchSettingsTime = this->GetMTime();
  }
  // The input's field data (a field-data tuple colours every cell alike),
  // copied into an object of the patch's own: each new patch comes with its
  // field data, and a shallow copy may write into the object it holds.
  vtkFieldData* fields = this->CurrentInput ? this->CurrentInput->GetFieldData() : nullptr;
  if (fields && (!this->PatchFieldsCopied || fields->GetMTime() > this->PatchFieldsTime))
  {
    vtkNew<vtkFieldData> copy;
    copy->ShallowCopy(fields);
    this->PatchData->SetFieldData(copy);
    this->PatchFieldsCopied = true;
    this->PatchFieldsTime = fields->GetMTime();
  }
  this->Patch->CellIdOffset = static_cast<int>(this->PatchCellOffset);
  this->Patch->PointIdOffset = static_cast<int>(this->PatchPointOffset);
  // Inside this mapper's BeginRenderProp/EndRenderProp, so the selector's
  // prop id and composite index are this mapper's.
  this->Patch->RenderPiece(ren, act);
}

// The patch's pixels are converted here (its cell ids to the ids given with
// SetPatch); the others go to the superclass, which maps them through its
// cell map and id arrays.
void vtkSilhouettePatchedMapper::ProcessSelectorPixelBuffers(
  vtkHardwareSelector* sel, std::vector<unsigned int>& pixeloffsets, vtkProp* prop)
{
  vtkPolyData* poly = this->CurrentInput;
  const auto recorded = this->SelectionPatches.find(prop);
  DrawnPatch current;
  if (recorded == this->SelectionPatches.end())
  {
    current = { this->PatchCellIds, this->PatchPointSources, this->PatchCellOffset,
      this->PatchPointOffset, this->PatchDrawnThisPass };
  }
  const DrawnPatch& drawn = recorded != this->SelectionPatches.end() ? recorded->second : current;
  if (!this->PopulateSelectionSettings || !poly || !drawn.Drawn)
  {
    this->Superclass::ProcessSelectorPixelBuffers(sel, pixeloffsets, prop);
    return;
  }
  const int pass = sel->GetCurrentPass();
  const bool pointPass = pass == vtkHardwareSelector::POINT_ID_LOW24 ||
    pass == vtkHardwareSelector::POINT_ID_HIGH24 || pass == vtkHardwareSelector::PROCESS_PASS;
  const bool cellPass = pass == vtkHardwareSelector::CELL_ID_LOW24 ||
    pass == vtkHardwareSelector::CELL_ID_HIGH24 ||
    pass == vtkHardwareSelector::COMPOSITE_INDEX_PASS;
  vtkUnsignedIntArray* processIds = this->ProcessIdArrayName && sel->GetUseProcessIdFromData()
    ? vtkArrayDownCast<vtkUnsignedIntArray>(
        poly->GetPointData()->GetArray(this->ProcessIdArrayName))
    : nullptr;
  vtkUnsignedIntArray* compositeIds = this->CompositeIdArrayName
    ? vtkArrayDownCast<vtkUnsignedIntArray>(
        poly->GetCellData()->GetArray(this->CompositeIdArrayName))
    : nullptr;
  std::vector<unsigned int> mesh;
  mesh.reserve(pixeloffsets.size());
  unsigned char* out = sel->GetPixelBuffer(pass);
  const vtkIdType patchCells = drawn.CellIds ? drawn.CellIds->GetNumberOfValues() : 0;
  const vtkIdType patchPoints = static_cast<vtkIdType>(drawn.PointSources.size());
  for (const unsigned int pos : pixeloffsets)
  {
    vtkIdType k = -1;
    if (pointPass)
    {
      const vtkIdType raw =
        RawId(sel, vtkHardwareSelector::POINT_ID_LOW24, vtkHardwareSelector::POINT_ID_HIGH24, pos);
      k = raw >= drawn.PointOffset ? raw - drawn.PointOffset : -1;
      k = k < patchPoints ? k : -1;
    }
    else if (cellPass)
    {
      const vtkIdType raw =
        RawId(sel, vtkHardwareSelector::CELL_ID_LOW24, vtkHardwareSelector::CELL_ID_HIGH24, pos);
      k = raw >= drawn.CellOffset ? raw - drawn.CellOffset : -1;
      k = k < patchCells ? k : -1;
    }
    if (k < 0)
    {
      mesh.push_back(pos);
      continue;
    }
    if (!out)
    {
      continue;
    }
    switch (pass)
    {
      case vtkHardwareSelector::CELL_ID_LOW24:
      case vtkHardwareSelector::CELL_ID_HIGH24:
        Write24(out, pos, drawn.CellIds->GetValue(k), pass == vtkHardwareSelector::CELL_ID_HIGH24);
        break;
      case vtkHardwareSelector::COMPOSITE_INDEX_PASS:
        if (compositeIds)
        {
          Write24(out, pos, compositeIds->GetValue(0), false); // one block per mapper
        }
        break;
      case vtkHardwareSelector::PROCESS_PASS:
        if (processIds)
        {
          Write24(out, pos,
            processIds->GetValue(drawn.PointSources[static_cast<std::size_t>(k)]) + 1, false);
        }
        break;
      default:
        break; // point ids: the patch is not drawn in point selection
    }
  }
  this->Superclass::ProcessSelectorPixelBuffers(sel, mesh, prop);
}
