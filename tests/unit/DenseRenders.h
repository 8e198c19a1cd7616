#pragma once
// Rendered frames with an exact relative pose for the dense refinement's tests: the simulator's
// ideal images (no sensor model), errors between motions, a scripted sparse registration.
#include <gtest/gtest.h>
#include <mrpt/core/bits_math.h>

#include <memory>
#include <opencv2/imgproc.hpp>
#include <string>
#include <utility>

#include "rgbd_odometry/DenseRefinement.h"
#include "rgbd_odometry/FeatureRegistration.h"
#include "rgbd_odometry/RigidFit.h"
#include "rgbd_sim/Render.h"
#include "rgbd_sim/Simulator.h"

namespace hrgbd::test {

/** An ideal render as the odometry's image: 8-bit grey, depth in metres. */
inline RgbdImage imageOf(const sim::IdealFrame& ideal, const PinholeCamera& cam) {
  RgbdImage f;
  cv::Mat grey;
  cv::cvtColor(ideal.colour, grey, cv::COLOR_RGB2GRAY);
  grey.convertTo(f.grey, CV_8U, 255);
  f.depth = ideal.depth;
  f.cam = cam;
  return f;
}

inline RgbdImage render(const sim::Scene& scene, const mrpt::poses::CPose3D& pose) {
  const PinholeCamera cam;
  return imageOf(sim::renderIdeal(scene, pose, cam), cam);
}

/** The reference camera of every rendered pair: over the desk, looking down at it. */
inline mrpt::poses::CPose3D referencePose() {
  return sim::lookAt(Eigen::Vector3d(0, 0.0, 1.2), Eigen::Vector3d(0, 1.3, 0.75));
}

/** The current camera's motion from the reference in the rendered pairs (3.7 cm, 2.6 deg). */
inline const mrpt::poses::CPose3D kMotion(0.03, -0.01, 0.02, mrpt::DEG2RAD(2.0),
                                          mrpt::DEG2RAD(-1.0), mrpt::DEG2RAD(1.5));

struct Pair {
  DensePyramid cur, ref;
  Eigen::Isometry3d truth;  // current -> reference
};

inline Pair renderPair(const std::string& scene_type, const mrpt::poses::CPose3D& motion,
                       const DenseParams& p = {}) {
  const auto scene = sim::makeScene(scene_type, false);
  const auto ref_pose = referencePose();
  return {buildDensePyramid(render(scene, ref_pose + motion), p),
          buildDensePyramid(render(scene, ref_pose), p), toIsometry(motion)};
}

/** Translation [m] and rotation [deg] between two motions. */
inline std::pair<double, double> error(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  const Eigen::Isometry3d d = a.inverse() * b;
  return {d.translation().norm(), mrpt::RAD2DEG(Eigen::AngleAxisd(d.rotation()).angle())};
}

inline Eigen::Isometry3d perturbed(const Eigen::Isometry3d& T, double metres, double deg) {
  return T * toIsometry(mrpt::poses::CPose3D(metres, -metres, metres / 2, mrpt::DEG2RAD(deg),
                                             mrpt::DEG2RAD(-deg), 0));
}

/** A sparse registration that answers with a scripted result. */
class ScriptedSparse : public Registration {
 public:
  explicit ScriptedSparse(RegistrationResult r) : m_r(std::move(r)) {}
  FrameFeatures prepare(Frame&) override { return {}; }
  RegistrationResult align(Frame&, Frame&) override { return m_r; }

 private:
  RegistrationResult m_r;
};

}  // namespace hrgbd::test
