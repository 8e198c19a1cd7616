#include "rgbd_sim/Simulator.h"

#include <mrpt/poses/CPose3DInterpolator.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "rgbd_core/Config.h"
#include "rgbd_core/Intrinsics.h"
#include "rgbd_core/RgbdFrame.h"
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

Trajectory cameraPath(const Scene& scene, const SimParams& p, const std::vector<double>& times) {
  const Eigen::Vector3d axis = scene.sweep_axis.normalized(), view = scene.view_dir.normalized();
  const double amp = 0.25 + 0.2 * scene.distance;  // [m] sweep amplitude
  Trajectory out;
  if (p.motion == "sweep") {
    const double ph = 0.7 * p.seed;
    for (double t : times) {
      // Slow sweep along the structure plus hand-held jitter (a few Hz, ~1 cm, ~0.5 deg).
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
  // Replay: the real trajectory, moved by a rotation about the vertical and a translation (TUM
  // ground truth has z up, as the scene) so that the point the real camera looked at maps onto
  // the scene's look_at and the camera stays on the side of view_dir. Camera height above that
  // point, distance to it, tilt and roll stay the real ones.
  const auto real = loadTumTrajectory(p.motion);
  if (real.size() < 2) throw std::runtime_error("motion file '" + p.motion + "' has < 2 poses");
  const double span = real.back().t - real[0].t,
               last = *std::max_element(times.begin(), times.end());
  if (last > span)
    throw std::runtime_error("motion file '" + p.motion + "' covers only " + std::to_string(span) +
                             " s");
  Trajectory used;
  for (const auto& q : real)
    if (q.t - real[0].t <= last + 0.1) used.push_back(q);
  const Eigen::Vector3d target = lookedAtPoint(used, scene.distance);
  Eigen::Vector2d away(0, 0);  // mean horizontal direction from the target to the camera
  for (const auto& q : used) {
    const Eigen::Vector2d h(q.pose.x() - target.x(), q.pose.y() - target.y());
    if (h.norm() > 1e-6) away += h.normalized();
  }
  const double yaw =
      std::atan2(view.y(), view.x()) - (away.norm() > 1e-6 ? std::atan2(away.y(), away.x()) : 0.0);
  const mrpt::poses::CPose3D turn(0, 0, 0, yaw, 0, 0);
  const auto moved = turn.composePoint({target.x(), target.y(), target.z()});
  const mrpt::poses::CPose3D anchor =
      mrpt::poses::CPose3D(scene.look_at.x() - moved.x, scene.look_at.y() - moved.y,
                           scene.look_at.z() - moved.z, 0, 0, 0) +
      turn;
  mrpt::poses::CPose3DInterpolator interp;
  for (const auto& q : used) interp.insert(mrpt::Clock::fromDouble(q.t - real[0].t), q.pose);
  for (double t : times) {
    mrpt::poses::CPose3D pose;
    bool valid = false;
    interp.interpolate(mrpt::Clock::fromDouble(t), pose, valid);
    if (!valid)
      throw std::runtime_error("cannot interpolate '" + p.motion + "' at " + std::to_string(t));
    out.push_back({t, anchor + pose});
  }
  return out;
}

Eigen::Vector3d lookedAtPoint(const Trajectory& path, double distance) {
  // Least-squares point nearest to all optical axes, sum |(I - d d^T)(x - c)|^2, pulled weakly
  // towards the first camera's axis at `distance` so that near-parallel axes (a camera that
  // only translates) still give a point in front of it.
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  auto add = [&](const Eigen::Matrix3d& P, const Eigen::Vector3d& x) { A += P, b += P * x; };
  for (const auto& q : path) {
    const Eigen::Vector3d c(q.pose.x(), q.pose.y(), q.pose.z());
    const Eigen::Vector3d d = q.pose.getRotationMatrix().asEigen().col(2);
    add(Eigen::Matrix3d::Identity() - d * d.transpose(), c);
  }
  const auto& first = path.front().pose;
  const Eigen::Vector3d prior = Eigen::Vector3d(first.x(), first.y(), first.z()) +
                                distance * first.getRotationMatrix().asEigen().col(2);
  add(0.01 * static_cast<double>(path.size()) * Eigen::Matrix3d::Identity(), prior);
  return A.ldlt().solve(b);
}

SimResult simulate(const SimParams& p, const SimOutputs& outputs) {
  const auto scene = makeScene(p.scene, p.far);
  const PinholeCamera cam;
  const auto camera = pinholeCamera(cam.fx, cam.fy, cam.cx, cam.cy, cam.width, cam.height);
  constexpr double kDepthFactor = 5000;  // TUM's convention: PNG value / 5000 = metres
  constexpr double kStart = 1000.0;      // [s] time stamp of the first frame

  // Poses at each frame time (the middle row), at the start of its exposure, and at its first
  // and last rows' times (rolling shutter), in one call (one file load).
  std::vector<double> times;
  const double exposure = p.sensor.exposure_ms * 1e-3, readout = p.sensor.rolling_shutter_ms * 1e-3;
  for (double offset : {0.0, -exposure, -readout / 2, readout / 2})
    for (int i = 0; i < p.frames; ++i) times.push_back(std::max(0.0, i / p.fps + offset));
  const auto poses = cameraPath(scene, p, times);
  auto part = [&](int k) {
    return Trajectory(poses.begin() + k * p.frames, poses.begin() + (k + 1) * p.frames);
  };
  const Trajectory path = part(0), path_before = part(1), first_row = part(2), last_row = part(3);

  std::unique_ptr<RawlogWriter> rawlog;
  if (!outputs.rawlog.empty())
    rawlog = std::make_unique<RawlogWriter>(outputs.rawlog, outputs.images, 9);
  std::ofstream rgb_txt, depth_txt;
  if (!outputs.tum_folder.empty()) {
    std::filesystem::create_directories(outputs.tum_folder + "/rgb");
    std::filesystem::create_directories(outputs.tum_folder + "/depth");
    rgb_txt.open(outputs.tum_folder + "/rgb.txt");
    depth_txt.open(outputs.tum_folder + "/depth.txt");
    if (!rgb_txt || !depth_txt)
      throw std::runtime_error("cannot write into '" + outputs.tum_folder + "'");
    rgb_txt << "# color images\n# file: rgbd-simulate " << scene.name << "\n# timestamp filename\n";
    depth_txt << "# depth maps\n# file: rgbd-simulate " << scene.name << "\n# timestamp filename\n";
  }

  std::mt19937 rng(static_cast<std::uint32_t>(p.seed));
  SimResult res;
  std::vector<double> ms;
  for (int i = 0; i < p.frames; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    const double t = kStart + times[i];
    const double gain = 1.0 + p.sensor.auto_exposure * std::sin(2 * M_PI * times[i] / 3.7 + p.seed);
    cv::Mat bgr, depth;
    const auto ideal = readout > 0 ? renderIdeal(scene, first_row[i].pose, cam, last_row[i].pose)
                                   : renderIdeal(scene, path[i].pose, cam);
    applyKinectModel(ideal, scene, cam, path[i].pose, path_before[i].pose, gain, p.sensor,
                     kDepthFactor, rng, bgr, depth);
    ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    res.ground_truth.push_back({t, path[i].pose});
    if (rawlog)
      rawlog->write(*makeRgbdObservation(bgr, depth, 1.0 / kDepthFactor, camera, t, "RGBD_SIM"));
    if (rgb_txt.is_open()) {
      std::ostringstream name;
      name << std::fixed << std::setprecision(6) << t << ".png";
      cv::imwrite(outputs.tum_folder + "/rgb/" + name.str(), bgr);
      cv::imwrite(outputs.tum_folder + "/depth/" + name.str(), depth);
      rgb_txt << std::fixed << std::setprecision(6) << t << " rgb/" << name.str() << "\n";
      depth_txt << std::fixed << std::setprecision(6) << t << " depth/" << name.str() << "\n";
    }
  }
  res.frames = p.frames;
  std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
  res.ms_per_frame = ms[ms.size() / 2];
  if (rawlog) saveTumTrajectory(groundTruthPathFor(outputs.rawlog), res.ground_truth);
  if (rgb_txt.is_open())
    saveTumTrajectory(outputs.tum_folder + "/groundtruth.txt", res.ground_truth);
  return res;
}

}  // namespace hrgbd::sim
