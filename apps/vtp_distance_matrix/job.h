// vtp_distance_matrix: the processes of one run (MPI ranks, or just this process).
//
// The same binary runs alone or under mpirun. MPI is initialized only when the process was started by
// an MPI launcher (its environment names a rank), so that a plain run needs no MPI runtime at all;
// a binary built without MPI refuses to run as one of several ranks. Everything the tool needs from
// MPI is here: the rank and size, agreeing on errors, broadcasting the plan of rank 0, and the row
// counts that rank 0 collects for the progress line.

#ifndef VTP_DISTANCE_MATRIX_JOB_H
#define VTP_DISTANCE_MATRIX_JOB_H

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace vtp_matrix {

// Thrown on every rank by Job::agree() when some rank had an error; the message is that of the
// lowest such rank.
struct Job_error
{
  std::string message;
};

class Job
{
public:
  // Initializes MPI if the process runs under an MPI launcher. Throws Tool_error if it does but the
  // tool was built without MPI, or if MPI cannot give the thread support the tool needs.
  Job(int& argc, char**& argv);
  ~Job();
  Job(const Job&) = delete;
  Job& operator=(const Job&) = delete;

  bool uses_mpi() const { return m_mpi; }
  int rank() const { return m_rank; }
  int size() const { return m_size; }
  bool is_root() const { return m_rank == 0; }

  // Collective. `error` is this rank's error message (empty: none). If any rank has one, every rank
  // throws Job_error with the message of the lowest failing rank.
  void agree(const std::string& error);
  // Collective: the bytes of rank 0 are copied to every rank.
  void broadcast(std::vector<char>& bytes);
  void barrier();

  // Progress. Every rank counts the rows it has written; rank 0 learns the others' counts.
  // Non-root ranks: send the count (at most twice a second, never blocking; `final` always sends,
  // and must be called exactly once, at the end of the computation, by every rank).
  void send_rows(std::int64_t rows, bool final);
  // Rank 0: the sum of the latest counts received from the other ranks (receives what has arrived).
  std::int64_t other_rows();
  // Rank 0: waits until every other rank has sent its final count, calling `tick` (about ten times
  // a second) with the total of the other ranks meanwhile.
  void wait_for_final_rows(const std::function<void(std::int64_t)>& tick);

  // Ends the whole job after an error that cannot be agreed on (MPI_Abort under MPI).
  [[noreturn]] void abort(int code);

private:
  bool m_mpi = false;
  int m_rank = 0, m_size = 1;
  std::vector<std::int64_t> m_rows_of_rank;
  std::vector<char> m_final_of_rank;
  std::int64_t m_sent = -1;
  double m_last_send = -1.;
  struct Pending_send;                     // the MPI request of the last count sent, if any
  Pending_send* m_pending = nullptr;
};

// Seconds on a monotonic clock.
double now_seconds();

} // namespace vtp_matrix

#endif // VTP_DISTANCE_MATRIX_JOB_H
