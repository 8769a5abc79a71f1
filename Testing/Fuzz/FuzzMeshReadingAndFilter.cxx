// libFuzzer target for mesh reading plus the VTK filter (issue 6, item 4).
//
// Input layout: byte 0 picks the format (.ply .obj .stl .vtp .vtk), the next
// ParameterBytes bytes pick the camera and the filter's settings, and the rest
// is the file. The file goes through cli::ReadMesh, the code path of the
// `silhouette` program: its pre-checks, VTK's reader in the reading process
// (a crash there is the program's clear error, as it must be) and the
// validation after it. A custom mutator adds mutations that know the formats;
// whatever reads is smoothed by vtkSilhouetteSmoothingFilter for a camera
// made from the parameter bytes: around the mesh or anywhere (eye inside or
// outside, on the focal point, any view-up), parallel or perspective, any
// viewport, then again for a second camera. The run must not crash or hang;
// when a request succeeds its outputs must hold only finite points and
// normals and in-range ids, and no valid input triangle may be lost.
//
// Seeds: scripts/fuzz.sh prefixes small meshes with a format byte and
// ParameterBytes bytes of 0x80 (a camera around the mesh).
#include "CliErrors.h"
#include "FuzzBytes.h"
#include "MeshIO.h"
#include "MeshValidation.h"
#include "VtkErrorLog.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSilhouetteSmoothingFilter.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <unistd.h>
#include <vector>

namespace
{

using fuzz::Bytes;

constexpr std::size_t ParameterBytes = 48; // two cameras and the settings, with room
const char* const Extensions[] = { ".ply", ".obj", ".stl", ".vtp", ".vtk" };
constexpr std::size_t FormatCount = sizeof(Extensions) / sizeof(Extensions[0]);

void require(bool condition, const char* what)
{
  if (!condition)
  {
    std::fprintf(stderr, "FuzzMeshReadingAndFilter: broken invariant: %s\n", what);
    std::abort();
  }
}

bool Finite(const double v[3])
{
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

// What the program asks of any mesh it reads (finite points, cell ids in
// range, one tuple per point or cell in each array), and finite normals.
void RequireValid(vtkPolyData* mesh)
{
  try
  {
    cli::RequireConsistentMesh(mesh, "the output");
  }
  catch (const cli::RuntimeError& error)
  {
    require(false, (std::string("a consistent output mesh: ") + error.what()).c_str());
  }
  if (vtkDataArray* normals = mesh->GetPointData()->GetNormals())
  {
    for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i)
    {
      double n[3];
      normals->GetTuple(i, n);
      require(Finite(n), "finite output normals");
    }
  }
}

// Triangles with three distinct ids, counting polygons fanned and strips split.
vtkIdType ValidTriangles(vtkPolyData* mesh)
{
  vtkIdType count = 0;
  auto polys = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  vtkIdType size = 0;
  const vtkIdType* ids = nullptr;
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    polys->GetCurrentCell(size, ids);
    if (size == 3 && ids[0] != ids[1] && ids[1] != ids[2] && ids[0] != ids[2])
    {
      ++count;
    }
  }
  return count;
}

