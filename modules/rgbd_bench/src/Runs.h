#pragma once
/** \file Runs.h (private to rgbd_bench)
 * The benchmark's runs: each sequence x method through runPlayback(), one line each with the
 * overall count and the time left (RunClock), the runs finished kept when an interrupt stops the
 * benchmark. */
#include <cstddef>
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

#include "rgbd_bench/Benchmark.h"

namespace hrgbd::bench {

/** The time left of a benchmark from the runs finished: each method's seconds per frame so far
 * (all methods' before its first run) times the frames of each run left (a sequence's count as
 * expected before the runs or from its first run; else the mean over the sequences known). */
class RunClock {
 public:
  /** A run on `sequence` plays `frames` frames (0 = not known). */
  void expect(const std::string& sequence, std::size_t frames);
  /** A run of `method` on `sequence` over `frames` frames took `seconds`. */
  void add(const std::string& sequence, const std::string& method, std::size_t frames,
           double seconds);
  /** [s] the runs `left` (sequence, method); negative when nothing is known yet. */
  double secondsLeft(const std::vector<std::pair<std::string, std::string>>& left) const;

 private:
  struct Sum {
    double seconds = 0;
    std::size_t frames = 0;
  };
  std::map<std::string, Sum> m_methods;
  Sum m_all;
  std::map<std::string, std::size_t> m_sequence_frames;
};

/** Every method on every sequence that is not skipped, on one core, each run appended to `runs`
 * as it finishes (an Interrupted thrown by a run leaves those finished there); a line per run on
 * `log`: "run 7 of 252: <sequence> <method> <figures>; 12 min left", flushed. */
void runAll(const std::vector<BenchSequence>& sequences, const BenchmarkParams& p,
            const std::string& config_file, std::ostream& log, bool progress,
            std::vector<BenchRun>& runs);

/** [count] the runs runAll() makes: methods x sequences that are not skipped. */
std::size_t runCount(const std::vector<BenchSequence>& sequences, const BenchmarkParams& p);

}  // namespace hrgbd::bench
