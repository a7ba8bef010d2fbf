// vtp_benchmark: the table on standard output and the CSV file.

#include "vtp_benchmark.h"

#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

namespace vtp_benchmark {

std::string number(double x, int precision)
{
  if(std::isnan(x))
    return std::string();
  if(std::isinf(x))
    return x > 0 ? "inf" : "-inf";
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*g", precision, x);
  return buffer;
}

namespace {

std::string csv_field(const std::string& s)
{
  if(s.find_first_of(",\"\n") == std::string::npos)
    return s;
  std::string r = "\"";
  for(char c : s)
  {
    if(c == '"') r += '"';
    r += c;
  }
  return r + "\"";
}

} // namespace

const char* const csv_columns =
  "mesh,vertices,faces,source,method,threads,seconds,preprocessing_seconds,peak_rss_mb,windows_created,"
  "windows_propagated,peak_window_bytes,max_abs_err_vs_vtp,max_rel_err_vs_vtp,mean_rel_err_vs_vtp,speedup_vs_cgal,"
  "total_seconds,rss_at_start_mb,mean_pointwise_rel_err_vs_vtp,max_pointwise_rel_err_vs_vtp,speedup_vs_vtp,"
  "peak_live_windows,ns_per_window,pseudo_source_share,cpu_seconds,cpu_ratio_vs_vtp,status,max_below_vtp";


void write_csv_row(std::ostream& os, const Mesh_info& mesh, std::size_t source, const Run_result& r)
{
  const Child_header& h = r.header;
  const CGAL::VTP_geodesics::Propagation_statistics& s = r.statistics;
  const bool w = r.ok && r.has_statistics;
  const bool own = w && r.method.kind != Method_kind::EXTERNAL;  // the library's statistics
  os << csv_field(mesh.label) << ',' << mesh.vertices << ',' << mesh.faces << ',' << source << ','
     << csv_field(r.method.label) << ',' << (r.ok ? std::to_string(s.threads) : std::string()) << ','
     << (r.ok ? number(h.seconds, 9) : "") << ',' << (r.ok ? number(h.preprocessing_seconds, 9) : "") << ','
     << number(r.peak_rss_mb, 6) << ','
     << (own ? std::to_string(s.windows_created) : "") << ','
     << (w ? std::to_string(s.windows_propagated) : "") << ','
     << (own ? std::to_string(s.peak_window_bytes) : "") << ','
     << number(r.max_abs_err, 6) << ',' << number(r.max_rel_err, 6) << ',' << number(r.mean_rel_err, 6) << ','
     << number(r.speedup_vs_cgal, 6) << ','
     << (r.ok ? number(total_seconds(r), 9) : "") << ','
     << (r.ok ? number(h.rss_at_start_kb / 1024., 6) : "") << ','
     << number(r.mean_pointwise_rel_err, 6) << ',' << number(r.max_pointwise_rel_err, 6) << ','
     << number(r.speedup_vs_vtp, 6) << ','
     << (own ? std::to_string(s.peak_live_windows) : "") << ','
     << number(ns_per_window(r), 6) << ',' << number(mesh.pseudo_source_share, 6) << ','
     << (r.ok ? number(h.cpu_seconds, 9) : "") << ',' << number(r.cpu_ratio_vs_vtp, 6) << ','
     << csv_field(r.status) << ',' << number(r.max_below_vtp, 6) << '\n';
}

void print_table_header()
{
  std::printf("%-22s %9s %9s  %-12s %11s %11s %9s %9s %11s %7s %10s %9s  %s\n", "mesh", "vertices", "source", "method",
              "seconds", "prep_s", "rss_MB", "+rss_MB", "windows", "ns/win", "max_rel", "speedup", "status");
}

void print_table_row(const Mesh_info& mesh, std::size_t source, const Run_result& r)
{
  const Child_header& h = r.header;
  const std::string windows = (r.ok && r.has_statistics && r.method.kind != Method_kind::EXTERNAL)
                              ? std::to_string(r.statistics.windows_created) : "-";
  const double increase = (r.ok && r.method.kind != Method_kind::EXTERNAL) ? r.peak_rss_mb - h.rss_at_start_kb / 1024.
                                                                           : nan_value;
  auto cell = [](double x, int p) { const std::string s = number(x, p); return s.empty() ? std::string("-") : s; };
  std::printf("%-22s %9zu %9zu  %-12s %11s %11s %9s %9s %11s %7s %10s %9s  %s\n", mesh.label.c_str(), mesh.vertices, source,
              r.method.label.c_str(), cell(r.ok ? h.seconds : nan_value, 4).c_str(),
              cell(r.ok ? h.preprocessing_seconds : nan_value, 4).c_str(), cell(r.peak_rss_mb, 4).c_str(),
              cell(increase, 4).c_str(), windows.c_str(), cell(ns_per_window(r), 3).c_str(), cell(r.max_rel_err, 3).c_str(),
              cell(r.speedup_vs_cgal, 3).c_str(), r.status.c_str());
  std::fflush(stdout);
}

} // namespace vtp_benchmark
