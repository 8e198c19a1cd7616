#include "rgbd_app/Playback.h"

#include <iomanip>
#include <iostream>

#include "PlaybackSection.h"
#include "rgbd_app/FrameLoop.h"
#include "rgbd_app/MapSinks.h"
#include "rgbd_app/TextSinks.h"
#include "rgbd_app/makeOdometry.h"
#include "rgbd_core/Config.h"
#include "rgbd_core/JobPaths.h"
#include "rgbd_core/OutputFile.h"
#include "rgbd_core/Progress.h"
#include "rgbd_eval/EvalPlot.h"
#include "rgbd_eval/Evaluate.h"
#include "rgbd_io/Grabber.h"
#include "rgbd_io/RawlogWriter.h"
#include "rgbd_io/openFrameSource.h"

namespace hrgbd {
namespace {

/** What runPlayback() does: the options over the INI's [Playback], [Odometry]. */
struct PlaybackJob {
  std::unique_ptr<mrpt::config::CConfigFileBase> cfg;
  OdometryParams odometry;
  SlamParams slam;
  std::string input, trajectory, csv, graph;
  MapOutputPaths outputs;
  std::vector<JobPath> written;  //!< every output file and folder, named by option or key
};

PlaybackJob resolveJob(const PlaybackOptions& opt) {
  PlaybackJob job;
  job.cfg = loadChecked(opt.config);
  PlaybackSection pb;
  const std::string base = iniFolder(opt.config);
  pb.load(*job.cfg, base);
  if (!opt.ini_outputs) pb.csv.clear(), pb.outputs = {};
  job.odometry.loadFromConfigFile(*job.cfg, "Odometry");
  if (!opt.method.empty()) job.odometry.method = parseMethod(opt.method);
  job.slam = loadSlamParams(*job.cfg, base, job.odometry.method, opt.slam, opt.no_slam);
  auto pick = [](const std::string& cli, const std::string& ini) {
    return cli.empty() ? ini : cli;
  };
  job.input = pick(opt.input, pb.input);
  job.trajectory = pick(opt.trajectory, pb.trajectory);
  job.csv = pick(opt.csv, pb.csv);
  job.graph = pick(opt.graph, pb.graph);
  job.outputs = {pick(opt.output_rawlog, pb.outputs.output_rawlog),
                 pick(opt.simplemap, pb.outputs.simplemap), pick(opt.map_ply, pb.outputs.map_ply),
                 pick(opt.map_scene, pb.outputs.map_scene)};
  // Each output named by the option or key that gave it, for checkJobPaths()'s messages.
  auto output = [&](const std::string& cli, const std::string& ini, const std::string& option,
                    const std::string& key) {
    return cli.empty() ? JobPath{ini, "[Playback] " + key} : JobPath{cli, option, false, true};
  };
  job.written = {
      output(opt.trajectory, pb.trajectory, "--trajectory", "trajectory"),
      output(opt.csv, pb.csv, "--csv", "csv"),
      output(opt.output_rawlog, pb.outputs.output_rawlog, "--output-rawlog", "output_rawlog"),
      output(opt.simplemap, pb.outputs.simplemap, "--simplemap", "simplemap"),
      output(opt.map_ply, pb.outputs.map_ply, "--map-ply", "map_ply"),
      output(opt.map_scene, pb.outputs.map_scene, "--map-scene", "map_scene"),
      output(opt.graph, pb.graph, "--graph", "graph"),
      {opt.plot, "--plot", false, true}};
  if (!job.outputs.output_rawlog.empty()) {
    auto images = job.written[2];  // its colour images, PNG files
    images.path = imagesFolderFor(images.path);
    images.name += "'s image folder";
    images.folder = true;
    job.written.push_back(images);
  }
  return job;
}

/** Collects the PlaybackSummary; finish() logs the counts and times, and throws when the source
 * gave no frame at all. */
class SummarySink : public FrameSink {
 public:
  explicit SummarySink(const FrameSource& source) : m_source(source) {}
  void add(const mrpt::obs::CObservation3DRangeScan&, const FrameResult& r) override {
    FrameResult figures = r;
    figures.inlier_points.clear();  // display only; a long run keeps just the figures
    m_sum.results.push_back(figures);
    m_sum.registered += r.registered();
  }
  void correct(const SlamPoses& slam) override {
    for (std::size_t i = 0; i < m_sum.results.size() && i < slam.poses.size(); ++i)
      m_sum.results[i].pose = slam.poses[i];
  }
  void finish(std::ostream& log) override {
    m_sum.frames = m_sum.results.size();
    const auto skipped = m_source.stats().skipped_objects;
    if (m_sum.frames == 0)
      throw std::runtime_error("no RGB-D frames (CObservation3DRangeScan) in " +
                               m_source.describe() + " (" + std::to_string(skipped) +
                               " other objects skipped)");
    std::vector<double> ms;
    for (const auto& r : m_sum.results) ms.push_back(r.ms.total);
    m_sum.median_ms = percentile(ms, 0.5);
    m_sum.p95_ms = percentile(ms, 0.95);
    log << "frames: " << m_sum.frames << ", registered: " << m_sum.registered
        << ", skipped objects: " << skipped << "\n"
        << "time per frame: median " << std::fixed << std::setprecision(1) << m_sum.median_ms
        << " ms, 95th percentile " << m_sum.p95_ms << " ms\n";
  }
  PlaybackSummary& summary() { return m_sum; }

