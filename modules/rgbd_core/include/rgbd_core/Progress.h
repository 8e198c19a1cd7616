#pragma once
/** \file Progress.h
 * One progress line for long loops (playback, benchmark, simulator, converter): items done, of
 * the total when known, rate and time left. On a terminal the line is redrawn in place; in a
 * file or pipe a whole line is written now and then, so logs show the progress too. */
#include <cstddef>
#include <functional>
#include <iosfwd>
#include <string>

namespace hrgbd {

/** Parameters of Progress. */
struct ProgressParams {
  std::string label;            //!< leads the line ("real/teddy hybrid"); "" = none
  std::string unit = "frames";  //!< what is counted
  std::size_t total = 0;        //!< [count] items in all; 0 = unknown (a live sensor)
  /** The stream is a terminal: one line redrawn with '\r'. Else whole lines (a file, a pipe). */
  bool terminal = false;
  double redraw_period = 0.25;  //!< [s] terminal: redrawn at most this often
  double log_period = 10;       //!< [s] not a terminal: a line after this long ...
  double log_fraction = 0.1;    //!< ... or after this share of the total, whichever comes first,
  double log_min_gap = 1;       //!< [s] ... but not sooner than this after the last line
};

/** The progress of one loop. The clock is injected (tests); by default steady_clock. */
class Progress {
 public:
  using Clock = std::function<double()>;  //!< [s] any monotonic origin

  Progress(std::ostream& out, ProgressParams params, Clock clock = {});
  /** `done` items so far; `detail` is added to the line ("12 not registered"). Writes the line
   * when due (ProgressParams). */
  void update(std::size_t done, const std::string& detail = "");
  /** Writes the final line (done, mean rate, time taken) and ends it. Once; later calls do
   * nothing. */
  void finish();
  /** The text of the line for `done` items after `seconds`, without '\r' or newline. */
  std::string text(std::size_t done, double seconds) const;

 private:
  void write(const std::string& line);

  std::ostream& m_out;
  ProgressParams m_params;
  Clock m_clock;
  double m_start = 0, m_last_line = 0;
  std::size_t m_done = 0, m_last_done = 0;
  std::string m_detail;
  std::size_t m_drawn_width = 0;  //!< terminal: length of the line on screen
  bool m_finished = false;
};

/** "4.4 s" (below 10 s), "12 s", "2 min 05 s", "1 h 02 min". */
std::string formatDuration(double seconds);

}  // namespace hrgbd
