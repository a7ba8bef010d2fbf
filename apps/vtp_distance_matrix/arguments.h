// vtp_distance_matrix: command-line arguments.

#ifndef VTP_DISTANCE_MATRIX_ARGUMENTS_H
#define VTP_DISTANCE_MATRIX_ARGUMENTS_H

#include <limits>
#include <ostream>
#include <string>

namespace vtp_support {
struct Method_info;
}

namespace vtp_matrix {

struct Arguments
{
  std::string mesh;
  std::string sources;      // "all", "A:B", "V,V,...", or a file name (see source_list.h)
  std::string output;
  bool float32 = false;
  bool has_max_distance = false;  // with a distance limit, the rows are sparse (CSR)
  bool polar = false;             // --polar: the polar patches (rho and theta), sparse rows; needs --max-distance
  double max_distance = std::numeric_limits<double>::infinity();
  // --method: a sequential method of the table (vtp_support/methods.h; the rows run in parallel); vtp by default
  const vtp_support::Method_info* method = nullptr;
  double lambda = 8.;             // AVTP reset period (mean edge lengths), --lambda
  bool has_lambda = false;
  int threads = 0;                // 0: OpenMP's default
  bool resume = false;
  bool force = false;
  int progress = -1;              // -1: on a terminal only; 0: --quiet; 1: --progress
  bool help = false;
};

// Throws Tool_error on any bad argument.
Arguments parse_arguments(int argc, char** argv);

void print_usage(std::ostream& os);

} // namespace vtp_matrix

#endif // VTP_DISTANCE_MATRIX_ARGUMENTS_H
