#include "rgbd_core/Progress.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ostream>

namespace hrgbd {
namespace {

double steadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

std::string formatDuration(double seconds) {
  seconds = std::max(0.0, seconds);
  const long s = std::lround(seconds);
  char buf[64];
  if (seconds < 9.95)
    std::snprintf(buf, sizeof buf, "%.1f s", seconds);
  else if (s < 60)
    std::snprintf(buf, sizeof buf, "%ld s", s);
  else if (s < 3600)
    std::snprintf(buf, sizeof buf, "%ld min %02ld s", s / 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%ld h %02ld min", s / 3600, (s % 3600) / 60);
  return buf;
}

Progress::Progress(std::ostream& out, ProgressParams params, Clock clock)
    : m_out(out), m_params(std::move(params)), m_clock(clock ? std::move(clock) : steadySeconds) {
  m_start = m_last_line = m_clock();
}

std::string Progress::text(std::size_t done, double seconds) const {
  std::string line = m_params.label.empty() ? "" : m_params.label + ": ";
  char buf[128];
  const std::size_t total = m_params.total;
  if (total > 0)
    std::snprintf(buf, sizeof buf, "%zu/%zu %s (%d%%)", done, total, m_params.unit.c_str(),
                  static_cast<int>(100.0 * std::min(done, total) / total));
  else
    std::snprintf(buf, sizeof buf, "%zu %s", done, m_params.unit.c_str());
  line += buf;
  if (done > 0 && seconds > 0) {
    const double rate = done / seconds;
    std::snprintf(buf, sizeof buf, ", %.1f %s/s", rate, m_params.unit.c_str());
    line += buf;
    if (total > done)
      line += ", " + formatDuration((total - done) / rate) + " left" +
              (m_params.after.empty() ? "" : " + " + m_params.after);
  }
  if (!m_detail.empty()) line += ", " + m_detail;
  return line;
}

void Progress::write(const std::string& line) {
  if (m_params.terminal) {
    // Redrawn in place; spaces clear what a longer previous line left.
    const auto pad = m_drawn_width > line.size() ? m_drawn_width - line.size() : 0;
    m_out << '\r' << line << std::string(pad, ' ') << std::flush;
    m_drawn_width = std::max(m_drawn_width, line.size());
  } else {
    m_out << line << '\n' << std::flush;
  }
}

void Progress::update(std::size_t done, const std::string& detail) {
  if (m_finished) return;
  m_done = done;
  m_detail = detail;
  const double now = m_clock();
  bool due;
  if (m_params.terminal) {
    due = now - m_last_line >= m_params.redraw_period || m_last_done == 0;
  } else {
    const std::size_t step =
        static_cast<std::size_t>(std::ceil(m_params.log_fraction * m_params.total));
    const bool share = m_params.total > 0 && step > 0 && done / step > m_last_done / step &&
                       done < m_params.total && now - m_last_line >= m_params.log_min_gap;
    due = share || now - m_last_line >= m_params.log_period;
  }
  if (!due) return;
  write(text(done, now - m_start));
  m_last_line = now;
  m_last_done = done;
}

void Progress::finish() {
  if (m_finished) return;
  m_finished = true;
  const double seconds = m_clock() - m_start;
  std::string line = m_params.label.empty() ? "" : m_params.label + ": ";
  char buf[128];
  std::snprintf(buf, sizeof buf, "%zu %s in %s", m_done, m_params.unit.c_str(),
                formatDuration(seconds).c_str());
  line += buf;
  if (m_done > 0 && seconds > 0) {
    std::snprintf(buf, sizeof buf, ", %.1f %s/s", m_done / seconds, m_params.unit.c_str());
    line += buf;
  }
  if (!m_detail.empty()) line += ", " + m_detail;
  write(line);
  if (m_params.terminal) m_out << '\n' << std::flush;
}

StagedProgress::StagedProgress(std::ostream& out, bool terminal, Progress::Clock clock)
    : m_out(out), m_terminal(terminal), m_clock(std::move(clock)) {}

void StagedProgress::update(const std::string& stage, const std::string& unit, std::size_t done,
                            std::size_t total) {
  if (!m_progress || stage != m_stage) {
    finish();
    ProgressParams p;
    p.label = stage;
    p.unit = unit;
    p.total = total;
    p.terminal = m_terminal;
    m_progress = std::make_unique<Progress>(m_out, p, m_clock);
    m_stage = stage;
  }
  m_progress->update(done);
}

void StagedProgress::finish() {
  if (m_progress) m_progress->finish();
}

void timedStep(std::ostream& out, const std::string& what, const std::function<void()>& step,
               const Progress::Clock& clock) {
  const Progress::Clock now = clock ? clock : Progress::Clock(steadySeconds);
  out << what << " ... " << std::flush;
  const double start = now();
  try {
    step();
  } catch (...) {
    out << "failed\n" << std::flush;
    throw;
  }
  out << formatDuration(now() - start) << "\n" << std::flush;
}

}  // namespace hrgbd
