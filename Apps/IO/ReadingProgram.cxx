// silhouette-read: the reading process of ReadMesh (SandboxedReading.h).
// Started by the program for each mesh file it reads, never by hand: it
// reads one file with VTK's reader and sends the mesh back on its standard
// output.
#include "MeshIO.h"
#include "SandboxedReading.h"

#include <vtkPolyData.h>

int main(int argc, char** argv)
{
  return cli::ReadingProcessMain(argc, argv, cli::ReadMeshInThisProcess);
}
