#include "rgbd_sim/Simulator.h"

#include <mrpt/poses/CPose3DInterpolator.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <vector>

#include "rgbd_core/Config.h"
#include "rgbd_core/Interrupt.h"
#include "rgbd_core/Intrinsics.h"
#include "rgbd_core/Median.h"
#include "rgbd_core/OutputFile.h"
#include "rgbd_core/RgbdFrame.h"
#include "rgbd_core/Timestamp.h"
#include "rgbd_io/OniWriter.h"
#include "rgbd_io/RawlogSource.h"

namespace hrgbd::sim {

mrpt::poses::CPose3D lookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target) {
  const Eigen::Vector3d z = (target - eye).normalized();
  const Eigen::Vector3d x = z.cross(Eigen::Vector3d::UnitZ()).normalized();  // right
  const Eigen::Vector3d y = z.cross(x);                                      // down
  mrpt::math::CMatrixDouble33 R;
  for (int i = 0; i < 3; ++i) R(i, 0) = x[i], R(i, 1) = y[i], R(i, 2) = z[i];
  return mrpt::poses::CPose3D::FromRotationAndTranslation(
      R, mrpt::math::TVector3D(eye.x(), eye.y(), eye.z()));
}

namespace {

// Slow sweep along the structure plus hand-held jitter (a few Hz, ~1 cm, ~0.5 deg).
Trajectory sweepPath(const Scene& scene, int seed, const std::vector<double>& times) {
  const Eigen::Vector3d axis = scene.sweep_axis.normalized(), view = scene.view_dir.normalized();
  const double amp = 0.25 + 0.2 * scene.distance;  // [m] sweep amplitude
  const double ph = 0.7 * seed;
  Trajectory out;
  for (double t : times) {
    const double s = amp * std::sin(2 * M_PI * t / 8.0);
    const Eigen::Vector3d jitter(0.006 * std::sin(2 * M_PI * 1.3 * t + ph),
                                 0.005 * std::sin(2 * M_PI * 2.1 * t + 2 * ph),
                                 0.004 * std::sin(2 * M_PI * 3.4 * t + 3 * ph));
    const Eigen::Vector3d look_jitter(0.01 * std::sin(2 * M_PI * 0.9 * t + ph), 0,
                                      0.01 * std::sin(2 * M_PI * 1.7 * t + ph));
    const Eigen::Vector3d eye = scene.look_at + view * scene.distance + axis * s + jitter;
    out.push_back({t, lookAt(eye, scene.look_at + axis * 0.8 * s + look_jitter)});
  }
  return out;
}

/** A loop for SLAM: an orbit about look_at's vertical, +-35 deg, with the distance (+-12 %) and
 * the elevation (+-5 deg) changing on the way, that returns to its start one frame after the
 * last (`period` [s] = frames / fps). Smooth, without jitter, so that it closes exactly. */
Trajectory loopPath(const Scene& scene, double period, const std::vector<double>& times) {
  const Eigen::Vector3d view = scene.view_dir.normalized();
  const double azimuth0 = std::atan2(view.y(), view.x()),
               elevation0 = std::asin(std::clamp(view.z(), -1.0, 1.0));
  Trajectory out;
  for (double t : times) {
    const double s = 2 * M_PI * (t - times.front()) / period;
    const double azimuth = azimuth0 + mrpt::DEG2RAD(35.0) * std::sin(s),
                 elevation = elevation0 + mrpt::DEG2RAD(5.0) * std::sin(2 * s),
                 r = scene.distance * (1 + 0.12 * std::sin(3 * s));
    const Eigen::Vector3d dir(std::cos(elevation) * std::cos(azimuth),
                              std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
    out.push_back({t, lookAt(scene.look_at + r * dir, scene.look_at)});
  }
  return out;
}

/** The poses of the TUM trajectory `file` up to 0.1 s past the last of `times`, and the first
 * pose after that when none is at or after the last time (a file sampled below 10 Hz: the
 * interpolation needs a pose on either side); time stamps made relative to its first. Throws
 * when it is shorter than `times`. */
Trajectory loadMotion(const std::string& file, const std::vector<double>& times) {
  const auto real = loadTumTrajectory(file);
  if (real.size() < 2) throw std::runtime_error("motion file '" + file + "' has < 2 poses");
  const double span = real.back().t - real[0].t,
               last = *std::max_element(times.begin(), times.end());
  if (last > span)
    throw std::runtime_error("motion file '" + file + "' covers only " + std::to_string(span) +
                             " s");
  const TimedPose* after = nullptr;  // the first pose past the window
  bool covered = false;
  for (const auto& q : real) {
    const double t = q.t - real[0].t;
    if (t > last + 0.1) {
      if (!after || q.t < after->t) after = &q;
    } else {
      covered = covered || t >= last;
    }
  }
  Trajectory used;
  for (const auto& q : real) {
    if (q.t - real[0].t > last + 0.1 && (covered || &q != after)) continue;
    for (int k = 0; k < 3; ++k)  // the evaluator's limit: the ground truth written stays exact
      if (!(std::abs(q.pose[k]) <= kMaxTrajectoryCoordinate))
        throw std::runtime_error("motion file '" + file + "': the pose at time stamp " +
                                 formatSeconds(q.t) + " has a coordinate of " +
                                 formatSeconds(q.pose[k]) + " m; motions are read up to 1e9 m");
    used.push_back({q.t - real[0].t, q.pose});
  }
  return used;
}

/** The rotation about the vertical and translation (TUM ground truth has z up, as the scene)
 * that move the point `path` looked at onto the scene's look_at, with the cameras on the side
 * of view_dir. */
mrpt::poses::CPose3D replayAnchor(const Scene& scene, const Trajectory& path,
                                  const KinectModel& sensor) {
  const Eigen::Vector3d view = scene.view_dir.normalized();
  const Eigen::Vector3d target = lookedAtPoint(path, scene.distance, sensor);
  Eigen::Vector2d away(0, 0);  // mean horizontal direction from the target to the camera
  for (const auto& q : path) {
    const Eigen::Vector2d h(q.pose.x() - target.x(), q.pose.y() - target.y());
    if (h.norm() > 1e-6) away += h.normalized();
  }
  const double yaw =
      std::atan2(view.y(), view.x()) - (away.norm() > 1e-6 ? std::atan2(away.y(), away.x()) : 0.0);
  const mrpt::poses::CPose3D turn(0, 0, 0, yaw, 0, 0);
  const auto moved = turn.composePoint({target.x(), target.y(), target.z()});
  return mrpt::poses::CPose3D(scene.look_at.x() - moved.x, scene.look_at.y() - moved.y,
                              scene.look_at.z() - moved.z, 0, 0, 0) +
         turn;
}

// Replay: the real trajectory, moved by replayAnchor(). Camera height above the looked-at point,
// tilt and roll stay the real ones, and so does the distance to it when the cameras see the
// point their axes meet (lookedAtPoint()).
Trajectory replayPath(const Scene& scene, const SimParams& p, const std::vector<double>& times) {
  const std::string& file = p.motion;
  const Trajectory used = loadMotion(file, times);
  const mrpt::poses::CPose3D anchor = replayAnchor(scene, used, p.sensor);
  mrpt::poses::CPose3DInterpolator interp;
  for (const auto& q : used) interp.insert(mrpt::Clock::fromDouble(q.t), q.pose);
  Trajectory out;
  for (double t : times) {
    mrpt::poses::CPose3D pose;
    bool valid = false;
    interp.interpolate(mrpt::Clock::fromDouble(t), pose, valid);
    if (!valid)
      throw std::runtime_error("cannot interpolate '" + file + "' at " + std::to_string(t));
    out.push_back({t, anchor + pose});
  }
  return out;
}

}  // namespace

Trajectory cameraPath(const Scene& scene, const SimParams& p, const std::vector<double>& times) {
  if (p.motion == "sweep") return sweepPath(scene, p.seed, times);
  if (p.motion == "loop") return loopPath(scene, p.frames / p.fps, times);
  return replayPath(scene, p, times);
}

namespace {

constexpr double kDepthFactor = 5000;  // TUM's convention: PNG value / 5000 = metres
constexpr double kStart = 1000.0;      // [s] time stamp of the first frame

/** Camera poses of each frame: at the frame time (the middle row), at the start of its
 * exposure, and at its first and last rows' times (rolling shutter). */
struct FramePoses {
  std::vector<double> times;  //!< [s] frame times from 0
  Trajectory path, before, first_row, last_row;
};

FramePoses framePoses(const Scene& scene, const SimParams& p) {
  // All four sets of times in one cameraPath() call (one file load).
  std::vector<double> times;
  const double exposure = p.sensor.exposure_ms * 1e-3, readout = p.sensor.rolling_shutter_ms * 1e-3;
  for (double offset : {0.0, -exposure, -readout / 2, readout / 2})
    for (int i = 0; i < p.frames; ++i) times.push_back(std::max(0.0, i / p.fps + offset));
  const auto poses = cameraPath(scene, p, times);
  auto part = [&](int k) {
    return Trajectory(poses.begin() + k * p.frames, poses.begin() + (k + 1) * p.frames);
  };
  times.resize(p.frames);
  return {times, part(0), part(1), part(2), part(3)};
}

/** Frame i: the ideal render (row by row with a rolling shutter) through the sensor model. */
SensorFrame renderFrame(const Scene& scene, const PinholeCamera& cam, const SimParams& p,
                        const FramePoses& poses, int i, std::mt19937& rng) {
  const double gain =
      1.0 + p.sensor.auto_exposure * std::sin(2 * M_PI * poses.times[i] / 3.7 + p.seed);
  const double readout = p.sensor.rolling_shutter_ms * 1e-3;
  const auto ideal = readout > 0
                         ? renderIdeal(scene, poses.first_row[i].pose, cam, poses.last_row[i].pose)
                         : renderIdeal(scene, poses.path[i].pose, cam);
  return applyKinectModel(
      ideal, cam, {poses.path[i].pose, poses.before[i].pose, gain, kDepthFactor}, p.sensor, rng);
}

/** Writes the frames into the requested outputs: a rawlog and/or a TUM folder. Each file is an
 * OutputFile: the rawlog, lists and ground truth appear under their names only when finish()
 * succeeds; every image is checked as written. */
class SequenceWriter {
 public:
  SequenceWriter(const SimOutputs& outputs, const std::string& scene_name, const PinholeCamera& cam)
      : m_outputs(outputs),
        m_camera(pinholeCamera(cam.fx, cam.fy, cam.cx, cam.cy, cam.width, cam.height)) {
    if (!outputs.rawlog.empty())
      m_rawlog = std::make_unique<RawlogWriter>(outputs.rawlog, outputs.images, 9);
    if (!outputs.tum_folder.empty()) openTumFolder(scene_name);
    if (!outputs.oni.empty()) {
      OniStreamSpec spec;
      spec.width = cam.width;
      spec.height = cam.height;
      spec.hfov = 2 * std::atan(0.5 * cam.width / cam.fx);
      spec.vfov = 2 * std::atan(0.5 * cam.height / cam.fy);
      m_oni = std::make_unique<OniWriter>(outputs.oni, spec, spec);
    }
  }

