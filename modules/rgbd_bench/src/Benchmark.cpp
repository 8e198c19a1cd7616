#include "rgbd_bench/Benchmark.h"

#include <mrpt/config/CConfigFileMemory.h>
#include <sys/utsname.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <thread>

#include "rgbd_app/AppConfig.h"
#include "rgbd_baselines/ThreadLimit.h"
#include "rgbd_core/Config.h"
#include "rgbd_core/Interrupt.h"
#include "rgbd_core/JobPaths.h"
#include "rgbd_core/OutputFile.h"
#include "rgbd_core/TextFile.h"
#include "rgbd_eval/EvalPlot.h"
#include "rgbd_io/RawlogSource.h"
#include "rgbd_sim/Scene.h"
#include "rgbd_sim/Simulator.h"

namespace hrgbd {
namespace fs = std::filesystem;

namespace {

// "fr1_xyz_groundtruth_per_rgb_frame.txt" -> "fr1_xyz"
std::string motionName(const std::string& motion) {
  if (sim::isProceduralMotion(motion)) return motion;
  const auto stem = fs::path(motion).stem().string();
  return stem.substr(0, stem.find("_groundtruth"));
}

std::string machineDescription() {
  std::string cpu = "unknown CPU";
  std::ifstream info("/proc/cpuinfo");
  for (std::string line; std::getline(info, line);)
    if (line.rfind("model name", 0) == 0) {
      cpu = line.substr(line.find(':') + 2);
      break;
    }
  utsname u{};
  uname(&u);
  return cpu + ", " + std::to_string(std::thread::hardware_concurrency()) + " cores, " + u.sysname +
         " " + u.release + " " + u.machine;
}

std::string today() {
  const auto t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M", std::localtime(&t));
  return buf;
}

}  // namespace

std::vector<BenchSequence> prepareSequences(const BenchmarkParams& p,
                                            const std::vector<std::string>& extra,
                                            std::ostream& log) {
  std::vector<BenchSequence> out;
  fs::create_directories(p.cache_folder);
  for (const auto& scene : p.sim_scenes) {
    const bool has_far =
        p.sim_far && (scene == "texture" || scene == "structure" || scene == "structure_texture");
    for (const bool far : {false, true}) {
      if (far && !has_far) continue;
      for (const auto& motion : p.sim_motions) {
        const auto variant = scene + (far ? "_far" : "_near");
        BenchSequence seq{"sim/" + variant + "/" + motionName(motion), "", scene, ""};
        seq.input = (fs::path(p.cache_folder) /
                     (variant + "_" + motionName(motion) + "_n" + std::to_string(p.sim_frames) +
                      "_s" + std::to_string(p.sim_seed) + ".rawlog"))
                        .string();
        if (!sim::isProceduralMotion(motion) && !fs::exists(motion)) {
          seq.skip_reason = "motion file not found: " + motion;
        } else if (!fs::exists(seq.input)) {
          sim::SimParams sp;
          sp.scene = scene;
          sp.far = far;
          sp.frames = p.sim_frames;
          sp.seed = p.sim_seed;
          sp.motion = motion;
          const auto r = sim::simulate(sp, {seq.input, "", ImageStorage::ExternalJpeg, ""});
          log << "rendered " << seq.name << ": " << r.frames << " frames, " << std::fixed
              << std::setprecision(1) << 1000.0 / r.ms_per_frame << " frames/s\n";
        }
        out.push_back(seq);
      }
    }
  }
  auto addReal = [&](const std::string& prefix, const std::string& path) {
    BenchSequence seq{prefix + fs::path(path).filename().replace_extension().string(), path, "",
                      ""};
    if (!fs::exists(path)) seq.skip_reason = "not found: " + path;
    out.push_back(seq);
  };
  for (const auto& r : p.real_sequences) addReal("real/", r);
  for (const auto& e : extra) addReal("given/", e);
  return out;
}

std::vector<std::string> benchmarkMethods() {
  auto names = enumNameList<Method>();
  names.push_back("hybrid_slam");
  names.push_back("hybrid_odometry");
  names.push_back("hybrid_paper");
  names.push_back("rgb_only_paper");
  names.push_back("depth_only_paper");
  names.push_back("hybrid_realtime");
  return names;
}

namespace {

/** [Benchmark] from `config_file` with `overrides` (key -> value) over its keys, its paths
 * resolved against the file's folder. */
BenchmarkParams loadBenchmarkParams(const std::string& config_file,
                                    const std::map<std::string, std::string>& overrides) {
  const auto file = loadChecked(config_file);
  // the section's keys copied to memory and overridden there (a CConfigFile written to would
  // write itself back to the file)
  mrpt::config::CConfigFileMemory cfg;
  std::vector<std::string> keys;
  file->getAllKeys("Benchmark", keys);
  for (const auto& key : keys) cfg.write("Benchmark", key, file->read_string("Benchmark", key, ""));
  for (const auto& [key, value] : overrides) cfg.write("Benchmark", key, value);
  BenchmarkParams p;
  p.loadFromConfigFile(cfg, "Benchmark");
  const auto base = iniFolder(config_file);
  p.cache_folder = resolvePath(base, p.cache_folder);
  p.output_folder = resolvePath(base, p.output_folder);
  p.paper_config = resolvePath(base, p.paper_config);
  for (auto& m : p.sim_motions)
    if (!sim::isProceduralMotion(m)) m = resolvePath(base, m);
  for (auto& r : p.real_sequences) r = resolvePath(base, r);
  return p;
}

/** One sequence x method through runPlayback(), writing <traj_dir>/<sequence>__<method>.txt
 * and .csv. An error is recorded in the run, not thrown. */
BenchRun runOne(const BenchSequence& seq, const std::string& method, const std::string& config_file,
                const fs::path& traj_dir, const BenchmarkParams& p, bool progress) {
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
  opt.progress_label = seq.name + " " + method;
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

/** One line per run: registered frames, ATE, time per frame, or the error. */
void logRun(const BenchRun& run, std::ostream& log) {
  log << std::left << std::setw(36) << run.sequence << std::setw(16) << run.method << std::right;
  if (!run.error.empty())
    log << "error: " << run.error << "\n";
  else
    log << std::setw(4) << run.summary.registered << "/" << std::setw(4) << std::left
        << run.summary.frames << std::right << " registered, ATE "
        << (run.summary.evaluated ? std::to_string(run.summary.eval.ate_mean_unaligned) : "-")
        << " m, " << std::fixed << std::setprecision(1) << run.summary.median_ms << " ms/frame\n";
  log.flush();
}

/** Every method on every sequence that is not skipped, on one core. */
std::vector<BenchRun> runAll(const std::vector<BenchSequence>& sequences, const BenchmarkParams& p,
                             const std::string& config_file, std::ostream& log, bool progress) {
  // Every method on one core, as the targets are stated (OpenCV and Open3D would use both
  // otherwise); the caller's setting is restored however this returns.
  const ThreadLimit one_thread(1);
  const auto traj_dir = fs::path(p.output_folder) / "trajectories";
  fs::create_directories(traj_dir);
  std::vector<BenchRun> runs;
  for (const auto& seq : sequences) {
    if (!seq.skip_reason.empty()) {
      log << seq.name << ": skipped (" << seq.skip_reason << ")\n";
      continue;
    }
    for (const auto& method : p.methods) {
      runs.push_back(runOne(seq, method, config_file, traj_dir, p, progress));
      logRun(runs.back(), log);
    }
  }
  return runs;
}

/** Throws when no run succeeded: there are no results to write (they were written empty, and
 * the benchmark exited 0). Names why: no sequence, every sequence skipped, every run failed. */
void requireAResult(const std::vector<BenchSequence>& sequences,
                    const std::vector<BenchRun>& runs) {
  for (const auto& run : runs)
    if (run.error.empty()) return;
  std::string why;
  if (sequences.empty())
    why = "no sequence: [Benchmark] sim_scenes and real_sequences are empty and none was given";
  else if (runs.empty())
    for (const auto& seq : sequences)
      why += (why.empty() ? "every sequence was skipped: " : "; ") + seq.name + " (" +
             (seq.skip_reason.empty() ? "no method" : seq.skip_reason) + ")";
  else
    why = "every run failed; the first, " + runs[0].sequence + " " + runs[0].method + ": " +
          runs[0].error;
  throw std::runtime_error("no benchmark result: " + why + "; no results written");
}

/** <output_folder>/<name>. */
std::string results(const BenchmarkParams& p, const std::string& name) {
  return (fs::path(p.output_folder) / name).string();
}

/** Refuses results files that would overwrite an input: the configuration file, a motion file,
 * a real sequence's rawlog, lists or ground truth (checkJobPaths()). Each run's trajectory and
 * CSV are checked by its playback. */
void checkResultPaths(const BenchmarkParams& p, const std::string& config_file,
                      const std::vector<std::string>& extra) {
  std::vector<JobPath> inputs{{config_file, "the configuration file (--config)"}};
  for (const auto& m : p.sim_motions)
    if (!sim::isProceduralMotion(m)) inputs.push_back({m, "[Benchmark] sim_motions file"});
  auto sequence = [&](const std::string& path, const std::string& name) {
    if (fs::is_directory(path)) {
      for (const auto* list : {"rgb.txt", "depth.txt", "groundtruth.txt"})
        inputs.push_back({(fs::path(path) / list).string(), name + "'s " + list});
    } else {
      inputs.push_back({path, name});
      inputs.push_back({groundTruthPathFor(path), name + "'s ground truth"});
    }
  };
  for (const auto& r : p.real_sequences) sequence(r, "[Benchmark] real_sequences entry");
  for (const auto& e : extra) sequence(e, "the sequence given on the command line");
  checkJobPaths(inputs, {{results(p, "results.md"), "[Benchmark] output_folder's results.md"},
                         {results(p, "results.csv"), "[Benchmark] output_folder's results.csv"}});
}

/** One figure per real sequence that ran: every evaluated method against its ground truth. */
std::vector<BenchFigure> plotRealSequences(const BenchmarkReport& report, const BenchmarkParams& p,
                                           std::ostream& log) {
  std::vector<BenchFigure> figures;
  for (const auto& seq : report.sequences) {
    if (!seq.scene_type.empty() || !seq.skip_reason.empty()) continue;
    auto stem = seq.name;
    std::replace(stem.begin(), stem.end(), '/', '_');
    BenchFigure fig{seq.name, "plots/" + stem + ".png", ""};
    std::vector<PlotSeries> series;
    for (const auto& run : report.runs)
      if (run.sequence == seq.name && run.error.empty() && run.summary.evaluated)
        series.push_back({run.method, &run.summary.eval});
    try {
      if (series.empty()) throw std::runtime_error("no method was evaluated");
      fs::create_directories(fs::path(p.output_folder) / "plots");
      PlotParams pp;
      pp.title = seq.name + ": every method against the ground truth";
      plotEvaluations(series, results(p, fig.file), pp);
      log << "figure: " << results(p, fig.file) << "\n";
    } catch (const std::exception& e) {
      fig.error = e.what();
      log << seq.name << ": no figure: " << fig.error << "\n";
    }
    figures.push_back(fig);
  }
  return figures;
}

}  // namespace

BenchmarkReport runBenchmark(const std::string& config_file, const std::vector<std::string>& extra,
                             std::ostream& log, bool progress,
                             const std::map<std::string, std::string>& overrides) {
  const auto start = std::chrono::steady_clock::now();
  // every run reads the file again (runPlayback()): a pipe would give the first run alone
  if (!config_file.empty())
    requireRegularFile(config_file, "config file", "the benchmark reads it once per run");
  const auto p = loadBenchmarkParams(config_file, overrides);
  checkResultPaths(p, config_file, extra);
  BenchmarkReport report;
  report.config_file = config_file;
  report.methods = p.methods;
  report.machine = machineDescription();
  report.date = today();
  report.sequences = prepareSequences(p, extra, log);
  report.runs = runAll(report.sequences, p, config_file, log, progress);
  requireAResult(report.sequences, report.runs);
  report.figures = plotRealSequences(report, p, log);
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  StreamOutput markdown(results(p, "results.md"), "benchmark results");
  markdown.stream() << toMarkdown(report);
  markdown.commit();
  StreamOutput csv(results(p, "results.csv"), "benchmark results");
  csv.stream() << toCsv(report);
  csv.commit();
  log << "results: " << markdown.path() << "\n";
  return report;
}

}  // namespace hrgbd
