#include "Smoothing.h"

#include "CameraOptions.h"
#include "CliErrors.h"
#include "PrintableText.h"
#include "VtkErrorLog.h"

#include <vtkPolyData.h>
#include <vtkSilhouetteSmoothingFilter.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <iostream>
#include <utility>
#include <vector>

namespace cli
{

SmoothingRun SmoothSilhouette(vtkPolyData* mesh, vtkCamera* camera, const CameraOptions& options)
{
  VtkErrorLog& errors = VtkErrorLog::Instance();
  SmoothingRun run;
  run.Filter = vtkSmartPointer<vtkSilhouetteSmoothingFilter>::New();
  vtkSilhouetteSmoothingFilter* filter = run.Filter;
  errors.Watch(filter);
  filter->SetInputData(mesh);
  // The camera and viewport before the first update, as the renderer will use them.
  filter->SetCamera(camera);
  filter->SetViewportSize(options.ViewportSize[0], options.ViewportSize[1]);
  ApplySmoothingOptions(filter, options);

  auto timedUpdate = [&]() {
    errors.Clear();
    const auto start = std::chrono::steady_clock::now();
    filter->Update();
    const auto stop = std::chrono::steady_clock::now();
    errors.ThrowIfErrors("smoothing failed");
    return std::chrono::duration<double, std::milli>(stop - start).count();
  };
  run.PrepareMilliseconds = timedUpdate();
  // The filter warns once, when it prepares the input.
  run.Warnings = errors.Warnings();
  std::vector<double> milliseconds;
  for (int i = 0; i < TimedFilterRuns; ++i)
  {
    filter->Modified(); // re-run the frame; the input is unchanged, so the cache stays
    milliseconds.push_back(timedUpdate());
  }
  std::nth_element(
    milliseconds.begin(), milliseconds.begin() + milliseconds.size() / 2, milliseconds.end());
  run.MedianMilliseconds = milliseconds[milliseconds.size() / 2];
  return run;
}

void ApplySmoothingOptions(vtkSilhouetteSmoothingFilter* filter, const CameraOptions& options)
{
  filter->SetTolerance(options.Tolerance);
  filter->SetFeatureEdgeDetection(options.FeatureAngle.has_value());
  if (options.FeatureAngle)
  {
    filter->SetFeatureAngle(*options.FeatureAngle);
  }
  filter->SetFeatureLines(options.FeatureLines);
  filter->SetPerturbVertices(options.PerturbVertices);
  filter->SetFoldPrevention(options.FoldPrevention);
  filter->SetKeepApexesPointed(options.KeepApexesPointed);
  filter->SetWeldCoincidentPoints(options.Weld);
  filter->SetWeldTolerance(options.WeldTolerance);
  filter->SetConsistentOrientation(options.Orient);
  filter->SetNormalSeamFeatures(options.NormalSeams);
  filter->SetFlatCreaseDetection(options.FlatCreases);
  if (options.FlatCreaseAngle)
  {
    filter->SetFlatCreaseAngle(*options.FlatCreaseAngle);
  }
  filter->SetNormalEstimation(options.NormalEstimation);
  if (options.DoublePrecision)
  {
    filter->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  }
}

namespace
{

// A filter warning in the program's words: the filter's settings it names
// become the options that set them.
std::string InTheProgramsWords(std::string warning)
{
  static const std::pair<const char*, const char*> options[] = {
    { "WeldTolerance", "--weld-tolerance" },
    { "FlatCreaseDetection", "--flat-crease-angle" },
    { "FeatureEdgeDetection", "--feature-angle" },
  };
  for (const auto& [setting, option] : options)
  {
    for (std::size_t at = warning.find(setting); at != std::string::npos;
         at = warning.find(setting, at + std::strlen(option)))
    {
      warning.replace(at, std::strlen(setting), option);
    }
  }
  return warning;
}

} // namespace

void PrintFilterWarning(const std::string& warning)
{
  std::cerr << "silhouette: warning: " << PrintableText(InTheProgramsWords(warning)) << "\n";
}

} // namespace cli