 private:
  const FrameSource& m_source;
  PlaybackSummary m_sum;
};

/** The playback's sinks; list() gives those in use in the order they get frames and finish. */
struct PlaybackSinks {
  std::unique_ptr<ProgressSink> progress;
  std::unique_ptr<SummarySink> summary;
  std::unique_ptr<TrajectorySink> trajectory;
  std::unique_ptr<CsvSink> csv;
  std::unique_ptr<PosedRawlogSink> rawlog;
  std::unique_ptr<SimplemapSink> simplemap;
  std::unique_ptr<ColouredMapSink> map;

  std::vector<FrameSink*> list() const {
    std::vector<FrameSink*> out;
    for (FrameSink* s :
         std::initializer_list<FrameSink*>{progress.get(), summary.get(), trajectory.get(),
                                           csv.get(), rawlog.get(), simplemap.get(), map.get()})
      if (s) out.push_back(s);
    return out;
  }
};

/** Opens the output files (trajectory first, then CSV, rawlog); throws if one cannot be written. */
PlaybackSinks makeSinks(const PlaybackJob& job, const FrameSource& source,
                        const ProgressParams* progress) {
  PlaybackSinks s;
  if (progress) s.progress = std::make_unique<ProgressSink>(std::cerr, *progress);
  s.summary = std::make_unique<SummarySink>(source);
  s.trajectory = std::make_unique<TrajectorySink>(
      job.trajectory,
      std::string("# hybrid-rgbd-odometry ") + toString(job.odometry.method) +
          ": timestamp tx ty tz qx qy qz qw (optical frame of the first camera)",
      !job.slam.enabled);  // the SLAM mode's poses are written once, optimised
  if (!job.csv.empty()) s.csv = std::make_unique<CsvSink>(job.csv);
  MapParams map_params;
  map_params.loadFromConfigFile(*job.cfg, "Map");
  const auto& o = job.outputs;
  if (!o.output_rawlog.empty()) s.rawlog = std::make_unique<PosedRawlogSink>(o.output_rawlog);
  if (!o.simplemap.empty()) s.simplemap = std::make_unique<SimplemapSink>(o.simplemap);
  if (!o.map_ply.empty() || !o.map_scene.empty())
    // in SLAM mode, a node's cloud where the graph culls nodes (KeyframeSlam::redundant()) adds
    // nothing to the map
    s.map = std::make_unique<ColouredMapSink>(map_params, MapFiles{o.map_ply, o.map_scene},
                                              job.slam.enabled, 0.5 * job.slam.node_spacing);
  return s;
}

/** Evaluation against the source's ground truth, when it has one; an evaluation that cannot be
 * made is logged, a plot that cannot be written is an error. */
void evaluate(const FrameSource& source, const Trajectory& estimate, const std::string& plot,
              const std::string& title, PlaybackSummary& sum, std::ostream& log) {
  const auto gt = source.groundTruth();
  if (gt.empty() || estimate.size() < 3) {
    if (!plot.empty())
      log << "no plot: " << (gt.empty() ? "the input has no ground truth" : "fewer than 3 poses")
          << "\n";
    return;
  }
  try {
    sum.eval = evaluateTrajectory(gt, estimate);
    sum.evaluated = true;
  } catch (const std::exception& ex) {
    log << "evaluation skipped: " << ex.what() << "\n";
    return;
  }
  log << "evaluation against ground truth:\n" << toText(sum.eval);
  if (!sum.loops.empty()) {
    sum.loop_check = checkRelativePoses(gt, sum.loops);
    log << "loop edges vs ground truth: " << sum.loop_check.checked << " checked, largest error "
        << std::fixed << std::setprecision(4) << sum.loop_check.largest_translation << " m, "
        << std::setprecision(2) << sum.loop_check.largest_rotation << " deg\n";
  }
  if (!plot.empty())
    timedStep(log, "plot: " + plot, [&] { plotEvaluation(sum.eval, plot, title); });
}

}  // namespace

PlaybackSummary runPlayback(const PlaybackOptions& opt, std::ostream& log) {
  const auto job = resolveJob(opt);
  if (job.input.empty()) throw ConfigError("no input: give --input or [Playback] input");
  auto source = openFrameSource(job.input, *job.cfg);
  const OdometryParams params = withSourceCamera(job.odometry, *source);
  auto odometry = makeOdometry(params, *job.cfg);
  // No output may overwrite an input or another output; checked before anything is written.
  auto inputs = source->inputs();
  inputs.push_back({opt.config, "the configuration file (--config)"});
  for (const auto& p : slamInputs(job.slam)) inputs.push_back(p);
  checkJobPaths(inputs, job.written);
  // Usage errors first, then every other output file is tried (a temporary file in its folder,
  // removed again): the map, simplemap and graph are written after the run, which a missing or
  // read-only folder would otherwise end with nothing but the trajectory and CSV.
  try {
    if (!opt.plot.empty()) checkPlotPath(opt.plot, "--plot");  // tries it too
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  if (!job.graph.empty() && !job.slam.enabled)
    throw UsageError(
        "a pose graph (--graph / [Playback] graph) needs the SLAM mode ([Slam] enabled)");
  for (const auto& out : job.written)
    if (!out.path.empty() && !out.folder && out.path != opt.plot) OutputFile(out.path, out.name);
  log << "input: " << source->describe() << "\nmethod: " << toString(params.method) << "\n";
  if (params.dense.enabled && params.dense.rolling_shutter_ms > 0 && isProductMethod(params.method))
    log << "rolling shutter: " << params.dense.rolling_shutter_ms << " ms readout undone\n";

  const auto max_frames = opt.max_frames > 0 ? static_cast<std::size_t>(opt.max_frames) : 0;
  ProgressParams progress;  // frameProgress() may count a rawlog's frames: only when shown
  if (opt.progress) progress = frameProgress(*source, max_frames, opt.progress_label);
  // what runs after the last frame and may take seconds: the time left does not include it
  const auto& o = job.outputs;
  if (job.slam.enabled || !o.map_ply.empty() || !o.map_scene.empty() || !o.simplemap.empty())
    progress.after = "final steps";
  // a sensor, or a recording played as one, through the sensor's grabber: it drops the frames
  // that arrive while the tracker is behind
  std::unique_ptr<Grabber> grabber;
  if (opt.realtime || job.input == "openni2") {
    const double rate = job.input == "openni2" ? 0 : 1;
    // -n counts the recorded frames here, tracked or dropped: the stretch offline runs cover
    grabber = std::make_unique<Grabber>(std::move(source), true, rate, max_frames);
    log << "played as a sensor: frames on their time stamps, late ones dropped\n";
  }
  FrameSource& frames = grabber ? *grabber : *source;
  const auto sinks = makeSinks(job, frames, opt.progress ? &progress : nullptr);
  FrameLoop loop(frames, std::move(odometry), sinks.list(), grabber ? 0 : max_frames);
  // live, the back end skips work rather than make the tracking wait (and drop frames)
  if (job.slam.enabled)
    loop.setSlam(std::make_unique<KeyframeSlam>(job.slam, params, grabber != nullptr));
  loop.run();
  if (grabber) grabber->stop();  // the count of dropped frames ends with the run
  // the progress line ends before the final steps print theirs
  if (sinks.progress) sinks.progress->finish(log);
  loop.finish(log);
  if (!job.graph.empty())
    timedStep(log, "pose graph (MRPT text format): " + job.graph,
              [&] { loop.slam()->graph().save(job.graph); });

  auto sum = std::move(sinks.summary->summary());
  if (grabber) {
    sum.dropped = grabber->dropped();
    log << "dropped: " << sum.dropped << " frames (the tracker was behind)\n";
  }
  sum.map_points = sinks.map ? sinks.map->map().size() : 0;
  sum.slam = job.slam.enabled;
  if (sum.slam) {
    sum.slam_stats = loop.slam()->stats();
    const auto slam = loop.slam()->poses();
    const auto& traj = sinks.trajectory->trajectory();
    for (std::size_t i = 0; i < slam.loops.size(); ++i)
      sum.loops.push_back(
          {traj.at(slam.loops[i].first).t, traj.at(slam.loops[i].second).t, slam.loop_measured[i]});
  }
  evaluate(frames, sinks.trajectory->trajectory(), opt.plot,
           job.input + " (" + toString(job.odometry.method) + (sum.slam ? ", SLAM" : "") + ")", sum,
           log);
  return sum;
}

}  // namespace hrgbd
