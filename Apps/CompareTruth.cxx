#include "Compare.h"

#include "CliErrors.h"
#include "MeshIO.h"
#include "PrintableText.h"
#include "VtkErrorLog.h"

#include "EvaluationModels.h"
#include "FidelityEvaluation.h"

#include <vtkPolyData.h>

#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace cli
{
namespace
{

std::string Number(double value, int decimals)
{
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", decimals, value);
  return text;
}

std::string Quoted(const std::string& text)
{
  std::string out = "\"";
  for (const char c : text)
  {
    if (c == '"' || c == '\\')
    {
      out += '\\';
    }
    out += c;
  }
  return out + "\"";
}

std::string Count(long count)
{
  return count < 0 ? std::string("-") : std::to_string(count);
}

// Turned-over triangles / cutting pairs, or "-" where not counted.
std::string Folds(const silhouette_eval::FidelityRow& row)
{
  return row.TurnedOver < 0 ? std::string("-") : Count(row.TurnedOver) + " / " + Count(row.Cutting);
}

// Where the largest distance to the reference is: "view 5, outside".
std::string WorstPlace(const silhouette_eval::FidelityRow& row)
{
  return row.WorstView < 0
    ? std::string("-")
    : "view " + std::to_string(row.WorstView) + ", " + (row.WorstOutside ? "outside" : "inside");
}

// "+0.0442 / -0.0079 of the diagonal": how far the reference strays.
std::string ReferenceStray(const silhouette_eval::FidelityResult& r)
{
  char text[96];
  std::snprintf(
    text, sizeof(text), "%+.4f / %+.4f of the diagonal", r.ReferenceOutside, r.ReferenceInside);
  return text;
}

const char* CoarsePointSurface(const silhouette_eval::FidelityResult& r)
{
  return r.CoarsePointsOnReference ? "reference" : "original";
}

void PrintText(const silhouette_eval::FidelityResult& r)
{
  std::cout << "mesh " << r.Name << ": " << r.OriginalTriangles << " triangles, coarse "
            << r.CoarseTriangles << " (points on the " << CoarsePointSurface(r)
            << "), reference (Butterfly) " << r.ReferenceTriangles << ", off the original by "
            << ReferenceStray(r) << "\n";
  std::printf("  %-31s %9s %9s %9s %11s %11s %8s %13s %7s  %s\n", "method", "triangles", "mean",
    "max", "mean(orig)", "max(orig)", "/coarse", "turned/cutting", "chord", "max at");
  const double coarse = r.Rows.empty() ? 0.0 : r.Rows.front().Mean;
  for (const silhouette_eval::FidelityRow& row : r.Rows)
  {
    std::printf("  %-31s %9.0f %9.3f %9.3f %11.3f %11.3f %8.2f %14s %7s  %s\n", row.Method.c_str(),
      row.Triangles, row.Mean, row.Max, row.MeanToOriginal, row.MaxToOriginal,
      coarse > 0 ? row.Mean / coarse : 0.0, Folds(row).c_str(), Count(row.ChordFallbacks).c_str(),
      WorstPlace(row).c_str());
  }
  std::cout.flush();
}

void PrintMarkdown(const std::vector<silhouette_eval::FidelityResult>& results)
{
  for (const silhouette_eval::FidelityResult& r : results)
  {
    // The file's name alone: the tables go into documents.
    const std::string name = r.Name.substr(r.Name.find_last_of('/') + 1);
    std::cout << "**" << name << "** (" << r.OriginalTriangles << " triangles; coarse "
              << r.CoarseTriangles << ", points on the " << CoarsePointSurface(r) << "; reference "
              << r.ReferenceTriangles << ", off the original by " << ReferenceStray(r) << ")\n\n";
    std::cout << "| method | triangles | mean px | max px | mean / coarse | mean px, original | "
                 "max px, original | folds: turned over / cutting | chord fallbacks | max at |\n"
                 "|---|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
    const double coarse = r.Rows.empty() ? 0.0 : r.Rows.front().Mean;
    for (const silhouette_eval::FidelityRow& row : r.Rows)
    {
      std::cout << "| " << row.Method << " | " << Number(row.Triangles, 0) << " | "
                << Number(row.Mean, 3) << " | " << Number(row.Max, 2) << " | "
                << Number(coarse > 0 ? row.Mean / coarse : 0.0, 2) << " | "
                << Number(row.MeanToOriginal, 3) << " | " << Number(row.MaxToOriginal, 2) << " | "
                << Folds(row) << " | " << Count(row.ChordFallbacks) << " | " << WorstPlace(row)
                << " |\n";
    }
    std::cout << "\n";
  }
}

void PrintJson(const std::vector<silhouette_eval::FidelityResult>& results)
{
  std::cout << "[";
  for (std::size_t i = 0; i < results.size(); ++i)
  {
    const silhouette_eval::FidelityResult& r = results[i];
    std::cout << (i ? ", " : "") << "{\"mesh\": " << Quoted(r.Name)
              << ", \"original_triangles\": " << r.OriginalTriangles
              << ", \"coarse_triangles\": " << r.CoarseTriangles
              << ", \"coarse_points\": " << Quoted(CoarsePointSurface(r))
              << ", \"reference_triangles\": " << r.ReferenceTriangles
              << ", \"reference_outside\": " << Number(r.ReferenceOutside, 5)
              << ", \"reference_inside\": " << Number(r.ReferenceInside, 5) << ", \"methods\": [";
    const double coarse = r.Rows.empty() ? 0.0 : r.Rows.front().Mean;
    for (std::size_t k = 0; k < r.Rows.size(); ++k)
    {
      const silhouette_eval::FidelityRow& row = r.Rows[k];
      std::cout << (k ? ", " : "") << "{\"method\": " << Quoted(row.Method)
                << ", \"triangles\": " << Number(row.Triangles, 1)
                << ", \"mean\": " << Number(row.Mean, 4) << ", \"max\": " << Number(row.Max, 4)
                << ", \"mean_over_coarse\": " << Number(coarse > 0 ? row.Mean / coarse : 0.0, 4)
                << ", \"mean_to_original\": " << Number(row.MeanToOriginal, 4)
                << ", \"max_to_original\": " << Number(row.MaxToOriginal, 4)
                << ", \"turned_over\": " << row.TurnedOver << ", \"cutting\": " << row.Cutting
                << ", \"chord_fallbacks\": " << row.ChordFallbacks
                << ", \"max_view\": " << row.WorstView
                << ", \"max_side\": " << Quoted(row.WorstOutside ? "outside" : "inside") << "}";
    }
    std::cout << "]}";
  }
  std::cout << "]\n";
}

} // namespace

void RunCompareTruth(const CompareOptions& options)
{
  silhouette_eval::FidelityOptions fidelity;
  fidelity.Width = options.ViewportSize[0];
  fidelity.Height = options.ViewportSize[1];
  fidelity.Views = options.Views;
  fidelity.Tolerance = options.Tolerance;
  fidelity.CoarseTriangles = options.CoarseTriangles > 0 ? options.CoarseTriangles : 500;
  fidelity.CoarsePointsOnReference = options.CoarsePointsOnReference;
  fidelity.Progress = [](const std::string& line) {
    std::cerr << "compare: " << PrintableText(line) << std::endl;
  };
  VtkErrorLog& errors = VtkErrorLog::Instance();
  std::vector<silhouette_eval::FidelityResult> results;
  for (const std::string& input : options.Inputs)
  {
    errors.Clear();
    try
    {
      vtkSmartPointer<vtkPolyData> original = ReadMesh(input);
      results.push_back(silhouette_eval::EvaluateFidelity(input, original, fidelity));
      errors.ThrowIfErrors("evaluating " + input + " failed");
    }
    catch (const RuntimeError&)
    {
      throw; // the reading's own message names the file
    }
    catch (const std::runtime_error& error)
    {
      throw RuntimeError(input + ": " + error.what()); // the evaluation's does not
    }
    if (options.Format == CompareFormat::Text)
    {
      PrintText(results.back());
    }
  }
  if (options.Format == CompareFormat::Markdown)
  {
    PrintMarkdown(results);
  }
  else if (options.Format == CompareFormat::Json)
  {
    PrintJson(results);
  }
}

} // namespace cli
