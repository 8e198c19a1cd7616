#include "rgbd_live/Live.h"

#include <chrono>
#include <ostream>
#include <thread>

#include "rgbd_app/MakeOdometry.h"
#include "rgbd_app/Playback.h"
#include "rgbd_core/Config.h"
#include "rgbd_core/Trajectory.h"
#include "rgbd_io/openFrameSource.h"
#include "rgbd_live/Grabber.h"
#include "rgbd_live/LiveViewer.h"
#include "rgbd_map/ColouredMap.h"

namespace hrgbd {
namespace {

struct Session {
  ColouredMap map;
  Trajectory trajectory;
  std::vector<mrpt::poses::CPose3D> path;  // MRPT world

  void save(const std::string& prefix, std::ostream& log) const {
    map.savePly(prefix + "map.ply");
    saveScene(map, path, prefix + "map.3Dscene");
    saveTumTrajectory(prefix + "trajectory.txt", trajectory);
    log << "saved " << prefix << "map.ply (" << map.size() << " points), " << prefix
        << "map.3Dscene, " << prefix << "trajectory.txt\n";
  }
};

}  // namespace

void runLive(const LiveOptions& opt, std::ostream& log) {
  using Clock = std::chrono::steady_clock;
  const auto cfg = loadChecked(opt.config);
  OdometryParams params;
  loadStrict(params, *cfg, "Odometry");
  MapParams map_params;
  loadStrict(map_params, *cfg, "Map");
  RgbdOdometry odometry = makeOdometry(params, *cfg);
  auto source = openFrameSource(opt.input, *cfg);  // throws "no OpenNI2 sensor ..." clearly
  log << "input: " << source->describe() << "\nmethod: " << toString(params.method) << std::endl;
  LiveViewer viewer("hybrid-rgbd-odometry live: " + opt.input);
  Grabber grabber(std::move(source), opt.input == "openni2", opt.rate);

  Session s{ColouredMap(map_params), {}, {}};
  bool paused = false, finished = false;
  double fps = 0;
  auto last = Clock::now(), ended = Clock::now();
  while (viewer.isOpen()) {
    const int key = viewer.key();
    if (key == 'q' || key == 27) break;
    if (key == 'p' || key == ' ') viewer.status((paused = !paused) ? "paused" : "");
    if (key == 's') s.save(opt.save_prefix, log), viewer.status("saved " + opt.save_prefix + "*");
    if (key == 'r') {
      odometry.reset();
      s = Session{ColouredMap(map_params), {}, {}};
      viewer.clear();
      viewer.status("reset: the next frame is the new origin");
    }
    const bool enough = opt.max_frames > 0 && s.path.size() >= std::size_t(opt.max_frames);
    if (paused || finished || enough) {
      if (!finished && enough) finished = true, ended = Clock::now();
      if (finished && opt.hold_seconds >= 0 &&
          Clock::now() - ended > std::chrono::duration<double>(opt.hold_seconds))
        break;
      std::this_thread::sleep_for(std::chrono::milliseconds(30));
      continue;
    }
    const auto obs = grabber.pop();
    if (!obs) {
      finished = true;
      ended = Clock::now();
      log << "finished: " << s.path.size() << " frames, map " << s.map.size() << " points, "
          << grabber.dropped() << " dropped by the grabber" << std::endl;
      viewer.status("end of data: [s] save  [q] quit");
      continue;
    }
    const auto r = odometry.processObservation(*obs);
    if (r.registered()) s.map.insert(*obs, r.pose);
    s.trajectory.push_back({r.t, r.pose});
    s.path.push_back(opticalToMrptWorld(r.pose));
    const auto now = Clock::now();
    const double dt = std::chrono::duration<double>(now - last).count();
    last = now;
    if (dt > 0) fps = fps == 0 ? 1 / dt : 0.9 * fps + 0.1 / dt;
    viewer.update(*obs, r, s.map, s.path, fps);
  }
  if (opt.hold_seconds >= 0) s.save(opt.save_prefix, log);
}

}  // namespace hrgbd
