// Reading files (Apps/IO/MeshIO.h) where VTK 9.1's readers would give another
// mesh than the file holds.
#include "MeshIO.h"

#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPLYReader.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace
{

using Corner = std::array<double, 3>;

// A tetrahedron whose faces give texture coordinates per corner (a
// `texcoord` list, as MeshLab writes), each face the same three: a point
// then needs another coordinate in another face while another point already
// has it.
const std::vector<Corner> TetrahedronPoints = { { { 0, 0, 0 } }, { { 1, 0, 0 } }, { { 0, 1, 0 } },
  { { 0, 0, 1 } } };
const std::vector<std::array<int, 3>> TetrahedronFaces = { { { 0, 2, 1 } }, { { 0, 1, 3 } },
  { { 0, 3, 2 } }, { { 1, 2, 3 } } };

std::string WriteTetrahedronWithFaceTextures()
{
  const std::string path = ::testing::TempDir() + "tetrahedron_face_texcoord.ply";
  std::ofstream file(path);
  file << "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
          "property float z\nelement face 4\nproperty list uchar int vertex_indices\n"
          "property list uchar float texcoord\nend_header\n";
  for (const Corner& p : TetrahedronPoints)
  {
    file << p[0] << " " << p[1] << " " << p[2] << "\n";
  }
  for (const auto& f : TetrahedronFaces)
  {
    file << "3 " << f[0] << " " << f[1] << " " << f[2] << " 6 0 0 1 0 0 1\n";
  }
  return path;
}

// Each face's corners as positions, in order.
std::vector<std::array<Corner, 3>> FacesOf(vtkPolyData* mesh)
{
  std::vector<std::array<Corner, 3>> faces;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < mesh->GetPolys()->GetNumberOfCells(); ++c)
  {
    mesh->GetCellPoints(mesh->GetNumberOfVerts() + mesh->GetNumberOfLines() + c, ids);
    std::array<Corner, 3> face{};
    for (int k = 0; k < 3 && k < ids->GetNumberOfIds(); ++k)
    {
      mesh->GetPoint(ids->GetId(k), face[static_cast<std::size_t>(k)].data());
    }
    faces.push_back(face);
  }
  return faces;
}

std::vector<std::array<Corner, 3>> FileFaces()
{
  std::vector<std::array<Corner, 3>> faces;
  for (const auto& f : TetrahedronFaces)
  {
    faces.push_back({ TetrahedronPoints[static_cast<std::size_t>(f[0])],
      TetrahedronPoints[static_cast<std::size_t>(f[1])],
      TetrahedronPoints[static_cast<std::size_t>(f[2])] });
  }
  return faces;
}

} // namespace

TEST(MeshReading, PlyFaceTextureCoordinatesLeaveEveryFaceItsOwnPoints)
{
  const std::string path = WriteTetrahedronWithFaceTextures();
  const vtkSmartPointer<vtkPolyData> mesh = cli::ReadMesh(path);
  ASSERT_NE(mesh, nullptr);
  EXPECT_EQ(FacesOf(mesh), FileFaces());
  EXPECT_NE(mesh->GetPointData()->GetTCoords(), nullptr);

  // Why: vtkPLYReader 9.1 as it comes, splitting points for the face
  // texture coordinates, gives faces points of other faces.
  vtkNew<vtkPLYReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  EXPECT_NE(FacesOf(reader->GetOutput()), FileFaces());
  std::remove(path.c_str());
}
