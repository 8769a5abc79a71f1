#ifndef MeshIO_h
#define MeshIO_h

#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <string>
#include <vector>

class vtkAlgorithm;
class vtkPolyData;

namespace cli
{

class FileBatch;

/// The extension of `path` in lower case, with its dot ("" if none).
std::string LowercaseExtension(const std::string& path);

/// VTK's reader for the extension of `path` (.ply .obj .stl .vtp .vtk), set
/// to read it, with none of ReadMesh's checks; null for another extension.
vtkSmartPointer<vtkAlgorithm> NewVtkReader(const std::string& path);

/**
 * Reads a mesh with the reader its extension picks (.ply .obj .stl .vtp .vtk).
 * Throws RuntimeError with one line for a missing or unreadable file, an
 * unknown extension, a legacy .vtk file that is not POLYDATA, and any error
 * VTK reports while reading.
 */
vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path);

/// What the reading process (silhouette-read) runs: ReadMesh's pre-check,
/// VTK's reader and the checks after it, in this process, with no limits.
/// Only for that process: VTK 9.1's readers crash and loop on hostile files.
vtkSmartPointer<vtkPolyData> ReadMeshInThisProcess(const std::string& path);

/// The triangles the filter will see: polygons fanned, strips split.
vtkIdType CountTriangles(vtkPolyData* mesh);

/// Throws RuntimeError unless the directory `path` goes into exists (VTK's
/// writers only say they could not open the file).
void RequireOutputDirectory(const std::string& path);

/// Throws UsageError when `output` (given with `option`, "-o") is the file
/// `input`: both exist and std::filesystem::equivalent says so (./a.ply and
/// a.ply, a link and its target). A job must not overwrite what it reads.
void RefuseOverwritingInput(
  const std::string& input, const std::string& output, const std::string& option);

/// Throws UsageError unless WriteMesh can write `path` (.vtp or .ply);
/// called before the work so a typo costs nothing.
void CheckMeshOutputPath(const std::string& path);

/// Writes .vtp (XML, binary, zlib: everything) or .ply (binary little-endian:
/// the points in their own precision, the polygons, and the active normals,
/// texture coordinates and unsigned-char colours as nx ny nz, u v and red
/// green blue [alpha], which vtkPLYReader reads back). Returns what the file
/// could not keep (the names of the other arrays, and "line cells" or
/// "vertex cells"), empty for .vtp. Throws RuntimeError on failure. With a
/// `batch`, the file is added to it (written when the batch is committed).
std::vector<std::string> WriteMesh(
  vtkPolyData* mesh, const std::string& path, FileBatch* batch = nullptr);

/// Throws UsageError unless WriteLines can write `path` (.vtp).
void CheckLinesOutputPath(const std::string& path);

/// Writes polylines (the filter's silhouette output) to .vtp (or adds them to
/// `batch`).
void WriteLines(vtkPolyData* lines, const std::string& path, FileBatch* batch = nullptr);

} // namespace cli

#endif
