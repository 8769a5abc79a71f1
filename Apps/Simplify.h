#ifndef Simplify_h
#define Simplify_h

#include "ArgumentList.h"
#include "CameraOptions.h"

#include <string>

namespace cli
{

/// `silhouette simplify`: silhouette-aware quadric simplification (Mata et
/// al.) of a mesh to a triangle count, for the view of the camera options.
struct SimplifyOptions
{
  std::string Input;
  std::string Output;
  bool Json = false;
  CameraOptions Camera;
  long long Triangles = 0; ///< required; at least 4
  int Grid = 128;          ///< proximity grid cells along the longer side
  double NearMinimum = 1.0;
  double NearMaximum = 3.0;
  double NearFactor = 0.1;
  bool Plain = false;   ///< no proximity: plain quadric simplification
  bool Measure = false; ///< render input and output masks, print the outline deviation
  bool Weld = false;    ///< join points at equal coordinates first
};

/// The help text of `simplify`.
std::string SimplifyHelp();

/// Consumes `option` if it is one of simplify's own; false if not. Throws
/// UsageError for bad values.
bool ParseSimplifyOption(const Option& option, ArgumentList& arguments, SimplifyOptions& options);

/// Checks after parsing (the required options); throws UsageError.
void CheckSimplifyOptions(const SimplifyOptions& options);

void RunSimplify(const SimplifyOptions& options);

} // namespace cli

#endif
