// The report's time figures: every frame counted under its typed path, the tables of time per
// frame, per stage and of the real-time playback, and the target lines on them.
#include <algorithm>
#include <iomanip>
#include <map>
#include <sstream>

#include "ReportParts.h"

namespace hrgbd::report {
namespace {

// Every frame of `method`'s runs (on the sequences `pick` selects): whole-tracking times, and
// per typed path (toString(FramePath)).
struct MethodTotals {
  std::vector<double> ms;
  std::map<std::string, std::vector<double>> ms_by_path;
  StageTimes sum;  //!< per stage, summed over the frames
  std::size_t frames = 0, registered = 0, dropped = 0;
};

MethodTotals totals(const BenchmarkReport& r, const std::string& method,
                    const std::function<bool(const BenchSequence&)>& pick) {
  MethodTotals t;
  for (const auto& s : r.sequences) {
    const auto* run = findRun(r, s.name, method);
    if (!run || !run->error.empty() || !pick(s)) continue;
    for (const auto& f : run->summary.results) {
      t.ms.push_back(f.ms.total);
      t.ms_by_path[toString(f.path)].push_back(f.ms.total);
      t.sum += f.ms;
      ++t.frames;
      t.registered += f.registered();
    }
    t.dropped += run->summary.dropped;
  }
  return t;
}

MethodTotals totals(const BenchmarkReport& r, const std::string& method) {
  return totals(r, method, [](const BenchSequence&) { return true; });
}

std::string pct(std::size_t n, std::size_t total) {
  if (total == 0) return "-";
  std::ostringstream s;
  s << std::fixed << std::setprecision(0) << 100.0 * n / total << " %";
  return s.str();
}

std::optional<double> median(const std::vector<double>& v) {
  if (v.empty()) return std::nullopt;
  return percentile(v, 0.5);
}

std::optional<double> p95(const std::vector<double>& v) {
  if (v.empty()) return std::nullopt;
  return percentile(v, 0.95);
}

// [Hz] the mean frame rate of a run's frames (all delivered: an offline run).
std::optional<double> frameRate(const PlaybackSummary& s) {
  if (s.results.size() < 2) return std::nullopt;
  const double span = s.results.back().t - s.results.front().t;
  if (!(span > 0)) return std::nullopt;
  return (s.results.size() - 1) / span;
}

// A real sequence the hybrid mostly registers on the geometric path: the plain-structure targets.
bool plainStructure(const BenchmarkReport& r, const BenchSequence& s) {
  const auto* run = findRun(r, s.name, "hybrid");
  if (!run) return false;
  std::size_t geometric = 0;
  for (const auto& f : run->summary.results)
    geometric += f.path.sparse == FramePath::Sparse::Geometric;
  return 2 * geometric > run->summary.results.size();
}

}  // namespace

// One row per method, over all its frames; the paths' shares add up to its frames.
std::string timingTable(const BenchmarkReport& r) {
  std::ostringstream out;
  out << "| method | frames | registered | median ms | p95 ms | paths: share (median ms) |\n"
         "|---|---:|---:|---:|---:|---|\n";
  for (const auto& m : r.methods) {
    const auto t = totals(r, m);
    std::vector<std::pair<std::string, const std::vector<double>*>> paths;
    for (const auto& [label, ms] : t.ms_by_path) paths.push_back({label, &ms});
    std::stable_sort(paths.begin(), paths.end(), [](const auto& a, const auto& b) {
      return a.second->size() > b.second->size();
    });
    out << "| " << m << " | " << t.frames << " | " << pct(t.registered, t.frames) << " | "
        << fmt(median(t.ms), 1) << " | " << fmt(p95(t.ms), 1) << " |";
    for (std::size_t i = 0; i < paths.size(); ++i)
      out << (i ? "; " : " ") << paths[i].first << " " << pct(paths[i].second->size(), t.frames)
          << " (" << fmt(median(*paths[i].second), 1) << ")";
    out << " |\n";
  }
  return out.str();
}

// Mean time of each stage over all frames: which stage dominates.
std::string stageTable(const BenchmarkReport& r) {
  std::ostringstream out;
  out << "| method | prepare | features | matching | estimation | refine | total |\n"
         "|---|---:|---:|---:|---:|---:|---:|\n";
  for (const auto& m : r.methods) {
    const auto t = totals(r, m);
    if (t.frames == 0) continue;
    const double n = static_cast<double>(t.frames);
    out << "| " << m;
    for (double v : {t.sum.prepare, t.sum.features, t.sum.matching, t.sum.estimation, t.sum.refine,
                     t.sum.total})
      out << " | " << fmt(v / n, 1);
    out << " |\n";
  }
  return out.str();
}

std::string realtimeTable(const BenchmarkReport& r) {
  std::ostringstream out;
  out << "| sequence | frames | dropped | ATE RMSE offline [m] | ATE RMSE real time [m] | "
         "tracking median / p95 ms |\n|---|---:|---:|---:|---:|---:|\n";
  for (const auto& s : r.sequences) {
    const auto *live = findRun(r, s.name, "hybrid_realtime"),
               *offline = findRun(r, s.name, "hybrid");
    if (!live || !live->error.empty()) continue;
    const auto& l = live->summary;
    std::vector<double> ms;
    for (const auto& f : l.results) ms.push_back(f.ms.total);
    out << "| " << s.name << " | " << l.frames + l.dropped << " | " << l.dropped << " | "
        << (offline ? fmt(evaluated(*offline, &EvalResult::ate_rmse), 4) : "-") << " | "
        << fmt(evaluated(*live, &EvalResult::ate_rmse), 4) << " | " << fmt(median(ms), 1) << " / "
        << fmt(p95(ms), 1) << " |\n";
  }
  return out.str();
}

std::string timeTargets(const BenchmarkReport& r) {
  std::ostringstream out;
  const auto has = [&](const std::string& m) {
    return std::find(r.methods.begin(), r.methods.end(), m) != r.methods.end();
  };
  const auto verdict = [](bool ok) { return ok ? "**met**" : "**missed**"; };
  // Whole tracking per frame, over all frames, against opencv_rgbd on the same frames.
  if (has("hybrid") && has("opencv_rgbd")) {
    for (const auto& s : r.sequences) {
      if (isSimulated(s) || !s.skip_reason.empty()) continue;
      const auto only = [&](const BenchSequence& x) { return x.name == s.name; };
      const auto h = totals(r, "hybrid", only), o = totals(r, "opencv_rgbd", only);
      if (h.ms.empty() || o.ms.empty()) continue;
      const bool plain = plainStructure(r, s);
      const double max_median = plain ? 1.0 : 0.55, max_p95 = plain ? 1.2 : 0.8;
      const double rm = *median(h.ms) / *median(o.ms), rp = *p95(h.ms) / *p95(o.ms);
      out << "- " << s.name << (plain ? " (plain structure)" : "") << ", whole tracking over all "
          << h.frames << " frames: hybrid median " << fmt(median(h.ms), 1) << " ms / p95 "
          << fmt(p95(h.ms), 1) << " ms = " << fmt(rm, 2) << "x / " << fmt(rp, 2)
          << "x opencv_rgbd's " << fmt(median(o.ms), 1) << " / " << fmt(p95(o.ms), 1)
          << " ms (target at most " << max_median << "x / " << max_p95
          << "x): " << verdict(rm <= max_median && rp <= max_p95) << "\n";
    }
  }
  // No frame kind far off, over the real sequences' frames.
  if (has("hybrid")) {
    const auto real = [](const BenchSequence& s) {
      return !isSimulated(s) && s.skip_reason.empty();
    };
    std::vector<double> prediction, geometric;
    for (const auto& s : r.sequences) {
      const auto* run = findRun(r, s.name, "hybrid");
      if (!run || !real(s)) continue;
      for (const auto& f : run->summary.results) {
        if (f.path.refined == FramePath::Refined::Prediction) prediction.push_back(f.ms.total);
        if (f.path.sparse == FramePath::Sparse::Geometric) geometric.push_back(f.ms.total);
      }
    }
    for (const auto& [kind, ms] : {std::pair{"refinement from the motion prediction", &prediction},
                                   std::pair{"geometric path", &geometric}})
      if (ms->empty())
        out << "- real sequences, hybrid frames on the " << kind << ": none\n";
      else
        out << "- real sequences, hybrid frames on the " << kind << " (" << ms->size()
            << "): median " << fmt(median(*ms), 1)
            << " ms (target at most 25): " << verdict(*median(*ms) <= 25) << "\n";
  }
  // Real-time playback: no frame dropped, the offline ATE kept (within 5 %).
  if (has("hybrid") && has("hybrid_realtime")) {
    for (const auto& s : r.sequences) {
      const auto *live = findRun(r, s.name, "hybrid_realtime"),
                 *offline = findRun(r, s.name, "hybrid");
      if (isSimulated(s) || !s.skip_reason.empty()) continue;
      const auto a = live ? evaluated(*live, &EvalResult::ate_rmse) : std::nullopt,
                 b = offline ? evaluated(*offline, &EvalResult::ate_rmse) : std::nullopt;
      out << "- " << s.name << ", real-time playback at its recorded "
          << fmt(offline ? frameRate(offline->summary) : std::nullopt, 1) << " Hz: ";
      if (!a || !b) {
        out << "no ATE to compare (a run failed or was not evaluated): " << verdict(false) << "\n";
        continue;
      }
      out << live->summary.dropped << " frames dropped, ATE " << fmt(a, 4) << " m against "
          << fmt(b, 4) << " m offline (target: none dropped, within 5 %): "
          << verdict(live->summary.dropped == 0 && *a <= 1.05 * *b) << "\n";
    }
  }
  return out.str();
}

}  // namespace hrgbd::report
