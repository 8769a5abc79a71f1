#include "Compare.h"

#include "ArgumentList.h"
#include "CameraOptions.h"
#include "CliErrors.h"
#include "DataFolder.h"
#include "Figures.h"
#include "MeshIO.h"
#include "ModelInput.h"
#include "PrintableText.h"
#include "RenderingBackend.h"
#include "TextFormat.h"
#include "VtkErrorLog.h"

#include "EvaluationModels.h"
#include "SilhouetteComparison.h"

#include <vtkPolyData.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace cli
{
namespace
{

// A ratio to the fine reference's figure, or `nothing` where that figure is
// 0 (the fine outline did not move: the ratio is undefined, stored as -1).
std::string RatioOrNothing(double ratio, int digits, const char* nothing)
{
  return ratio < 0.0 ? std::string(nothing) : Fixed(ratio, digits);
}

using silhouette_eval::ModelComparison;
using silhouette_eval::VariantFigures;

// The issue's targets: smoothing removes at least two thirds of the coarse
// outline's deviation from the fine reference, and a whole frame costs at
// most a third of rendering the fine mesh.
constexpr double TargetRatio = 1.0 / 3.0;

double DeviationRatio(const ModelComparison& c)
{
  return c.Coarse.MeanDeviation > 0 ? c.Smoothed.MeanDeviation / c.Coarse.MeanDeviation : 0.0;
}

double FrameRatio(const ModelComparison& c)
{
  return c.Fine.FrameMilliseconds > 0 ? c.Smoothed.FrameMilliseconds / c.Fine.FrameMilliseconds
                                      : 0.0;
}

std::string JsonVariant(const VariantFigures& v)
{
  std::ostringstream s;
  s << "{\"triangles\": " << Fixed(v.Triangles, 0)
    << ", \"deviation_mean_px\": " << Fixed(v.MeanDeviation, 3)
    << ", \"deviation_max_px\": " << Fixed(v.MaxDeviation, 3);
  if (v.MeanExact >= 0)
  {
    s << ", \"exact_mean_px\": " << Fixed(v.MeanExact, 3)
      << ", \"exact_max_px\": " << Fixed(v.MaxExact, 3);
  }
  s << ", \"filter_ms\": " << Fixed(v.FilterMilliseconds, 3)
    << ", \"frame_ms\": " << Fixed(v.FrameMilliseconds, 3);
  if (v.CoherenceMean >= 0)
  {
    s << ", \"coherence_mean_px\": " << Fixed(v.CoherenceMean, 3)
      << ", \"coherence_max_px\": " << Fixed(v.CoherenceMax, 3)
      << ", \"coherence_ratio_to_fine\": " << RatioOrNothing(v.CoherenceRatio, 3, "null")
      << ", \"coherence_excess_px\": " << Fixed(v.CoherenceExcess, 3);
  }
  s << "}";
  return s.str();
}

void PrintText(const ModelComparison& c, const CompareOptions& options)
{
  std::cout << "model " << c.Name << ": " << c.Description << "\n";
  std::cout << "  " << options.Views << " views and " << options.Frames << " timed frames at "
            << options.ViewportSize[0] << "x" << options.ViewportSize[1] << ", tolerance "
            << options.Tolerance << " px; deviations are outline distances in pixels\n";
  const bool exact = c.Coarse.MeanExact >= 0;
  std::printf("  %-18s %10s %10s %10s %10s %10s %10s %10s\n", "variant", "triangles", "dev mean",
    "dev max", exact ? "exact mean" : "", exact ? "exact max" : "", "filter ms", "frame ms");
  auto row = [&](const char* name, const VariantFigures& v, bool smoothing) {
    std::printf("  %-18s %10.0f %10.3f %10.3f %10s %10s %10s %10.2f\n", name, v.Triangles,
      v.MeanDeviation, v.MaxDeviation, exact ? Fixed(v.MeanExact, 3).c_str() : "",
      exact ? Fixed(v.MaxExact, 3).c_str() : "",
      smoothing ? Fixed(v.FilterMilliseconds, 3).c_str() : "-", v.FrameMilliseconds);
  };
  row("coarse", c.Coarse, false);
  row("coarse+smoothing", c.Smoothed, true);
  row("wang 2003", c.Wang2003, true);
  row(("PN triangles k=" + std::to_string(c.PNLevel)).c_str(), c.PN, true);
  row(("fine (Loop " + std::to_string(options.FineLevel) + ")").c_str(), c.Fine, false);
  std::cout << "  (PN triangles: the level k >= 1 whose count is nearest coarse+smoothing's; its "
               "filter ms is the one-off tessellation)\n";
  if (c.Fine.CoherenceMean >= 0)
  {
    std::cout << "  coherence over " << options.Frames
              << " 1-degree steps, outline change per step (px): mean, largest, mean over fine's, "
                 "largest excess over fine's in the same step:\n";
    auto coherence = [](const char* name, const VariantFigures& v) {
      std::printf("  %-18s %10.3f %10.3f %10s %10.3f\n", name, v.CoherenceMean, v.CoherenceMax,
        RatioOrNothing(v.CoherenceRatio, 2, "-").c_str(), v.CoherenceExcess);
    };
    coherence("coarse", c.Coarse);
    coherence("coarse+smoothing", c.Smoothed);
    coherence("wang 2003", c.Wang2003);
    coherence("PN triangles", c.PN);
    coherence("fine", c.Fine);
  }
  std::cout << "  deviation, smoothed / coarse: " << Fixed(DeviationRatio(c), 2)
            << " (target <= 0.33: " << (DeviationRatio(c) <= TargetRatio ? "met" : "MISSED")
            << ")\n"
            << "  frame time, smoothed / fine:  " << Fixed(FrameRatio(c), 2)
            << " (target <= 0.33: " << (FrameRatio(c) <= TargetRatio ? "met" : "MISSED") << ")\n";
}

void PrintMarkdown(const std::vector<ModelComparison>& results, const CompareOptions& options)
{
  std::cout << "| model | triangles coarse / smoothed / fine | deviation from fine, coarse: mean / "
               "max px | smoothed: mean / max px | smoothed / coarse | frame ms smoothed / fine | "
               "smoothed / fine | filter ms |\n"
               "|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const ModelComparison& c : results)
  {
    std::cout << "| " << c.Name << " | " << Fixed(c.Coarse.Triangles, 0) << " / "
              << Fixed(c.Smoothed.Triangles, 0) << " / " << Fixed(c.Fine.Triangles, 0) << " | "
              << Fixed(c.Coarse.MeanDeviation, 2) << " / " << Fixed(c.Coarse.MaxDeviation, 1)
              << " | " << Fixed(c.Smoothed.MeanDeviation, 2) << " / "
              << Fixed(c.Smoothed.MaxDeviation, 1) << " | " << Fixed(DeviationRatio(c), 2)
              << (DeviationRatio(c) <= TargetRatio ? "" : " (missed)") << " | "
              << Fixed(c.Smoothed.FrameMilliseconds, 1) << " / "
              << Fixed(c.Fine.FrameMilliseconds, 1) << " | " << Fixed(FrameRatio(c), 2)
              << (FrameRatio(c) <= TargetRatio ? "" : " (missed)") << " | "
              << Fixed(c.Smoothed.FilterMilliseconds, 2) << " |\n";
  }
  bool anyExact = false;
  for (const ModelComparison& c : results)
  {
    anyExact = anyExact || c.Coarse.MeanExact >= 0;
  }
  if (anyExact)
  {
    std::cout << "\n| model | distance to the exact silhouette, mean / max px: coarse | smoothed | "
                 "fine |\n|---|---:|---:|---:|\n";
    for (const ModelComparison& c : results)
    {
      if (c.Coarse.MeanExact >= 0)
      {
        std::cout << "| " << c.Name << " | " << Fixed(c.Coarse.MeanExact, 2) << " / "
                  << Fixed(c.Coarse.MaxExact, 1) << " | " << Fixed(c.Smoothed.MeanExact, 2) << " / "
                  << Fixed(c.Smoothed.MaxExact, 1) << " | " << Fixed(c.Fine.MeanExact, 2) << " / "
                  << Fixed(c.Fine.MaxExact, 1) << " |\n";
      }
    }
  }
  std::cout
    << "\n| model | triangles: ours / Wang 2003 / PN (k) | deviation from fine, mean / max px: "
       "ours | Wang 2003 | PN | frame ms: ours / Wang 2003 / PN | filter ms: ours / Wang "
       "2003 / PN (once) |\n|---|---:|---:|---:|---:|---:|---:|\n";
  for (const ModelComparison& c : results)
  {
    std::cout << "| " << c.Name << " | " << Fixed(c.Smoothed.Triangles, 0) << " / "
              << Fixed(c.Wang2003.Triangles, 0) << " / " << Fixed(c.PN.Triangles, 0) << " ("
              << c.PNLevel << ") | " << Fixed(c.Smoothed.MeanDeviation, 2) << " / "
              << Fixed(c.Smoothed.MaxDeviation, 1) << " | " << Fixed(c.Wang2003.MeanDeviation, 2)
              << " / " << Fixed(c.Wang2003.MaxDeviation, 1) << " | " << Fixed(c.PN.MeanDeviation, 2)
              << " / " << Fixed(c.PN.MaxDeviation, 1) << " | "
              << Fixed(c.Smoothed.FrameMilliseconds, 1) << " / "
              << Fixed(c.Wang2003.FrameMilliseconds, 1) << " / " << Fixed(c.PN.FrameMilliseconds, 1)
              << " | " << Fixed(c.Smoothed.FilterMilliseconds, 2) << " / "
              << Fixed(c.Wang2003.FilterMilliseconds, 2) << " / "
              << Fixed(c.PN.FilterMilliseconds, 2) << " |\n";
  }
  if (anyExact)
  {
    std::cout << "\n| model | distance to the exact silhouette, mean / max px: ours | Wang 2003 | "
                 "PN |\n|---|---:|---:|---:|\n";
    for (const ModelComparison& c : results)
    {
      if (c.Coarse.MeanExact >= 0)
      {
        std::cout << "| " << c.Name << " | " << Fixed(c.Smoothed.MeanExact, 2) << " / "
                  << Fixed(c.Smoothed.MaxExact, 1) << " | " << Fixed(c.Wang2003.MeanExact, 2)
                  << " / " << Fixed(c.Wang2003.MaxExact, 1) << " | " << Fixed(c.PN.MeanExact, 2)
                  << " / " << Fixed(c.PN.MaxExact, 1) << " |\n";
      }
    }
  }
  bool anyCoherence = false;
  for (const ModelComparison& c : results)
  {
    anyCoherence = anyCoherence || c.Fine.CoherenceMean >= 0;
  }
  if (anyCoherence)
  {
    std::cout << "\n| model | outline change per 1-degree step, mean / largest px: coarse | ours | "
                 "Wang 2003 | PN | fine | mean over fine's: ours | Wang 2003 | PN | largest excess "
                 "over fine's step, px: ours | Wang 2003 | PN |\n"
                 "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const ModelComparison& c : results)
    {
      std::cout << "| " << c.Name;
      for (const VariantFigures* v : { &c.Coarse, &c.Smoothed, &c.Wang2003, &c.PN, &c.Fine })
      {
        std::cout << " | " << Fixed(v->CoherenceMean, 2) << " / " << Fixed(v->CoherenceMax, 1);
      }
      for (const VariantFigures* v : { &c.Smoothed, &c.Wang2003, &c.PN })
      {
        std::cout << " | " << RatioOrNothing(v->CoherenceRatio, 2, "-");
      }
      for (const VariantFigures* v : { &c.Smoothed, &c.Wang2003, &c.PN })
      {
        std::cout << " | " << Fixed(v->CoherenceExcess, 1);
      }
      std::cout << " |\n";
    }
  }
  std::cout << "\n"
            << options.Views << " views, " << options.Frames << " timed orbit frames, "
            << options.ViewportSize[0] << "x" << options.ViewportSize[1] << ", tolerance "
            << options.Tolerance << " px, fine = Loop level " << options.FineLevel
            << "; Wang 2003 at the same tolerance; PN at the level k >= 1 whose triangle count is "
               "nearest ours; coherence over "
            << options.Frames << " 1-degree steps.\n";
}

} // namespace

std::string CoarseVersionText(vtkPolyData* original, int coarseTriangles)
{
  const vtkIdType have = CountTriangles(original);
  return have <= coarseTriangles
    ? "keeping its " + std::to_string(have) + " triangles (no more than " +
      std::to_string(coarseTriangles) + ")"
    : "decimating to " + std::to_string(coarseTriangles) + " triangles";
}

vtkSmartPointer<vtkPolyData> OriginalOf(const std::string& input, const std::string& dataDirectory,
  const std::string& command, int& coarseTriangles)
{
  if (silhouette_eval::IsModelName(input))
  {
    coarseTriangles =
      coarseTriangles > 0 ? coarseTriangles : silhouette_eval::DefaultCoarseTriangles(input);
    return silhouette_eval::MakeOriginal(input, dataDirectory);
  }
  RequireModelOrFile(input);
  coarseTriangles = coarseTriangles > 0 ? coarseTriangles : 1000;
  vtkIdType merged = 0;
  vtkSmartPointer<vtkPolyData> welded = silhouette_eval::WeldedTriangles(ReadMesh(input), &merged);
  if (merged > 0)
  {
    std::cerr << command << ": " << PrintableText(input) << ": " << Grouped(merged)
              << " points share a position with another (texture seams, hard edges or a "
                 "triangle soup); merged, so that decimation and Loop refinement see one surface"
              << std::endl;
  }
  return welded;
}

void RunCompare(const CompareOptions& options)
{
  if (options.Truth)
  {
    RunCompareTruth(options);
    return;
  }
  std::vector<std::string> inputs;
  for (const std::string& input : options.Inputs)
  {
    if (input == "all")
    {
      const auto names = silhouette_eval::ModelNames();
      inputs.insert(inputs.end(), names.begin(), names.end());
    }
    else
    {
      inputs.push_back(input);
    }
  }
  const std::string dataDirectory =
    options.DataDirectory.empty() ? DefaultDataDirectory() : options.DataDirectory;

  silhouette_eval::ComparisonOptions comparison;
  comparison.Width = options.ViewportSize[0];
  comparison.Height = options.ViewportSize[1];
  comparison.Views = options.Views;
  comparison.TimedFrames = options.Frames;
  comparison.CoherenceSteps = options.Frames;
  comparison.Tolerance = options.Tolerance;
  comparison.Progress = [](const std::string& line) {
    std::cerr << "compare: " << PrintableText(line) << std::endl;
  };

  VtkErrorLog& errors = VtkErrorLog::Instance();
  std::vector<ModelComparison> results;
  for (const std::string& input : inputs) // a typo found before the work
  {
    try
    {
      RequireModelOrFile(input);
    }
    catch (const RuntimeError& error)
    {
      throw RuntimeError(input + ": " + error.what());
    }
  }
  for (const std::string& input : inputs)
  {
    errors.Clear();
    int coarseTriangles = options.CoarseTriangles;
    try
    {
      const vtkSmartPointer<vtkPolyData> original =
        OriginalOf(input, dataDirectory, "compare", coarseTriangles);
      std::cerr << "compare: " << input << ": " << CoarseVersionText(original, coarseTriangles)
                << " and refining to Loop level " << options.FineLevel << std::endl;
      const silhouette_eval::ModelVersions versions =
        silhouette_eval::MakeVersions(input, original, coarseTriangles, options.FineLevel);
      errors.ThrowIfErrors("preparing " + input + " failed");
      results.push_back(silhouette_eval::CompareModel(versions, comparison));
      errors.ThrowIfErrors("comparing " + input + " failed");
    }
    catch (const std::runtime_error& error)
    {
      throw RuntimeError(input + ": " + error.what());
    }
    if (options.Format == CompareFormat::Text)
    {
      PrintText(results.back(), options);
    }
  }
  if (options.Format == CompareFormat::Markdown)
  {
    PrintMarkdown(results, options);
  }
  else if (options.Format == CompareFormat::Json)
  {
    std::cout << "[";
    for (std::size_t i = 0; i < results.size(); ++i)
    {
      const ModelComparison& c = results[i];
      std::cout << (i ? ", " : "") << "{\"model\": " << JsonString(c.Name)
                << ", \"original_triangles\": " << c.OriginalTriangles
                << ", \"silhouette_triangles\": " << Fixed(c.SilhouetteTriangles, 1)
                << ", \"coarse\": " << JsonVariant(c.Coarse)
                << ", \"smoothed\": " << JsonVariant(c.Smoothed)
                << ", \"wang2003\": " << JsonVariant(c.Wang2003) << ", \"pn_level\": " << c.PNLevel
                << ", \"pn\": " << JsonVariant(c.PN) << ", \"fine\": " << JsonVariant(c.Fine)
                << ", \"deviation_ratio\": " << Fixed(DeviationRatio(c), 3)
                << ", \"frame_ratio\": " << Fixed(FrameRatio(c), 3) << "}";
    }
    std::cout << "]\n";
  }
}

std::string CompareHelp()
{
  return R"(Usage: silhouette compare MODEL|MESH|all ... [options]

R. Xing's evaluation ("Adaptive Local Remeshing for Smooth Silhouette on 3D
Triangle Meshes", section 4.4) with numbers: for each input, a coarse version (quadric
decimation of the original), the coarse version with silhouette smoothing
(Wang et al. 2008, this project), the coarse version with the methods the
2008 paper compares with -- Wang et al. 2003 boundary-curve interpolation
(same tolerance) and PN triangles (Vlachos et al. 2001) at the level k >= 1
whose triangle count, coarse x (k+1)^2, is nearest the smoothed mesh's --
and a fine reference (OpenSubdiv Loop refinement of the original, projected
to the limit surface) are rendered from the same cameras. For each it prints
the triangles rendered, the distance of its outline to the fine reference's
outline (pixels; every boundary pixel of each mask measured to the other's
boundary with a Euclidean distance transform, mean over the views and max),
and the whole-frame time (camera move, filter when view-dependent, render
to completion; median over an orbit). 'filter ms' is per frame for the
view-dependent methods and the one-off tessellation for PN triangles. For
the analytic models (all but the bunny) it also prints the distance to the
exact silhouette: the exact circle for the sphere; for the torus, the
ellipsoid, the super-toroid and the knot, the outline of the same analytic
surface sampled very finely (327,680 to 518,400 triangles, within a
0.015 px of the true outline; docs/exact-surfaces.md).
Temporal coherence: from the first view the camera turns in --frames steps
of 1 degree; for each variant, each step compares the outline with its
outline one step before (both ways, by distance transform). It prints the
mean distance of a step averaged over the steps (how far the outline
moves), the largest distance in any step (the worst local jump), the
first over the fine reference's (1: the outline moves as the smooth
surface's does; more: it jumps about), and the largest amount by which a
step's largest distance exceeds the fine reference's in the same step (a
jump the smooth surface did not make).
Targets: smoothed deviation at most 1/3 of the coarse one, and smoothed
frame time at most 1/3 of the fine one; each line says whether they are met.
Progress goes to stderr. Where there is no X display it renders through
OSMesa (--backend).

Models: bunny, sphere, torus, ellipsoid, supertoroid, knot; 'all' for all of
them. Any other INPUT is read as a mesh file (.ply .obj .stl .vtp .vtk).

Options:
  --coarse-triangles N  triangles of the coarse version (default: the
                        model's own; 1000 for a mesh file)
  --fine-level L        Loop refinement level of the fine reference, 1 to 5
                        (default 3)
  --views N             camera positions for the deviations (default 12)
  --frames N            timed orbit frames per variant, at least 30 for the
                        figures of docs/comparison.md, and the number of
                        1-degree steps of the coherence orbit (default 30)
  --size WxH            image size (default 1024x768)
  --tolerance PX        the filters' Tolerance, ours and Wang 2003's
                        (default 0.5)
  --data DIR            the folder that holds bunny.ply (default: the one
                        installed with the program, share/SilhouetteSmoothing/
                        Data beside its bin folder)
  --truth               measure against the truth instead, for mesh files
                        (closed triangle meshes): a coarse version (our
                        link-condition quadric decimation to --coarse-triangles,
                        default 500, points moved onto the original) as it is,
                        smoothed with its own normals (each NormalEstimation),
                        with the original's normals carried over and with the
                        fold guard off, and as PN triangles and Phong
                        tessellation (given the area-weighted normals ours
                        uses) at the level nearest ours and at level 3,
                        against the original refined by two levels of
                        Butterfly subdivision (interpolating: unlike Loop's
                        limit it does not shrink the shape) and against the
                        original itself; for ours also the folds (turned-over
                        triangles / cutting pairs) and the chord fallbacks,
                        summed over the views, and for every method where its
                        largest distance is: the view, and whether its outline
                        lies outside the reference's there or inside it (a
                        part shrunk, or a gap seen through the mesh)
                        (docs/fidelity.md)
  --coarse-points original|reference
                        with --truth: move the coarse points onto the
                        original (default) or onto the reference; the
                        original's facets lie inside the reference, so
                        points on them sit inside the true shape, and
                        with 'reference' the carried normals are the
                        reference's
  --json                one JSON array, an object per model
  --markdown            docs/comparison.md's tables (the earlier methods and the
                        coherence in tables of their own)
)" + RenderBackendHelp(24) +
    R"(  -h, --help            show this help and exit
)";
}

