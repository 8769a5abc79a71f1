#ifndef Compare_h
#define Compare_h

#include "RenderingBackend.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <array>
#include <string>
#include <vector>

namespace cli
{

enum class CompareFormat
{
  Text,
  Json,
  Markdown
};

struct CompareOptions
{
  /// Model names of the set, "all", or mesh files.
  std::vector<std::string> Inputs;
  int CoarseTriangles = 0; ///< 0: the model's default (1,000 for a file)
  int FineLevel = 3;
  int Views = 12;
  int Frames = 30;
  std::array<int, 2> ViewportSize{ 1024, 768 };
  double Tolerance = 0.5;
  CompareFormat Format = CompareFormat::Text;
  std::string DataDirectory; ///< where bunny.ply is; empty: the built-in default
  /// Measure against the truth instead (docs/fidelity.md): mesh files only.
  bool Truth = false;
  /// With Truth: the coarse points on the reference instead of the original
  /// (`--coarse-points reference`).
  bool CoarsePointsOnReference = false;
};

/// `silhouette compare`: coarse, coarse + smoothing and the fine reference of
/// each input, measured from the same cameras (see CompareHelp).
void RunCompare(const CompareOptions& options);

/// The original of `input` for `compare` and `figure` (`command`): a model
/// of the set (silhouette_eval::MakeOriginal), or a mesh file with its
/// points merged where they share a position (silhouette_eval::
/// WeldedTriangles; a line on standard error says how many went). Sets
/// `coarseTriangles`, when 0, to the input's default (1,000 for a file).
/// Refuses a name that is neither a model nor a file in one line
/// (RequireModelOrFile, ModelInput.h).
vtkSmartPointer<vtkPolyData> OriginalOf(const std::string& input, const std::string& dataDirectory,
  const std::string& command, int& coarseTriangles);

/// What the progress line says of the coarse version of `original` at
/// `coarseTriangles`: "decimating to N triangles", or, where the original
/// has no more than that, "keeping its N triangles" (Decimate keeps it).
std::string CoarseVersionText(vtkPolyData* original, int coarseTriangles);

/// `silhouette compare --truth`: each mesh file's coarse version, smoothed
/// (own and carried normals) and by the peers, against the original refined
/// by Butterfly subdivision and against the original (FidelityEvaluation.h).
void RunCompareTruth(const CompareOptions& options);

std::string CompareHelp();

class ArgumentList;

/// The options of `silhouette compare ...`, and its --backend into
/// `backend`; throws UsageError.
CompareOptions ParseCompare(ArgumentList& arguments, RenderBackend& backend);

} // namespace cli

#endif