  /** Without finish() (an error, Ctrl-C): the TUM folder's images written are removed again, with
   * the folders made for them; the lists, rawlog and recording were never moved into place. */
  ~SequenceWriter() {
    if (m_finished) return;
    m_oni.reset(), m_rgb_txt.reset(), m_depth_txt.reset(), m_rawlog.reset();  // their temporaries
    std::error_code ec;
    for (const auto& f : m_images) std::filesystem::remove(f, ec);
    for (auto d = m_made_folders.rbegin(); d != m_made_folders.rend(); ++d)
      std::filesystem::remove(*d, ec);  // only when empty
    if (interrupted() && !m_images.empty())
      noteNotWritten("the TUM folder's images in '" + m_outputs.tum_folder + "' (removed)");
  }
  SequenceWriter(const SequenceWriter&) = delete;
  SequenceWriter& operator=(const SequenceWriter&) = delete;

  /** Frame at time stamp t [s]. */
  void write(double t, const SensorFrame& frame) {
    if (m_oni) {
      // The recording's clock: device microseconds from the first frame; depth in millimetres.
      const auto us = static_cast<std::uint64_t>(std::llround((t - kStart) * 1e6));
      const auto index = static_cast<std::uint32_t>(++m_oni_frames);
      cv::Mat mm;
      frame.depth.convertTo(mm, CV_16UC1, 1000.0 / kDepthFactor);
      m_oni->writeDepth(us, index, mm);
      m_oni->writeColour(us, index, frame.bgr);
    }
    if (m_rawlog)
      m_rawlog->write(*makeRgbdObservation(frame.bgr, frame.depth, 1.0 / kDepthFactor, m_camera, t,
                                           "RGBD_SIM"));
    if (!m_rgb_txt) return;
    std::ostringstream name;
    name << std::fixed << std::setprecision(6) << t << ".png";
    writePng(m_outputs.tum_folder + "/rgb/" + name.str(), frame.bgr);
    writePng(m_outputs.tum_folder + "/depth/" + name.str(), frame.depth);
    m_rgb_txt->stream() << std::fixed << std::setprecision(6) << t << " rgb/" << name.str() << "\n";
    m_depth_txt->stream() << std::fixed << std::setprecision(6) << t << " depth/" << name.str()
                          << "\n";
  }

