// What the benchmarks of the curves and of the kept field (curves_benchmark.cpp, field_benchmark.cpp) share: the
// processor time of the process, and the summary of the errors of checked points.

#ifndef VTP_GEODESICS_BENCHMARK_ERROR_REPORT_H
#define VTP_GEODESICS_BENCHMARK_ERROR_REPORT_H

#include <algorithm>
#include <cstddef>
#include <ctime>
#include <iostream>
#include <vector>

namespace vtp_benchmark_report {

// the processor time of the process (the runs and the extractions are sequential: robust to other jobs)
inline double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// one line: how many of the errors `e` (relative to the largest distance) are within `threshold`, their median,
// 99th percentile and largest
inline void print_errors(const char* what, std::vector<double> e, double threshold)
{
  std::sort(e.begin(), e.end());
  const std::size_t n = e.size();
  std::size_t within = 0;
  for(double x : e)
    within += x <= threshold ? 1 : 0;
  std::cout << what << ": " << n << " points, " << within << " within " << threshold << " (" << 100. * within / (n ? n : 1)
            << "%), median " << (n ? e[n / 2] : 0.) << ", 99% " << (n ? e[n * 99 / 100] : 0.) << ", max "
            << (n ? e[n - 1] : 0.) << " (relative to the largest distance)\n";
}

} // namespace vtp_benchmark_report

#endif // VTP_GEODESICS_BENCHMARK_ERROR_REPORT_H