// A camera from the parameter bytes: around the mesh's bounding sphere, or
// at any place and scale (which may be degenerate on purpose).
void MakeCamera(Bytes& bytes, vtkPolyData* mesh, vtkCamera* camera)
{
  const std::uint8_t mode = bytes.byte();
  double bounds[6];
  mesh->GetBounds(bounds);
  double center[3], radius = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    center[a] = 0.5 * (bounds[2 * a] + bounds[2 * a + 1]);
    radius = std::max(radius, 0.5 * (bounds[2 * a + 1] - bounds[2 * a]));
  }
  if (!(radius > 0.0) || !std::isfinite(radius))
  {
    radius = 1.0;
  }
  if (!Finite(center))
  {
    center[0] = center[1] = center[2] = 0.0;
  }
  double position[3], focal[3];
  if ((mode & 2) == 0)
  {
    // Around the mesh: a direction, a distance from 0.1 to 100 radii (the eye
    // may be inside), and a focal point near the centre.
    const double azimuth = 3.14159265358979 * bytes.unit();
    const double elevation = 1.5707963267949 * bytes.unit();
    const double distance = radius * std::pow(10.0, 3.0 * (bytes.byte() / 255.0) - 1.0);
    const double direction[3] = { std::cos(elevation) * std::cos(azimuth), std::sin(elevation),
      std::cos(elevation) * std::sin(azimuth) };
    for (int a = 0; a < 3; ++a)
    {
      focal[a] = center[a] + 0.2 * radius * bytes.unit();
      position[a] = focal[a] + distance * direction[a];
    }
  }
  else
  {
    // Anywhere, at scales from 1e-30 to 1e30; the eye may sit on the focal point.
    const double scale = std::pow(10.0, static_cast<int>(bytes.byte() % 61) - 30);
    for (int a = 0; a < 3; ++a)
    {
      position[a] = scale * bytes.unit();
    }
    for (int a = 0; a < 3; ++a)
    {
      focal[a] = (mode & 4) ? position[a] : scale * bytes.unit();
    }
  }
  camera->SetPosition(position);
  camera->SetFocalPoint(focal);
  // Any view-up, possibly zero or along the view direction.
  const double up[3] = { bytes.unit(), bytes.unit(), bytes.unit() };
  camera->SetViewUp(up[0], up[1], up[2]);
  camera->SetViewAngle(1.0 + bytes.byte() % 179);
  camera->SetParallelProjection(mode & 1);
  camera->SetParallelScale(radius * std::pow(10.0, 2.0 * (bytes.byte() / 255.0) - 1.0));
}

// The file: one per process, in the temporary directory.
std::string InputPath(std::size_t format)
{
  static const std::string stem = [] {
    const char* tmp = std::getenv("TMPDIR");
    return std::string(tmp && *tmp ? tmp : "/tmp") + "/silhouette-fuzz-" +
      std::to_string(static_cast<long>(getpid()));
  }();
  return stem + Extensions[format];
}

// ---------------------------------------------- structure-aware mutations
// libFuzzer's byte-level mutations rarely produce what trips the readers:
// a reordered PLY header, a blank body line, an extra list property, the
// other quoting style, an extreme count or offset, another data mode, cut
// appended data. One input in three gets one of these instead (issue 14).

using Random = std::minstd_rand;

std::size_t Pick(Random& random, std::size_t n)
{
  return n == 0 ? 0 : static_cast<std::size_t>(random() % n);
}

std::vector<std::string> SplitLines(const std::string& text)
{
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start <= text.size())
  {
    const std::size_t end = text.find('\n', start);
    lines.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos)
    {
      break;
    }
    start = end + 1;
  }
  return lines;
}

std::string JoinLines(const std::vector<std::string>& lines)
{
  std::string text;
  for (std::size_t i = 0; i < lines.size(); ++i)
  {
    text += lines[i];
    if (i + 1 < lines.size())
    {
      text += '\n';
    }
  }
  return text;
}

const char* const ExtremeNumbers[] = { "-1", "0", "1", "2147483647", "2147483648", "3000000000",
  "4294967295", "2000000000", "18446744073709551615", "1e2", "0x10", "+", "nan", "1e39" };

// Replaces the number after one occurrence of `key` by an extreme one.
void ReplaceNumberAfter(std::string& text, const std::string& key, Random& random)
{
  std::vector<std::size_t> places;
  for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + 1))
  {
    places.push_back(at + key.size());
  }
  if (places.empty())
  {
    return;
  }
  std::size_t begin = places[Pick(random, places.size())];
  while (begin < text.size() && (text[begin] == ' ' || text[begin] == '"' || text[begin] == '\''))
  {
    ++begin;
  }
  std::size_t end = begin;
  while (end < text.size() &&
    (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '-' || text[end] == '+' ||
      text[end] == '.'))
  {
    ++end;
  }
  text.replace(begin, end - begin, ExtremeNumbers[Pick(random, std::size(ExtremeNumbers))]);
}