  /** Ground truth beside the rawlog and into the TUM folder; every file moved into place. */
  void finish(const Trajectory& ground_truth) {
    if (m_oni) {
      m_oni->close();
      Trajectory in_recording_clock = ground_truth;
      for (auto& p : in_recording_clock) p.t = std::round((p.t - kStart) * 1e6) * 1e-6;  // [us]
      if (const auto gt = groundTruthOutputFor(m_outputs.oni); !gt.empty())
        saveTumTrajectory(gt, in_recording_clock);
    }
    if (m_rawlog) {
      m_rawlog->close();
      if (const auto gt = groundTruthOutputFor(m_outputs.rawlog); !gt.empty())
        saveTumTrajectory(gt, ground_truth);
    }
    if (m_rgb_txt) {
      m_rgb_txt->commit();
      m_depth_txt->commit();
      saveTumTrajectory(m_outputs.tum_folder + "/groundtruth.txt", ground_truth);
      // The camera, so that the folder is not read with one guessed from its name
      // (TumSource: ETH3D's "fx fy cx cy").
      StreamOutput calibration(m_outputs.tum_folder + "/calibration.txt", "TUM calibration");
      calibration.stream() << std::setprecision(17) << m_camera.fx() << ' ' << m_camera.fy() << ' '
                           << m_camera.cx() << ' ' << m_camera.cy() << '\n';
      calibration.commit();
    }
    m_finished = true;
  }

