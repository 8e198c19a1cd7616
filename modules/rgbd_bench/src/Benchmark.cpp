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

#include "Runs.h"
#include "rgbd_app/AppConfig.h"
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
  std::vector<JobPath> outputs;
  for (const auto* name :
       {"results.md", "results.csv", "results_partial.md", "results_partial.csv"})
    outputs.push_back({results(p, name), std::string("[Benchmark] output_folder's ") + name});
  checkJobPaths(inputs, outputs);
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

/** <output_folder>/<stem>.md and .csv, each in full or not at all; logs their paths. */
void writeResults(const BenchmarkReport& report, const BenchmarkParams& p, const std::string& stem,
                  std::ostream& log) {
  StreamOutput markdown(results(p, stem + ".md"), "benchmark results");
  markdown.stream() << toMarkdown(report);
  markdown.commit();
  StreamOutput csv(results(p, stem + ".csv"), "benchmark results");
  csv.stream() << toCsv(report);
  csv.commit();
  if (report.partial.empty())
    log << "results: " << markdown.path() << std::endl;
  else
    log << "\npartial results (" << report.partial << "): " << markdown.path() << ", " << csv.path()
        << std::endl;
}

}  // namespace

std::map<std::string, std::string> quickBenchmark() {
  return {{"methods", "hybrid opencv_rgbd"},
          {"sim_far", "false"},
          {"sim_motions", "sweep"},
          {"max_frames", "60"},
          {"output_folder", "benchmark_quick"}};
}

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
  const auto seconds = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  try {
    bench::runAll(report.sequences, p, config_file, log, progress, report.runs);
  } catch (const Interrupted& e) {
    // the runs finished so far are results too: written under other names, marked partial
    report.partial = std::string(e.what()) + " after " + std::to_string(report.runs.size()) +
                     " of " + std::to_string(bench::runCount(report.sequences, p)) + " runs";
    report.seconds = seconds();
    if (report.runs.empty()) {
      log << "\n" << e.what() << " before the first run finished: no results written" << std::endl;
      throw;
    }
    // the tables then hold the sequences that ran (a row of "-" would read as failures)
    auto ran = report;
    ran.sequences.clear();
    for (const auto& seq : report.sequences)
      if (!seq.skip_reason.empty() ||
          std::any_of(report.runs.begin(), report.runs.end(),
                      [&](const BenchRun& r) { return r.sequence == seq.name; }))
        ran.sequences.push_back(seq);
    writeResults(ran, p, "results_partial", log);
    throw;
  }
  requireAResult(report.sequences, report.runs);
  report.figures = plotRealSequences(report, p, log);
  report.seconds = seconds();
  writeResults(report, p, "results", log);
  for (const auto* stale : {"results_partial.md", "results_partial.csv"})  // an earlier one's
    fs::remove(results(p, stale));
  return report;
}

}  // namespace hrgbd