void MutatePly(std::string& file, Random& random)
{
  std::vector<std::string> lines = SplitLines(file);
  std::size_t header = 0;
  while (header < lines.size() && lines[header].rfind("end_header", 0) != 0)
  {
    ++header;
  }
  std::vector<std::size_t> elements;
  for (std::size_t i = 0; i < header; ++i)
  {
    if (lines[i].rfind("element ", 0) == 0)
    {
      elements.push_back(i);
    }
  }
  switch (Pick(random, 4))
  {
    case 0: // swap the first two elements' header blocks (not their data)
      if (elements.size() >= 2)
      {
        const std::vector<std::string> first(
          lines.begin() + static_cast<std::ptrdiff_t>(elements[0]),
          lines.begin() + static_cast<std::ptrdiff_t>(elements[1]));
        const std::size_t secondEnd = elements.size() > 2 ? elements[2] : header;
        std::vector<std::string> swapped(lines.begin() + static_cast<std::ptrdiff_t>(elements[1]),
          lines.begin() + static_cast<std::ptrdiff_t>(secondEnd));
        swapped.insert(swapped.end(), first.begin(), first.end());
        std::copy(
          swapped.begin(), swapped.end(), lines.begin() + static_cast<std::ptrdiff_t>(elements[0]));
      }
      break;
    case 1: // a blank line somewhere in the body
      if (header + 1 < lines.size())
      {
        lines.insert(lines.begin() +
            static_cast<std::ptrdiff_t>(header + 1 + Pick(random, lines.size() - header - 1)),
          Pick(random, 2) ? "" : " \r");
      }
      break;
    case 2: // an extra list property on some element
      if (!elements.empty())
      {
        lines.insert(
          lines.begin() + static_cast<std::ptrdiff_t>(elements[Pick(random, elements.size())] + 1),
          Pick(random, 2) ? "property list uchar float texcoord" : "property list int int extra");
      }
      break;
    default: // an extreme count or index
      file = JoinLines(lines);
      ReplaceNumberAfter(file, Pick(random, 2) ? "element vertex" : "element face", random);
      return;
  }
  file = JoinLines(lines);
}

void MutateVtp(std::string& file, Random& random)
{
  switch (Pick(random, 6))
  {
    case 0: // the other quoting style, throughout
      std::replace(file.begin(), file.end(), '"', '\'');
      break;
    case 1:
    {
      const char* const keys[] = { "NumberOfPoints=", "NumberOfComponents=", "NumberOfTuples=",
        "NumberOfPolys=", "NumberOfVerts=", "offset=", "RangeMax=" };
      ReplaceNumberAfter(file, keys[Pick(random, std::size(keys))], random);
      break;
    }
    case 2: // another data mode for one array
    {
      const std::size_t at = file.find("format=", Pick(random, file.size()));
      const char* const modes[] = { "\"ascii\"", "\"binary\"", "\"appended\"" };
      if (at != std::string::npos && at + 8 < file.size())
      {
        const std::size_t end = file.find_first_of("\"'", at + 8);
        if (end != std::string::npos)
        {
          file.replace(at + 7, end + 1 - (at + 7), modes[Pick(random, 3)]);
        }
      }
      break;
    }
    case 3: // the other header type, or compression added or removed
      if (file.find("UInt32") != std::string::npos && Pick(random, 2))
      {
        file.replace(file.find("UInt32"), 6, "UInt64");
      }
      else if (file.find(" compressor=") == std::string::npos)
      {
        const std::size_t at = file.find("<VTKFile ");
        if (at != std::string::npos)
        {
          file.insert(at + 9, "compressor=\"vtkZLibDataCompressor\" ");
        }
      }
      break;
    case 4: // appended data cut short by a few bytes
    {
      const std::size_t end = file.rfind("</AppendedData>");
      const std::size_t cut = 1 + Pick(random, 16);
      if (end != std::string::npos && end > cut + 1)
      {
        file.erase(end - 1 - cut, cut);
      }
      break;
    }
    default: // one array's element repeated
    {
      const std::size_t begin = file.find("<DataArray", Pick(random, file.size()));
      const std::size_t end = begin == std::string::npos ? begin : file.find("</DataArray>", begin);
      if (end != std::string::npos)
      {
        file.insert(begin, file.substr(begin, end + 12 - begin));
      }
      break;
    }
  }
}

void MutateLegacyOrObj(std::string& file, Random& random, bool legacy)
{
  if (legacy)
  {
    const char* const keys[] = { "POINTS ", "POLYGONS ", "VERTICES ", "LINES ", "POINT_DATA ",
      "TRIANGLE_STRIPS ", "\n3 " };
    ReplaceNumberAfter(file, keys[Pick(random, std::size(keys))], random);
    return;
  }
  const char* const keys[] = { "v ", "f ", "vt ", "vn ", "/" };
  ReplaceNumberAfter(file, keys[Pick(random, std::size(keys))], random);
}

