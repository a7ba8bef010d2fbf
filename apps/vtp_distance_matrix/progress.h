// vtp_distance_matrix: the progress line (rank 0 only).

#ifndef VTP_DISTANCE_MATRIX_PROGRESS_H
#define VTP_DISTANCE_MATRIX_PROGRESS_H

#include <cstdint>

namespace vtp_matrix {

// "vtp_distance_matrix: 1234/9770 rows (12.6%), 41.2 rows/s, 3 min 27 s left" on stderr.
// On a terminal, one line rewritten in place; otherwise one line per update. At most two updates a
// second, and a last line at the end. The rate counts the rows computed by this run only (rows done
// before a --resume are in the total, not in the rate).
class Progress
{
public:
  // `enabled`: print anything at all; `total`: rows of the matrix; `done_before`: rows already
  // complete when this run started.
  Progress(bool enabled, std::int64_t total, std::int64_t done_before);
  // `done` rows complete in the whole matrix (including `done_before`).
  void update(std::int64_t done);
  void finish(std::int64_t done);

private:
  void print(std::int64_t done, bool last);
  bool m_enabled, m_terminal;
  std::int64_t m_total, m_done_before;
  double m_start, m_last_print = -1.;
  std::int64_t m_last_done = -1;
  int m_last_width = 0;
};

} // namespace vtp_matrix

#endif // VTP_DISTANCE_MATRIX_PROGRESS_H
