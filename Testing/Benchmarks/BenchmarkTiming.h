// Timing helpers the benchmarks share (header only, no VTK).
#ifndef BenchmarkTiming_h
#define BenchmarkTiming_h

#include <algorithm>
#include <chrono>
#include <functional>
#include <vector>

namespace benchmark_timing
{

/// Wall-clock milliseconds `work` takes.
inline double Milliseconds(const std::function<void()>& work)
{
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
    .count();
}

/// The middle value (the upper middle one of an even count); `values` not empty.
inline double Median(std::vector<double> values)
{
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

} // namespace benchmark_timing

#endif
