// vtp_distance_matrix: the processes of one run (MPI ranks, or just this process).

#include "job.h"
#include "tool_error.h"

#include <chrono>
#include <cstdlib>
#include <thread>

#ifdef VTP_MATRIX_WITH_MPI
#include <mpi.h>
#endif

namespace vtp_matrix {

double now_seconds()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

namespace {

long long environment_number(const char* name)
{
  const char* v = std::getenv(name);
  if(v == nullptr || *v == '\0')
    return -1;
  return std::atoll(v);
}

// True when an MPI launcher (Open MPI's mpirun, or a PMI/PMIx launcher such as MPICH's or Slurm's)
// started this process.
bool launched_by_mpi()
{
  return environment_number("OMPI_COMM_WORLD_SIZE") >= 0 || environment_number("PMIX_RANK") >= 0
         || environment_number("PMI_RANK") >= 0 || environment_number("PMI_SIZE") >= 0;
}

constexpr int tag_rows = 1, tag_final_rows = 2;

} // namespace

#ifdef VTP_MATRIX_WITH_MPI
struct Job::Pending_send
{
  MPI_Request request = MPI_REQUEST_NULL;
  std::int64_t value = 0;
};
#else
struct Job::Pending_send {};
#endif

Job::Job(int& argc, char**& argv)
{
#ifdef VTP_MATRIX_WITH_MPI
  if(launched_by_mpi())
  {
    // Rows are handed to the output by whichever OpenMP thread finishes them, one at a time (under a
    // critical section): MPI_THREAD_SERIALIZED.
    int provided = MPI_THREAD_SINGLE;
    if(MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided) != MPI_SUCCESS)
      throw Tool_error("MPI_Init_thread failed");
    m_mpi = true;
    MPI_Comm_rank(MPI_COMM_WORLD, &m_rank);
    MPI_Comm_size(MPI_COMM_WORLD, &m_size);
    MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
    if(provided < MPI_THREAD_SERIALIZED)
      throw Tool_error("the MPI library does not support MPI_THREAD_SERIALIZED");
    m_rows_of_rank.assign(static_cast<std::size_t>(m_size), 0);
    m_final_of_rank.assign(static_cast<std::size_t>(m_size), 0);
    m_pending = new Pending_send;
  }
#else
  (void)argc;
  (void)argv;
  if(launched_by_mpi() && (environment_number("OMPI_COMM_WORLD_SIZE") > 1 || environment_number("PMI_SIZE") > 1
                           || environment_number("PMIX_RANK") > 0 || environment_number("PMI_RANK") > 0))
    throw Tool_error("started as one of several MPI processes, but built without MPI support "
                     "(install libopenmpi-dev and rebuild)");
#endif
}

Job::~Job()
{
#ifdef VTP_MATRIX_WITH_MPI
  if(m_mpi)
  {
    if(m_pending != nullptr && m_pending->request != MPI_REQUEST_NULL)
      MPI_Wait(&m_pending->request, MPI_STATUS_IGNORE);
    delete m_pending;
    int finalized = 0;
    MPI_Finalized(&finalized);
    if(!finalized)
      MPI_Finalize();
  }
#endif
}

void Job::agree(const std::string& error)
{
#ifdef VTP_MATRIX_WITH_MPI
  if(m_mpi)
  {
    int mine = error.empty() ? m_size : m_rank, first = m_size;
    MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if(first == m_size)
      return;
    long long length = static_cast<long long>(error.size());
    MPI_Bcast(&length, 1, MPI_LONG_LONG, first, MPI_COMM_WORLD);
    std::string message(static_cast<std::size_t>(length), ' ');
    if(m_rank == first)
      message = error;
    if(length > 0)
      MPI_Bcast(&message[0], static_cast<int>(length), MPI_CHAR, first, MPI_COMM_WORLD);
    throw Job_error{message};
  }
#endif
  if(!error.empty())
    throw Job_error{error};
}

void Job::broadcast(std::vector<char>& bytes)
{
#ifdef VTP_MATRIX_WITH_MPI
  if(m_mpi)
  {
    long long size = static_cast<long long>(bytes.size());
    MPI_Bcast(&size, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
    bytes.resize(static_cast<std::size_t>(size));
    // in pieces of at most 1 GiB (MPI counts are ints)
    const long long piece = 1LL << 30;
    for(long long at = 0; at < size; at += piece)
    {
      const long long n = (size - at < piece) ? size - at : piece;
      MPI_Bcast(bytes.data() + at, static_cast<int>(n), MPI_CHAR, 0, MPI_COMM_WORLD);
    }
  }
#else
  (void)bytes;
#endif
}

void Job::barrier()
{
#ifdef VTP_MATRIX_WITH_MPI
  if(m_mpi)
    MPI_Barrier(MPI_COMM_WORLD);
#endif
}

void Job::send_rows(std::int64_t rows, bool final)
{
#ifdef VTP_MATRIX_WITH_MPI
  if(!m_mpi || is_root())
    return;
  Pending_send& p = *m_pending;
  if(p.request != MPI_REQUEST_NULL)
  {
    int done = 0;
    if(final)
      MPI_Wait(&p.request, MPI_STATUS_IGNORE);
    else
    {
      MPI_Test(&p.request, &done, MPI_STATUS_IGNORE);
      if(!done)
        return;
    }
  }
  if(final)
  {
    std::int64_t value = rows;
    MPI_Send(&value, 1, MPI_INT64_T, 0, tag_final_rows, MPI_COMM_WORLD);
    return;
  }
  const double t = now_seconds();
  if(rows == m_sent || t - m_last_send < 0.5)
    return;
  m_sent = rows;
  m_last_send = t;
  p.value = rows;
  MPI_Isend(&p.value, 1, MPI_INT64_T, 0, tag_rows, MPI_COMM_WORLD, &p.request);
#else
  (void)rows;
  (void)final;
#endif
}

std::int64_t Job::other_rows()
{
  std::int64_t sum = 0;
#ifdef VTP_MATRIX_WITH_MPI
  if(!m_mpi || !is_root())
    return 0;
  while(true)
  {
    int arrived = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status);
    if(!arrived)
      break;
    std::int64_t value = 0;
    MPI_Recv(&value, 1, MPI_INT64_T, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    m_rows_of_rank[static_cast<std::size_t>(status.MPI_SOURCE)] = value;
    if(status.MPI_TAG == tag_final_rows)
      m_final_of_rank[static_cast<std::size_t>(status.MPI_SOURCE)] = 1;
  }
  for(int r = 1; r < m_size; ++r)
    sum += m_rows_of_rank[static_cast<std::size_t>(r)];
#endif
  return sum;
}

void Job::wait_for_final_rows(const std::function<void(std::int64_t)>& tick)
{
#ifdef VTP_MATRIX_WITH_MPI
  if(!m_mpi || !is_root())
    return;
  while(true)
  {
    const std::int64_t others = other_rows();
    tick(others);
    bool all = true;
    for(int r = 1; r < m_size; ++r)
      all = all && m_final_of_rank[static_cast<std::size_t>(r)] != 0;
    if(all)
      return;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
#else
  (void)tick;
#endif
}

void Job::abort(int code)
{
#ifdef VTP_MATRIX_WITH_MPI
  if(m_mpi)
    MPI_Abort(MPI_COMM_WORLD, code);
#endif
  std::_Exit(code);
}

} // namespace vtp_matrix
