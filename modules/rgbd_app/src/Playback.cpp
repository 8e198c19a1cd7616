#include "rgbd_app/Playback.h"

#include <mrpt/config/CConfigFileMemory.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>

#include "MapOutputs.h"
#include "PlaybackSection.h"
#include "rgbd_app/MakeOdometry.h"
#include "rgbd_core/Config.h"
#include "rgbd_eval/EvalPlot.h"
#include "rgbd_eval/Evaluate.h"
#include "rgbd_io/TumSource.h"
#include "rgbd_io/openFrameSource.h"

namespace hrgbd {
namespace {

void writeCsvHeader(std::ostream& out) {
  out << "timestamp,status,path,orb_features,features,matches,inliers,scale_m,ms_prepare,"
         "ms_features,"
         "ms_matching,ms_estimation,ms_refine,ms_total,detail\n";
}

void writeCsvRow(std::ostream& out, const FrameResult& r) {
  out << std::fixed << std::setprecision(6) << r.t << "," << toString(r.status) << "," << r.path
      << "," << r.orb_features << "," << r.features << "," << r.matches << "," << r.inliers << ","
      << std::setprecision(5) << r.scale << "," << std::setprecision(3) << r.ms.prepare << ","
      << r.ms.features << "," << r.ms.matching << "," << r.ms.estimation << "," << r.ms.refine
      << "," << r.ms.total << ",\"" << r.detail << "\"\n";
  out.flush();
}

void progressBar(std::ostream& err, std::size_t n, std::size_t registered, double ms) {
  err << "\r  frame " << std::setw(6) << n << "  registered " << std::setw(6) << registered << "  "
      << std::fixed << std::setprecision(1) << std::setw(6) << ms << " ms/frame" << std::flush;
}

}  // namespace

PlaybackSummary runPlayback(const PlaybackOptions& opt, std::ostream& log) {
  const auto cfg = loadChecked(opt.config);
  PlaybackSection pb;
  pb.load(*cfg,
          opt.config.empty() ? "." : std::filesystem::path(opt.config).parent_path().string());
  if (!opt.ini_outputs) pb.csv.clear(), pb.outputs = {};
  OdometryParams params;
  loadStrict(params, *cfg, "Odometry");
  if (!opt.method.empty()) params.method = parseMethod(opt.method);
  RgbdOdometry odometry = makeOdometry(params, *cfg);

  const auto input = opt.input.empty() ? pb.input : opt.input;
  if (input.empty()) throw ConfigError("no input: give --input or [Playback] input");
  auto source = openFrameSource(input, *cfg);
  log << "input: " << source->describe() << "\nmethod: " << toString(params.method) << "\n";

  const auto traj_path = opt.trajectory.empty() ? pb.trajectory : opt.trajectory;
  std::ofstream traj(traj_path);
  if (!traj) throw std::runtime_error("cannot write trajectory '" + traj_path + "'");
  traj << "# hybrid-rgbd-odometry " << toString(params.method)
       << ": timestamp tx ty tz qx qy qz qw (optical frame of the first camera)\n";
  const auto csv_path = opt.csv.empty() ? pb.csv : opt.csv;
  std::ofstream csv;
  if (!csv_path.empty()) {
    csv.open(csv_path);
    if (!csv) throw std::runtime_error("cannot write CSV '" + csv_path + "'");
    writeCsvHeader(csv);
  }

  auto pick = [](const std::string& cli, const std::string& ini) {
    return cli.empty() ? ini : cli;
  };
  MapParams map_params;
  loadStrict(map_params, *cfg, "Map");
  MapOutputs outputs(
      {pick(opt.output_rawlog, pb.outputs.output_rawlog), pick(opt.simplemap, pb.outputs.simplemap),
       pick(opt.map_ply, pb.outputs.map_ply), pick(opt.map_scene, pb.outputs.map_scene)},
      map_params);

  PlaybackSummary sum;
  Trajectory estimate;
  const bool bar = opt.progress && isatty(STDERR_FILENO);
  while (auto obs = source->next()) {
    auto r = odometry.processObservation(*obs);
    r.inlier_points.clear();  // display only; a long run keeps just the figures
    writeTumLine(traj, {r.t, r.pose});
    traj.flush();
    if (csv.is_open()) writeCsvRow(csv, r);
    outputs.add(*obs, r);
    estimate.push_back({r.t, r.pose});
    sum.registered += r.registered();
    sum.results.push_back(r);
    if (bar) progressBar(std::cerr, sum.results.size(), sum.registered, r.ms.total);
    if (opt.max_frames > 0 && sum.results.size() >= static_cast<std::size_t>(opt.max_frames)) break;
  }
  if (bar) std::cerr << "\n";
  sum.frames = sum.results.size();
  if (sum.frames == 0)
    throw std::runtime_error("no RGB-D frames (CObservation3DRangeScan) in " + source->describe() +
                             " (" + std::to_string(source->stats().skipped_objects) +
                             " other objects skipped)");
  std::vector<double> ms;
  for (const auto& r : sum.results) ms.push_back(r.ms.total);
  sum.median_ms = percentile(ms, 0.5);
  sum.p95_ms = percentile(ms, 0.95);
  log << "frames: " << sum.frames << ", registered: " << sum.registered
      << ", skipped objects: " << source->stats().skipped_objects << "\n"
      << "time per frame: median " << std::fixed << std::setprecision(1) << sum.median_ms
      << " ms, 95th percentile " << sum.p95_ms << " ms\n"
      << "trajectory: " << traj_path << "\n";
  sum.map_points = outputs.finish(log);

  const auto gt = source->groundTruth();
  if (!gt.empty() && estimate.size() >= 3) {
    try {
      const auto e = evaluateTrajectory(gt, estimate);
      sum.evaluated = true;
      sum.eval = e;
      log << "evaluation against ground truth:\n" << toText(e);
      if (!opt.plot.empty())
        plotEvaluation(e, opt.plot, input + " (" + toString(params.method) + ")");
    } catch (const std::exception& ex) {
      log << "evaluation skipped: " << ex.what() << "\n";
    }
  }
  return sum;
}

}  // namespace hrgbd