 private:
  void openTumFolder(const std::string& scene_name) {
    const std::string& dir = m_outputs.tum_folder;
    std::error_code ec;
    for (const auto& made : {dir, dir + "/rgb", dir + "/depth"})
      if (!std::filesystem::exists(made, ec)) m_made_folders.push_back(made);
    for (const auto* sub : {"/rgb", "/depth"})
      if (!std::filesystem::create_directories(dir + sub, ec) && ec)
        throw std::runtime_error("cannot create folder '" + dir + sub + "': " + ec.message());
    m_rgb_txt = std::make_unique<StreamOutput>(dir + "/rgb.txt", "TUM list");
    m_depth_txt = std::make_unique<StreamOutput>(dir + "/depth.txt", "TUM list");
    m_rgb_txt->stream() << "# color images\n# file: rgbd-simulate " << scene_name
                        << "\n# timestamp filename\n";
    m_depth_txt->stream() << "# depth maps\n# file: rgbd-simulate " << scene_name
                          << "\n# timestamp filename\n";
  }

  /** PNG through cv::imencode and a checked OutputFile (cv::imwrite does not report a full disk).
   */
  void writePng(const std::string& path, const cv::Mat& image) {
    std::vector<uchar> bytes;
    if (!cv::imencode(".png", image, bytes))
      throw std::runtime_error("cannot encode image '" + path + "'");
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) m_images.push_back(path);  // a rerun's stay
    writeOutputFile(path, "image", bytes.data(), bytes.size());
  }

