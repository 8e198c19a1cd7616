// The benchmark report: markdown tables and CSV rows from the runs.
#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <map>
#include <optional>
#include <sstream>

#include "ReportParts.h"
#include "rgbd_bench/Benchmark.h"

namespace hrgbd {
namespace report {

using Value = std::function<std::optional<double>(const BenchRun&)>;

const BenchRun* findRun(const BenchmarkReport& r, const std::string& seq, const std::string& m) {
  for (const auto& run : r.runs)
    if (run.sequence == seq && run.method == m) return &run;
  return nullptr;
}

std::optional<double> evaluated(const BenchRun& r, double EvalResult::*field) {
  if (!r.error.empty() || !r.summary.evaluated) return std::nullopt;
  const bool rpe = field == &EvalResult::rpe_trans || field == &EvalResult::rpe_rot;
  if (rpe && r.summary.eval.rpe_pairs == 0) return std::nullopt;  // no interval without a gap
  return r.summary.eval.*field;
}

std::string fmt(std::optional<double> v, int precision) {
  if (!v || !std::isfinite(*v)) return "-";
  std::ostringstream s;
  s << std::fixed << std::setprecision(precision) << *v;
  return s.str();
}

bool isSimulated(const BenchSequence& s) { return !s.scene_type.empty(); }

}  // namespace report

namespace {

using report::evaluated;
using report::findRun;
using report::fmt;
using report::isSimulated;
using report::Value;

/** `text` as one CSV field: quoted, inner quotes doubled. */
std::string csvField(const std::string& text) {
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// Mean of `value` over the run sequences selected by `pick`; nullopt when none has a value.
std::optional<double> mean(const BenchmarkReport& r, const std::string& method, const Value& value,
                           const std::function<bool(const BenchSequence&)>& pick) {
  double sum = 0;
  int n = 0;
  for (const auto& s : r.sequences) {
    const auto* run = findRun(r, s.name, method);
    if (!pick(s) || !run) continue;
    if (const auto v = value(*run)) sum += *v, ++n;
  }
  if (n == 0) return std::nullopt;
  return sum / n;
}

// Rows: sequences; columns: methods; then the simulated and real averages.
std::string metricTable(const BenchmarkReport& r, const Value& value, int precision) {
  std::ostringstream out;
  out << "| sequence |";
  for (const auto& m : r.methods) out << " " << m << " |";
  out << "\n|---|";
  for (std::size_t i = 0; i < r.methods.size(); ++i) out << "---:|";
  out << "\n";
  for (const auto& s : r.sequences) {
    if (!s.skip_reason.empty()) continue;
    out << "| " << s.name << " |";
    for (const auto& m : r.methods) {
      const auto* run = findRun(r, s.name, m);
      out << " " << (run ? fmt(value(*run), precision) : "-") << " |";
    }
    out << "\n";
  }
  for (const bool sim : {true, false}) {
    out << "| **average, " << (sim ? "simulated" : "real") << "** |";
    for (const auto& m : r.methods)
      out << " "
          << fmt(mean(r, m, value,
                      [&](const BenchSequence& s) {
                        return s.skip_reason.empty() && isSimulated(s) == sim;
                      }),
                 precision)
          << " |";
    out << "\n";
  }
  return out.str();
}

// The benchmark's targets, computed from the runs; each line says met or missed with the figures.
std::string targets(const BenchmarkReport& r) {
  std::ostringstream out;
  const auto has = [&](const std::string& m) {
    return std::find(r.methods.begin(), r.methods.end(), m) != r.methods.end();
  };
  const auto verdict = [](bool ok) { return ok ? "**met**" : "**missed**"; };
  out << report::timeTargets(r);
  const Value ate = [](const BenchRun& x) { return evaluated(x, &EvalResult::ate_mean_unaligned); };
  // The paper's switch (Table I): the hybrid no worse than the better of its two single-cue paths,
  // all three as published (paper_config).
  if (has("hybrid_paper") && has("rgb_only_paper") && has("depth_only_paper")) {
    std::vector<std::string> types;
    for (const auto& s : r.sequences)
      if (s.skip_reason.empty()) {
        const auto type = isSimulated(s) ? s.scene_type : s.name;
        if (std::find(types.begin(), types.end(), type) == types.end()) types.push_back(type);
      }
    for (const auto& type : types) {
      const auto pick = [&](const BenchSequence& s) {
        return s.skip_reason.empty() && (isSimulated(s) ? s.scene_type : s.name) == type;
      };
      const auto h = mean(r, "hybrid_paper", ate, pick), a = mean(r, "rgb_only_paper", ate, pick),
                 b = mean(r, "depth_only_paper", ate, pick);
      if (!h || !a || !b) continue;
      const double best = std::min(*a, *b);
      out << "- " << type << ", the paper's pipeline: hybrid " << fmt(h, 4)
          << " m vs best of RGB-only / depth-only " << fmt(best, 4)
          << " m (target: no worse, within 5 %): " << verdict(*h <= 1.05 * best) << "\n";
    }
  }
  for (const bool sim : {true, false}) {
    const auto pick = [&](const BenchSequence& s) {
      return s.skip_reason.empty() && isSimulated(s) == sim;
    };
    const auto h = mean(r, "hybrid", ate, pick);
    if (!h) continue;
    for (const auto* peer :
         {"opencv_rgbd", "opencv_icp", "opencv_rgbd_icp", "open3d_color", "open3d_hybrid"}) {
      const auto p = mean(r, peer, ate, pick);
      if (!has(peer) || !p) continue;
      out << "- " << (sim ? "simulated" : "real") << " average: hybrid " << fmt(h, 4) << " m vs "
          << peer << " " << fmt(p, 4) << " m (target: better): " << verdict(*h < *p) << "\n";
    }
  }
  return out.str();
}

}  // namespace

std::string toMarkdown(const BenchmarkReport& r) {
  std::ostringstream out;
  out << "# Benchmark results" << (r.partial.empty() ? "" : " (PARTIAL)") << "\n\n";
  if (!r.partial.empty())
    out << "**Partial results: " << r.partial
        << "**; the runs not made are missing from the tables, and there are no figures.\n\n";
  out << "- machine: " << r.machine << "; every method on one thread\n"
      << "- date: " << r.date << "; configuration: `" << r.config_file << "`; wall time "
      << std::fixed << std::setprecision(0) << r.seconds << " s\n"
      << "- ATE is evaluated against each sequence's ground truth; frames a method cannot "
         "register keep a constant-velocity pose and count in the ATE.\n\n";
  out << "## Mean ATE, unaligned [m] (the paper's metric, eq. 10; Tables I and II)\n\n"
      << metricTable(
             r, [](const BenchRun& x) { return evaluated(x, &EvalResult::ate_mean_unaligned); }, 4)
      << "\n## ATE RMSE after rigid alignment [m] (TUM tool)\n\n"
      << metricTable(
             r, [](const BenchRun& x) { return evaluated(x, &EvalResult::ate_rmse); }, 4)
      << "\n## RPE translation [m/s] (RMSE over 1 s, or the whole sequence if shorter)\n\n"
      << metricTable(
             r, [](const BenchRun& x) { return evaluated(x, &EvalResult::rpe_trans); }, 4)
      << "\n## RPE rotation [deg/s]\n\n"
      << metricTable(
             r, [](const BenchRun& x) { return evaluated(x, &EvalResult::rpe_rot); }, 2)
      << "\n## Frames not registered (failures)\n\n"
      << metricTable(
             r,
             [](const BenchRun& x) -> std::optional<double> {
               if (!x.error.empty()) return std::nullopt;
               return static_cast<double>(x.summary.frames - x.summary.registered);
             },
             0)
      << "\n## Time per frame, median [ms] (Table III)\n\n"
      << metricTable(
             r,
             [](const BenchRun& x) -> std::optional<double> {
               if (!x.error.empty()) return std::nullopt;
               return x.summary.median_ms;
             },
             1)
      << "\n## Time per frame over all frames, and the paths' shares\n\n"
      << "Whole tracking (prepare + features + matching + estimation + refinement) of every frame "
         "of every sequence; each path is the sparse path that ran and, after `+dense`, the "
         "dense refinement's start (none: the sparse fit; `prediction`: the motion prediction; "
         "`refused`: ran, result not taken).\n\n"
      << report::timingTable(r) << "\n## Time per stage, mean over all frames [ms]\n\n"
      << report::stageTable(r);
  if (std::find(r.methods.begin(), r.methods.end(), "hybrid_realtime") != r.methods.end())
    out << "\n## Real-time playback (frames on their time stamps, late ones dropped)\n\n"
        << report::realtimeTable(r);
  out << "\n## Targets\n\n" << targets(r);
  std::ostringstream problems;
  for (const auto& s : r.sequences)
    if (!s.skip_reason.empty())
      problems << "- " << s.name << ": skipped, " << s.skip_reason << "\n";
  for (const auto& run : r.runs)
    if (!run.error.empty())
      problems << "- " << run.sequence << " / " << run.method << ": error, " << run.error << "\n";
  if (!problems.str().empty()) out << "\n## Skipped sequences and errors\n\n" << problems.str();
  if (!r.figures.empty()) {
    out << "\n## Figures of the real sequences\n\n"
        << "Every method's estimate (each aligned to the ground truth), the position error and "
           "the RPE over time.\n";
    for (const auto& f : r.figures) {
      out << "\n### " << f.sequence << "\n\n";
      if (f.error.empty())
        out << "[![" << f.sequence << "](" << f.file << ")](" << f.file << ")\n";
      else
        out << "no figure: " << f.error << "\n";
    }
  }
  return out.str();
}

std::string toCsv(const BenchmarkReport& r) {
  std::ostringstream out;
  out << "sequence,method,frames,registered,ate_mean_unaligned,ate_rmse,rpe_trans,rpe_rot,"
         "end_to_start_trans,end_to_start_rot,ms_median,ms_p95,dropped,error\n";
  for (const auto& run : r.runs) {
    const auto& s = run.summary;
    auto v = [&](double EvalResult::*f) { return fmt(evaluated(run, f), 6); };
    out << run.sequence << "," << run.method << "," << s.frames << "," << s.registered << ","
        << v(&EvalResult::ate_mean_unaligned) << "," << v(&EvalResult::ate_rmse) << ","
        << v(&EvalResult::rpe_trans) << "," << v(&EvalResult::rpe_rot) << ","
        << v(&EvalResult::end_to_start_trans) << "," << v(&EvalResult::end_to_start_rot) << ","
        << std::fixed << std::setprecision(3) << s.median_ms << "," << s.p95_ms << "," << s.dropped
        << "," << csvField(run.error) << "\n";
  }
  return out.str();
}

}  // namespace hrgbd
