// silhouette-read: the reading process of ReadMesh (SandboxedReading.h).
// Started by the program for each mesh file it reads, never by hand: it
// reads one file with VTK's reader and sends the mesh back on its standard
// output.
#include "MeshIO.h"
#include "SandboxedReading.h"

#include <vtkPolyData.h>

#include <unistd.h>

int main(int argc, char** argv)
{
  // _exit: the answer is sent; VTK's static destructors, and under a
  // sanitizer its leak check, would only add to every read's time (about
  // 20 of 155 ms in the fuzz build).
  ::_exit(cli::ReadingProcessMain(argc, argv, cli::ReadMeshInThisProcess));
}
