#include "rgbd_live/Live.h"

#include <chrono>
#include <ostream>
#include <thread>

#include "rgbd_app/AppConfig.h"
#include "rgbd_app/FrameLoop.h"
#include "rgbd_app/MapSinks.h"
#include "rgbd_app/TextSinks.h"
#include "rgbd_app/makeOdometry.h"
#include "rgbd_core/Config.h"
#include "rgbd_core/JobPaths.h"
#include "rgbd_core/Trajectory.h"
#include "rgbd_io/Grabber.h"
#include "rgbd_io/openFrameSource.h"
#include "rgbd_live/LiveViewer.h"
#include "rgbd_live/ViewerSink.h"

namespace hrgbd {
namespace {

using Clock = std::chrono::steady_clock;

/** The live app's sinks: the trajectory and the map, kept for [s], and the window. */
struct LiveSinks {
  TrajectorySink trajectory;
  ColouredMapSink map;
  ViewerSink viewer;

  LiveSinks(const MapParams& params, LiveViewer& window, bool slam)
      : map(params, {}, slam), viewer(window, map) {}
  std::vector<FrameSink*> list() { return {&trajectory, &map, &viewer}; }
  /** Writes <prefix>map.ply, <prefix>map.3Dscene and <prefix>trajectory.txt as they are now,
   * each in full or not at all; throws naming the file that cannot be written. */
  void save(const std::string& prefix, std::ostream& log) const {
    map.save({prefix + "map.ply", prefix + "map.3Dscene"});
    trajectory.save(prefix + "trajectory.txt",
                    "# rgbd-live: timestamp tx ty tz qx qy qz qw (optical frame of the first "
                    "camera)");
    log << "saved " << prefix << "map.ply (" << map.map().size() << " points), " << prefix
        << "map.3Dscene, " << prefix << "trajectory.txt\n";
  }
};

/** The files [s] and the end of a held run write. */
std::vector<JobPath> savedFiles(const std::string& prefix) {
  std::vector<JobPath> out;
  for (const auto* name : {"map.ply", "map.3Dscene", "trajectory.txt"})
    out.push_back({prefix + name, std::string("--save-prefix's ") + name, false, true});
  return out;
}

/** Steps the loop between the window's keys ([p] pause, [r] reset, [s] save, [q] quit) until
 * [q], the window is closed, or the hold after the end of the data expires. */
void runControls(FrameLoop& loop, LiveSinks& sinks, LiveViewer& viewer, Grabber& grabber,
                 const LiveOptions& opt, std::ostream& log) {
  bool paused = false, finished = false;
  auto ended = Clock::now();
  while (viewer.isOpen()) {
    const int key = viewer.key();
    if (key == 'q' || key == 27) break;
    if (key == 'p' || key == ' ') viewer.status((paused = !paused) ? "paused" : "");
    if (key == 's') {
      try {  // a failed save is shown and the session goes on; the files stay as they were
        sinks.save(opt.save_prefix, log);
        viewer.status("saved " + opt.save_prefix + "*");
      } catch (const std::exception& e) {
        log << "save failed: " << e.what() << std::endl;
        viewer.status(std::string("save failed: ") + e.what());
      }
    }
    if (key == 'r') {
      loop.reset();
      viewer.status("reset: the next frame is the new origin");
    }
    if (finished && opt.hold_seconds >= 0 &&
        Clock::now() - ended > std::chrono::duration<double>(opt.hold_seconds))
      break;
    if (paused || finished) {
      std::this_thread::sleep_for(std::chrono::milliseconds(30));
      continue;
    }
    if (!loop.step()) {
      grabber.stop();  // the count of dropped frames ends with the data
      finished = true;
      ended = Clock::now();
      if (loop.slam()) loop.finish(log);  // the last loops and optimisation, shown
      log << "finished: " << loop.frames() << " frames, map " << sinks.map.map().size()
          << " points, " << grabber.dropped() << " dropped (the tracker was behind)" << std::endl;
      viewer.status("end of data: [s] save  [q] quit");
    }
  }
}

}  // namespace

void runLive(const LiveOptions& opt, std::ostream& log) {
  if (opt.realtime && opt.rate <= 0 && opt.input != "openni2")
    throw UsageError("--realtime plays frames on their time stamps: it needs --rate > 0");
  const auto cfg = loadChecked(opt.config);
  OdometryParams params;
  params.loadFromConfigFile(*cfg, "Odometry");
  MapParams map_params;
  map_params.loadFromConfigFile(*cfg, "Map");
  const SlamParams slam =
      loadSlamParams(*cfg, iniFolder(opt.config), params.method, opt.slam, opt.no_slam);
  auto source = openFrameSource(opt.input, *cfg);  // throws "no OpenNI2 sensor ..." clearly
  params = withSourceCamera(params, *source);
  auto odometry = makeOdometry(params, *cfg);
  auto inputs = source->inputs();
  inputs.push_back({opt.config, "the configuration file (--config)"});
  for (const auto& p : slamInputs(slam)) inputs.push_back(p);
  checkJobPaths(inputs, savedFiles(opt.save_prefix));
  log << "input: " << source->describe() << "\nmethod: " << toString(params.method) << std::endl;
  LiveViewer viewer("hybrid-rgbd-odometry live: " + opt.input);
  // a sensor delivers at its own pace and drops what the tracker is too slow for; a recording
  // does the same with --realtime, else it waits for the tracker
  const bool sensor = opt.input == "openni2";
  Grabber grabber(std::move(source), sensor || opt.realtime, sensor ? 0 : opt.rate);

  LiveSinks sinks(map_params, viewer, slam.enabled);
  FrameLoop loop(grabber, std::move(odometry), sinks.list(),
                 opt.max_frames > 0 ? static_cast<std::size_t>(opt.max_frames) : 0);
  // live, the map snaps to the optimised poses after each optimisation
  if (slam.enabled)
    loop.setSlam(std::make_unique<KeyframeSlam>(slam, params, sensor || opt.realtime), true);
  runControls(loop, sinks, viewer, grabber, opt, log);
  if (opt.hold_seconds >= 0) sinks.save(opt.save_prefix, log);
}

}  // namespace hrgbd