void MutateStl(std::string& file, Random& random)
{
  if (file.size() >= 84 && file.rfind("solid", 0) != 0)
  {
    const std::uint32_t counts[] = { 0, 1, 0x7fffffffu, 0xffffffffu, 100000000u };
    const std::uint32_t count = counts[Pick(random, std::size(counts))];
    std::memcpy(&file[80], &count, sizeof(count));
    return;
  }
  ReplaceNumberAfter(file, Pick(random, 2) ? "vertex " : "normal ", random);
}

} // namespace

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t maxSize);

extern "C" std::size_t LLVMFuzzerCustomMutator(
  std::uint8_t* data, std::size_t size, std::size_t maxSize, unsigned int seed)
{
  Random random(seed);
  const std::size_t prefix = 1 + ParameterBytes;
  if (size <= prefix || Pick(random, 3) != 0)
  {
    return LLVMFuzzerMutate(data, size, maxSize);
  }
  std::string file(reinterpret_cast<const char*>(data + prefix), size - prefix);
  switch (data[0] % FormatCount)
  {
    case 0:
      MutatePly(file, random);
      break;
    case 1:
      MutateLegacyOrObj(file, random, false);
      break;
    case 2:
      MutateStl(file, random);
      break;
    case 3:
      MutateVtp(file, random);
      break;
    default:
      MutateLegacyOrObj(file, random, true);
      break;
  }
  if (prefix + file.size() > maxSize)
  {
    return LLVMFuzzerMutate(data, size, maxSize);
  }
  std::memcpy(data + prefix, file.data(), file.size());
  return prefix + file.size();
}

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  // VTK's messages go to the program's log instead of the terminal.
  cli::VtkErrorLog::Instance().InstallMessageCapture();
  vtkSMPTools::Initialize(1); // one thread: the fuzzer runs many inputs, not big ones
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if (size < 1 + ParameterBytes)
  {
    return 0;
  }
  const std::size_t format = data[0] % FormatCount;
  Bytes parameters(data + 1, ParameterBytes);
  const std::string path = InputPath(format);
  {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file.write(reinterpret_cast<const char*>(data + 1 + ParameterBytes),
      static_cast<std::streamsize>(size - 1 - ParameterBytes));
    require(static_cast<bool>(file), "the input file is written");
  }

  vtkSmartPointer<vtkPolyData> mesh;
  try
  {
    mesh = cli::ReadMesh(path);
  }
  catch (const cli::RuntimeError& error)
  {
    std::remove(path.c_str());
    // A reader that computes forever runs out of processor time first; the
    // waiting limit only ends a reading process that waits for nothing: the
    // deadlock of a forked copy that read in place (found here, and why the
    // reading process is a program of its own).
    require(std::string(error.what()).find("reading took longer than") == std::string::npos,
      "the reading process does not hang");
    return 0; // a clear error: what the program does with a bad file
  }
  std::remove(path.c_str());
  require(mesh != nullptr, "ReadMesh gives a mesh or throws");

  vtkNew<vtkCamera> camera;
  MakeCamera(parameters, mesh, camera);
  vtkNew<vtkSilhouetteSmoothingFilter> filter;
  cli::VtkErrorLog& errors = cli::VtkErrorLog::Instance();
  errors.Clear();
  errors.Watch(filter);
  filter->SetInputData(mesh);
  filter->SetCamera(camera);
  filter->SetViewportSize(parameters.byte() * 8, parameters.byte() * 8);
  filter->SetTolerance(0.05 + parameters.byte() / 50.0);
  filter->SetPerturbVertices(parameters.byte() % 2 == 0);
  filter->SetSamplingRule(parameters.byte() % 2);
  filter->Update();
  if (errors.HasErrors())
  {
    return 0; // the request failed with an error, as documented for bad input
  }
  RequireValid(filter->GetOutput());
  RequireValid(filter->GetSilhouetteOutput());
  require(
    ValidTriangles(filter->GetOutput()) >= ValidTriangles(mesh), "no valid input triangle is lost");

  // Move the camera and run again: the prepared cache must serve any view.
  MakeCamera(parameters, mesh, camera);
  errors.Clear();
  filter->Update();
  if (!errors.HasErrors())
  {
    RequireValid(filter->GetOutput());
    RequireValid(filter->GetSilhouetteOutput());
  }
  return 0;
}
