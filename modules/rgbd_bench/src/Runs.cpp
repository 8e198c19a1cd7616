#include "Runs.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <ostream>
#include <sstream>

#include "rgbd_app/AppConfig.h"
#include "rgbd_baselines/ThreadLimit.h"
#include "rgbd_core/Interrupt.h"
#include "rgbd_core/Progress.h"
#include "rgbd_io/openFrameSource.h"

namespace hrgbd::bench {
namespace fs = std::filesystem;

void RunClock::expect(const std::string& sequence, std::size_t frames) {
  if (frames > 0) m_sequence_frames[sequence] = frames;
}

void RunClock::add(const std::string& sequence, const std::string& method, std::size_t frames,
                   double seconds) {
  for (Sum* s : {&m_methods[method], &m_all}) s->seconds += seconds, s->frames += frames;
  if (frames > 0) m_sequence_frames.emplace(sequence, frames);
}

double RunClock::secondsLeft(const std::vector<std::pair<std::string, std::string>>& left) const {
  if (m_all.frames == 0 || m_sequence_frames.empty()) return -1;
  double mean_frames = 0;
  for (const auto& [name, frames] : m_sequence_frames) mean_frames += frames;
  mean_frames /= m_sequence_frames.size();
  double seconds = 0;
  for (const auto& [sequence, method] : left) {
    const auto m = m_methods.find(method);
    const Sum& rate = m != m_methods.end() && m->second.frames > 0 ? m->second : m_all;
    const auto f = m_sequence_frames.find(sequence);
    seconds += rate.seconds / rate.frames *
               (f != m_sequence_frames.end() ? static_cast<double>(f->second) : mean_frames);
  }
  return seconds;
}

namespace {

/** One sequence x method through runPlayback(), writing <traj_dir>/<sequence>__<method>.txt
 * and .csv. An error is recorded in the run, not thrown. */
BenchRun runOne(const BenchSequence& seq, const std::string& method, const std::string& config_file,
                const fs::path& traj_dir, const BenchmarkParams& p, const std::string& label,
                bool progress) {
  BenchRun run{seq.name, method, {}, ""};
  auto stem = seq.name + "__" + method;
  std::replace(stem.begin(), stem.end(), '/', '_');
  PlaybackOptions opt;
  opt.config = config_file;
  opt.input = seq.input;
  opt.trajectory = (traj_dir / (stem + ".txt")).string();
  opt.csv = (traj_dir / (stem + ".csv")).string();
  opt.method = method;
  if (method == "hybrid_slam") opt.method = "hybrid", opt.slam = true;
  if (method == "hybrid_odometry") opt.method = "hybrid", opt.no_slam = true;
  const std::string paper = "_paper";
  if (method.size() > paper.size() &&
      method.compare(method.size() - paper.size(), paper.size(), paper) == 0)
    opt.method = method.substr(0, method.size() - paper.size()), opt.config = p.paper_config;
  if (method == "hybrid_realtime") opt.method = "hybrid", opt.realtime = true;
  opt.max_frames = p.max_frames;
  opt.progress = progress;
  opt.progress_label = label;
  opt.ini_outputs = false;
  std::ostringstream playback_log;
  try {
    run.summary = runPlayback(opt, playback_log);
  } catch (const Interrupted&) {
    throw;  // not this run's error: the benchmark stops
  } catch (const std::exception& e) {
    run.error = e.what();
  }
  return run;
}

/** One line per run: its number, registered frames, ATE, time per frame, or the error, and the
 * benchmark's time left (`seconds_left` < 0: not known, or none left). */
void logRun(const BenchRun& run, std::size_t number, std::size_t count, double seconds_left,
            std::ostream& log) {
  log << "run " << number << " of " << count << ": " << std::left << std::setw(36) << run.sequence
      << " " << std::setw(16) << run.method << std::right;
  if (!run.error.empty())
    log << "error: " << run.error;
  else
    log << std::setw(4) << run.summary.registered << "/" << std::setw(4) << std::left
        << run.summary.frames << std::right << " registered, ATE "
        << (run.summary.evaluated ? std::to_string(run.summary.eval.ate_mean_unaligned) : "-")
        << " m, " << std::fixed << std::setprecision(1) << run.summary.median_ms << " ms/frame";
  if (number < count && seconds_left >= 0) log << "; " << formatDuration(seconds_left) << " left";
  log << std::endl;  // each line as it comes, even into a pipe
}

/** [count] frames a run on `seq` plays (at most [Benchmark] max_frames); 0 = not known. */
std::size_t frameCount(const BenchSequence& seq, const BenchmarkParams& p,
                       const mrpt::config::CConfigFileBase& cfg) {
  try {
    return openFrameSource(seq.input, cfg)->frameCount(static_cast<std::size_t>(p.max_frames));
  } catch (const std::exception&) {  // the run says what is wrong with the input
    return 0;
  }
}

}  // namespace

std::size_t runCount(const std::vector<BenchSequence>& sequences, const BenchmarkParams& p) {
  std::size_t n = 0;
  for (const auto& seq : sequences) n += seq.skip_reason.empty() ? p.methods.size() : 0;
  return n;
}

void runAll(const std::vector<BenchSequence>& sequences, const BenchmarkParams& p,
            const std::string& config_file, std::ostream& log, bool progress,
            std::vector<BenchRun>& runs) {
  // Every method on one core, as the targets are stated (OpenCV and Open3D would use both
  // otherwise); the caller's setting is restored however this returns.
  const ThreadLimit one_thread(1);
  const auto traj_dir = fs::path(p.output_folder) / "trajectories";
  fs::create_directories(traj_dir);
  std::vector<std::pair<std::string, std::string>> left;  // (sequence, method), in run order
  for (const auto& seq : sequences) {
    if (!seq.skip_reason.empty()) {
      log << seq.name << ": skipped (" << seq.skip_reason << ")" << std::endl;
      continue;
    }
    for (const auto& method : p.methods) left.emplace_back(seq.name, method);
  }
  const std::size_t count = left.size();
  RunClock clock;
  // the frames of each sequence, counted before the runs (a real one may run ten times as long
  // as a simulated one)
  const auto cfg = loadChecked(config_file);
  for (const auto& seq : sequences)
    if (seq.skip_reason.empty()) clock.expect(seq.name, frameCount(seq, p, *cfg));
  std::reverse(left.begin(), left.end());  // the next run at the back
  for (const auto& seq : sequences) {
    if (!seq.skip_reason.empty()) continue;
    for (const auto& method : p.methods) {
      const auto number = runs.size() + 1;
      const auto label = "run " + std::to_string(number) + "/" + std::to_string(count) + " " +
                         seq.name + " " + method;
      const auto start = std::chrono::steady_clock::now();
      runs.push_back(runOne(seq, method, config_file, traj_dir, p, label, progress));
      const auto& s = runs.back().summary;
      clock.add(seq.name, method, s.frames + s.dropped,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      left.pop_back();
      logRun(runs.back(), number, count, clock.secondsLeft(left), log);
    }
  }
}

}  // namespace hrgbd::bench
