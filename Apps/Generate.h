#ifndef Generate_h
#define Generate_h

#include <string>

namespace cli
{

enum class GeneratedShape
{
  Sphere,
  Torus
};

struct GenerateOptions
{
  GeneratedShape Shape = GeneratedShape::Sphere;
  std::string Output;
  int Level = 1;           ///< sphere: 20 * 4^level triangles
  int RingResolution = 24; ///< torus: samples around the ring
  int TubeResolution = 12; ///< torus: samples around the tube
  double Radius = 1.0;     ///< sphere radius, or the torus ring radius
  double TubeRadius = 0.4; ///< torus tube radius
};

/// `silhouette generate`: writes an analytic mesh with exact normals
/// (vtkIcosphereSource or vtkTorusSurfaceSource) to a .vtp or .ply file.
void RunGenerate(const GenerateOptions& options);

class ArgumentList;

/// The options of `silhouette generate ...` (the words after the command);
/// throws UsageError.
GenerateOptions ParseGenerate(ArgumentList& arguments);

} // namespace cli

#endif