CompareOptions ParseCompare(ArgumentList& arguments, RenderBackend& backend)
{
  CompareOptions options;
  bool coarsePointsGiven = false;
  while (!arguments.AtEnd())
  {
    const std::string word = arguments.Take();
    if (!LooksLikeOption(word))
    {
      options.Inputs.push_back(word);
      continue;
    }
    const Option option = SplitOption(word);
    if (option.Name == "--coarse-triangles")
    {
      options.CoarseTriangles = ParseCount(option, arguments.TakeValue(option), 4, 10000000);
    }
    else if (option.Name == "--fine-level")
    {
      options.FineLevel = ParseCount(option, arguments.TakeValue(option), 1, 5);
    }
    else if (option.Name == "--views")
    {
      options.Views = ParseCount(option, arguments.TakeValue(option), 1, 1000);
    }
    else if (option.Name == "--frames")
    {
      options.Frames = ParseCount(option, arguments.TakeValue(option), 1, 100000);
    }
    else if (option.Name == "--size")
    {
      options.ViewportSize = ParseViewportSize(option.Name, arguments.TakeValue(option));
    }
    else if (option.Name == "--tolerance")
    {
      const std::string text = arguments.TakeValue(option);
      options.Tolerance = ParseNumber(option.Name, text);
      if (!(options.Tolerance >= 0.001))
      {
        throw UsageError(
          "option '--tolerance' needs a number of at least 0.001, got '" + text + "'");
      }
    }
    else if (option.Name == "--data")
    {
      options.DataDirectory = arguments.TakeValue(option);
    }
    else if (option.Name == "--json" || option.Name == "--markdown")
    {
      RejectInlineValue(option);
      const CompareFormat format =
        option.Name == "--json" ? CompareFormat::Json : CompareFormat::Markdown;
      if (options.Format != CompareFormat::Text && options.Format != format)
      {
        throw UsageError("options '--json' and '--markdown' do not go together");
      }
      options.Format = format;
    }
    else if (option.Name == "--truth")
    {
      RejectInlineValue(option);
      options.Truth = true;
    }
    else if (option.Name == "--coarse-points")
    {
      const std::string where = arguments.TakeValue(option);
      if (where != "original" && where != "reference")
      {
        throw UsageError(
          "option '--coarse-points' takes 'original' or 'reference', got '" + where + "'");
      }
      options.CoarsePointsOnReference = where == "reference";
      coarsePointsGiven = true;
    }
    else if (option.Name == "--backend")
    {
      backend = ParseRenderBackend(option.Name, arguments.TakeValue(option));
    }
    else
    {
      throw UsageError(
        "unknown option '" + option.Name + "' for 'compare'; run 'silhouette compare --help'");
    }
  }
  if (options.Inputs.empty())
  {
    throw UsageError("'compare' needs a model name, 'all' or a mesh file");
  }
  if (coarsePointsGiven && !options.Truth)
  {
    throw UsageError("option '--coarse-points' needs '--truth'");
  }
  if (options.Truth)
  {
    for (const std::string& input : options.Inputs)
    {
      if (input == "all" || silhouette_eval::IsModelName(input))
      {
        throw UsageError("'compare --truth' takes mesh files, not the model '" + input + "'");
      }
    }
  }
  return options;
}

} // namespace cli
