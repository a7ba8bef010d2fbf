// vtp_distance_matrix: the progress line (rank 0 only).

#include "progress.h"
#include "job.h"
#include "tool_error.h"

#include <cmath>
#include <cstdio>
#include <string>

#include <unistd.h> // isatty

namespace vtp_matrix {
namespace {

std::string duration_text(double seconds)
{
  if(!std::isfinite(seconds))
    return "?";
  const long long s = static_cast<long long>(seconds + 0.5);
  char text[64];
  if(s >= 3600)
    std::snprintf(text, sizeof(text), "%lld h %02lld min", s / 3600, (s / 60) % 60);
  else if(s >= 60)
    std::snprintf(text, sizeof(text), "%lld min %02lld s", s / 60, s % 60);
  else
    std::snprintf(text, sizeof(text), "%lld s", s);
  return text;
}

} // namespace

Progress::Progress(bool enabled, std::int64_t total, std::int64_t done_before)
  : m_enabled(enabled), m_terminal(isatty(2) != 0), m_total(total), m_done_before(done_before),
    m_start(now_seconds())
{}

void Progress::update(std::int64_t done)
{
  if(!m_enabled || done == m_last_done)
    return;
  const double t = now_seconds();
  if(m_last_print >= 0. && t - m_last_print < 0.5)
    return;
  print(done, false);
}

void Progress::finish(std::int64_t done)
{
  if(!m_enabled)
    return;
  print(done, true);
}

void Progress::print(std::int64_t done, bool last)
{
  const double t = now_seconds();
  m_last_print = t;
  m_last_done = done;
  const double elapsed = t - m_start;
  const std::int64_t computed = done - m_done_before;
  const double rate = (elapsed > 0. && computed > 0) ? static_cast<double>(computed) / elapsed : 0.;
  const double percent = m_total > 0 ? 100. * static_cast<double>(done) / static_cast<double>(m_total) : 100.;
  char rate_text[32];
  std::snprintf(rate_text, sizeof(rate_text), rate >= 100. ? "%.0f" : rate >= 10. ? "%.1f" : "%.2f", rate);
  char line[256];
  int n;
  if(last)
    n = std::snprintf(line, sizeof(line), "%s: %lld/%lld rows (%.1f%%), %s rows/s, %s", program_name,
                      static_cast<long long>(done), static_cast<long long>(m_total), percent, rate_text,
                      duration_text(elapsed).c_str());
  else
    n = std::snprintf(line, sizeof(line), "%s: %lld/%lld rows (%.1f%%), %s rows/s, %s left", program_name,
                      static_cast<long long>(done), static_cast<long long>(m_total), percent, rate_text,
                      rate > 0. ? duration_text(static_cast<double>(m_total - done) / rate).c_str() : "?");
  if(n < 0)
    return;
  if(m_terminal)
  {
    // rewrite the line in place, blanking what is left of a longer previous line
    const int pad = m_last_width > n ? m_last_width - n : 0;
    std::fprintf(stderr, "\r%s%*s%s", line, pad, "", last ? "\n" : "");
    m_last_width = n;
  }
  else
    std::fprintf(stderr, "%s\n", line);
  std::fflush(stderr);
}

} // namespace vtp_matrix