  const SimOutputs& m_outputs;
  mrpt::img::TCamera m_camera;
  std::unique_ptr<RawlogWriter> m_rawlog;
  std::unique_ptr<StreamOutput> m_rgb_txt, m_depth_txt;
  std::unique_ptr<OniWriter> m_oni;
  int m_oni_frames = 0;
  bool m_finished = false;
  std::vector<std::string> m_images, m_made_folders;  //!< removed again without finish()
};

}  // namespace

std::vector<JobPath> writtenFiles(const SimOutputs& outputs) {
  std::vector<JobPath> out;
  if (!outputs.rawlog.empty()) {
    out.push_back({outputs.rawlog, "--rawlog", false, true});
    out.push_back({groundTruthOutputFor(outputs.rawlog), "--rawlog's ground truth", false, true});
    if (outputs.images != ImageStorage::Inline)
      out.push_back({imagesFolderFor(outputs.rawlog), "--rawlog's image folder", true, true});
  }
  if (!outputs.oni.empty()) {
    out.push_back({outputs.oni, "--oni", false, true});
    out.push_back({groundTruthOutputFor(outputs.oni), "--oni's ground truth", false, true});
  }
  if (!outputs.tum_folder.empty()) {
    for (const auto* name : {"rgb.txt", "depth.txt", "groundtruth.txt", "calibration.txt"})
      out.push_back({outputs.tum_folder + "/" + name, std::string("--tum's ") + name, false, true});
    for (const auto* name : {"rgb", "depth"})
      out.push_back(
          {outputs.tum_folder + "/" + name, std::string("--tum's ") + name + "/", true, true});
  }
  return out;
}

SimResult simulate(const SimParams& p, const SimOutputs& outputs, Progress* progress) {
  const auto scene = makeScene(p.scene, p.far);
  const PinholeCamera cam;
  const FramePoses poses = framePoses(scene, p);
  SequenceWriter writer(outputs, scene.name, cam);
  std::mt19937 rng(static_cast<std::uint32_t>(p.seed));
  SimResult res;
  std::vector<double> ms;
  for (int i = 0; i < p.frames; ++i) {
    checkInterrupt();  // Ctrl-C: the outputs are not completed (their destructors clean up)
    const auto t0 = std::chrono::steady_clock::now();
    const SensorFrame frame =
        p.walker_speed > 0
            ? renderFrame(withWalker(scene, poses.times[i], p.walker_speed), cam, p, poses, i, rng)
            : renderFrame(scene, cam, p, poses, i, rng);
    ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    if (cv::countNonZero(frame.depth) <
        kSparseDepthShare * static_cast<double>(frame.depth.total()))
      ++res.sparse_depth_frames;
    const double t = kStart + poses.times[i];
    res.ground_truth.push_back({t, poses.path[i].pose});
    writer.write(t, frame);
    if (progress) progress->update(static_cast<std::size_t>(i) + 1);
  }
  res.frames = p.frames;
  res.ms_per_frame = median(ms);
  writer.finish(res.ground_truth);
  return res;
}

}  // namespace hrgbd::sim
