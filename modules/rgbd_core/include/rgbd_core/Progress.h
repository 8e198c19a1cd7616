#pragma once
/** \file Progress.h
 * One progress line for long loops (playback, benchmark, simulator, converter): items done, of
 * the total when known, rate and time left. On a terminal the line is redrawn in place; in a
 * file or pipe a whole line is written now and then, so logs show the progress too. Also: the
 * progress of work in stages (StagedProgress) and the timed steps that follow a loop
 * (timedStep(): final optimisation, map, outputs). */
#include <cstddef>
#include <functional>
#include <iosfwd>
#include <memory>
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
  /** What follows the last item ("final steps"): the time left is then that of the items only,
   * and the line says so ("12 s left + final steps"); "" = nothing follows. */
  std::string after;
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

/** Work in stages, one progress line each ("seeding: 400/1000 words ..."): a stage's line is
 * finished when the next stage begins, and by finish(). */
class StagedProgress {
 public:
  /** `terminal` as ProgressParams::terminal; `clock` as Progress's. */
  StagedProgress(std::ostream& out, bool terminal, Progress::Clock clock = {});
  /** `done` of `total` `unit` in stage `stage`; a new stage finishes the line of the last. */
  void update(const std::string& stage, const std::string& unit, std::size_t done,
              std::size_t total);
  /** Finishes the line of the current stage, if any. */
  void finish();

 private:
  std::ostream& m_out;
  bool m_terminal;
  Progress::Clock m_clock;
  std::string m_stage;
  std::unique_ptr<Progress> m_progress;
};

/** One step after a loop (final optimisation, writing an output): writes `what` and " ... "
 * (flushed, so the line shows while the step runs), runs `step`, then ends the line with the
 * step's time ("map (PLY, 120 points): map.ply ... 1.2 s"). When `step` throws, the line ends
 * with "failed" and the exception propagates. `clock` as Progress's. */
void timedStep(std::ostream& out, const std::string& what, const std::function<void()>& step,
               const Progress::Clock& clock = {});

/** "4.4 s" (below 10 s), "12 s", "2 min 05 s", "1 h 02 min". */
std::string formatDuration(double seconds);

}  // namespace hrgbd
