#include "rgbd_odometry/RgbdOdometry.h"

#include <cmath>

#include "rgbd_core/Config.h"
#include "rgbd_core/ErrorText.h"

namespace hrgbd {
namespace {

double rotationDeg(const Eigen::Isometry3d& T) {
  return mrpt::RAD2DEG(Eigen::AngleAxisd(T.rotation()).angle());
}

// What the registration saw and measured, into the frame's report.
void report(const FrameFeatures& seen, FrameResult& r) {
  r.path = seen.path;
  r.orb_features = seen.orb_features;
  r.features = seen.features;
  r.ms += seen.ms;
}

void report(RegistrationResult& reg, FrameResult& r) {
  report(reg.seen, r);
  r.matches = reg.matches;
  r.inliers = reg.inliers;
  r.scale = reg.scale;
  r.inlier_points = std::move(reg.inlier_points);  // the registration's result is not kept
}

}  // namespace

StageTimes& StageTimes::operator+=(const StageTimes& o) {
  prepare += o.prepare, features += o.features, matching += o.matching;
  estimation += o.estimation, refine += o.refine, total += o.total;
  return *this;
}

const char* toString(FramePath::Sparse s) {
  using S = FramePath::Sparse;
  switch (s) {
    case S::None:
      return "none";
    case S::Photometric:
      return "photometric";
    case S::Geometric:
      return "geometric";
    case S::Peer:
      return "peer";
  }
  return "?";
}

const char* toString(FramePath::Refined r) {
  using R = FramePath::Refined;
  switch (r) {
    case R::None:
      return "none";
    case R::Sparse:
      return "sparse";
    case R::Prediction:
      return "prediction";
    case R::Refused:
      return "refused";
  }
  return "?";
}

std::string toString(const FramePath& p) {
  std::string s = toString(p.sparse);
  if (p.refined == FramePath::Refined::Sparse) s += "+dense";
  if (p.refined == FramePath::Refined::Prediction) s += "+dense(prediction)";
  if (p.refined == FramePath::Refined::Refused) s += "+dense(refused)";
  return s;
}

const char* toString(FrameResult::Status s) {
  using S = FrameResult::Status;
  switch (s) {
    case S::FirstFrame:
      return "first_frame";
    case S::Ok:
      return "ok";
    case S::BadInput:
      return "bad_input";
    case S::TooFewFeatures:
      return "too_few_features";
    case S::TooFewMatches:
      return "too_few_matches";
    case S::DegenerateSamples:
      return "degenerate_samples";
    case S::TooFewInliers:
      return "too_few_inliers";
    case S::LargeResiduals:
      return "large_residuals";
    case S::ImplausibleMotion:
      return "implausible_motion";
    case S::Degenerate:
      return "degenerate";
  }
  return "?";
}

RgbdOdometry::RgbdOdometry(const OdometryParams& params)
    : RgbdOdometry(params, makeRegistration(params)) {}

RgbdOdometry::RgbdOdometry(const OdometryParams& params, std::unique_ptr<Registration> registration)
    : m_params(params), m_registration(std::move(registration)) {
  // the baselines and peers track frame to frame, as published
  if (!isProductMethod(params.method)) {
    m_params.keyframe_max_translation = 0;
    m_params.keyframe_after_failures = 0;
  }
}

void RgbdOdometry::reset() {
  m_ref.reset();
  m_pose = m_velocity = mrpt::poses::CPose3D();
  m_twist.reset();
  m_previous_registered = false;
  m_failures = 0;
  m_flagged_run = 0;
  m_last_t.reset();
  m_mean_interval = 0;
  m_after_gap = false;
}

void RgbdOdometry::correct(const mrpt::poses::CPose3D& correction) {
  if (m_ref) m_ref->pose = toPose(toIsometry(correction + m_ref->pose));
  m_pose = toPose(toIsometry(correction + m_pose));
}

FrameResult RgbdOdometry::processObservation(const mrpt::obs::CObservation3DRangeScan& obs) {
  double total = 0;
  FrameResult r = timed(total, [&] { return track(obs); });
  r.ms.total = total;
  return r;
}

FrameResult RgbdOdometry::track(const mrpt::obs::CObservation3DRangeScan& obs) {
  FrameResult r;
  r.t = mrpt::Clock::toDouble(obs.timestamp);
  noteTimeGap(r.t);
  // Algorithm 2, line 3: the frame and the features the registration needs.
  Frame cur;
  try {
    cur.image = timed(r.ms.prepare, [&] { return prepareRgbdImage(obs); });
  } catch (const std::exception& e) {
    r.path = {};                                                                // none
    return predict(std::move(r), FrameResult::Status::BadInput, errorText(e));  // no backtrace
  }
  report(m_registration->prepare(cur), r);
  if (!m_ref) return accept(std::move(cur), m_pose, std::move(r), true);
  // Lines 4-15: register against the reference, on the path the registration chooses.
  if (!m_after_gap) cur.guess = toIsometry((m_pose + m_velocity) - m_ref->pose);
  cur.velocity = m_twist;  // none after a time gap or a failure
  auto reg = m_registration->align(cur, m_ref->frame);
  report(reg, r);
  if (!reg.ok()) return failed(std::move(cur), std::move(r), reg.status, reg.detail);
  if (auto why = implausible(reg.T))
    return failed(std::move(cur), std::move(r), FrameResult::Status::ImplausibleMotion,
                  std::move(*why));
  // Line 16: G_n = G_ref T (eq. 8); this frame becomes the reference, or, tracking against a
  // keyframe, when the keyframe wears out.
  return accept(std::move(cur), m_ref->pose + toPose(reg.T), std::move(r), newKeyframe(reg));
}

std::optional<std::string> RgbdOdometry::implausible(const Eigen::Isometry3d& T) const {
  if (T.translation().norm() <= m_params.max_step_translation &&
      rotationDeg(T) <= m_params.max_step_rotation_deg)
    return std::nullopt;
  return "step of " + std::to_string(T.translation().norm()) + " m, " +
         std::to_string(rotationDeg(T)) + " deg";
}

FrameResult RgbdOdometry::predict(FrameResult r, FrameResult::Status why, std::string detail) {
  r.status = why;
  r.detail = std::move(detail);
  r.inlier_points.clear();
  m_previous_registered = false;
  m_twist.reset();  // measured again once two frames in a row have registered
  ++m_failures;
  ++m_flagged_run;
  // beyond max_predicted_frames the motion is no longer extrapolated: the pose and the next
  // frames' prediction hold
  if (m_params.max_predicted_frames > 0 && m_flagged_run > m_params.max_predicted_frames)
    m_velocity = mrpt::poses::CPose3D();
  if (m_params.on_failure == FailurePolicy::ConstantVelocity) m_pose = m_pose + m_velocity;
  r.pose = m_pose;
  return r;
}

FrameResult RgbdOdometry::failed(Frame frame, FrameResult r, FrameResult::Status why,
                                 std::string detail) {
  r = predict(std::move(r), why, std::move(detail));
  // the keyframe is out of reach (the camera moved on, or the keyframe was a poor one): this frame
  // takes its place at the predicted pose; the error of that prediction stays in the trajectory,
  // but the frames after it can register again
  if (m_params.keyframe_after_failures > 0 && m_failures >= m_params.keyframe_after_failures) {
    m_ref = Reference{std::move(frame), m_pose};
    m_failures = 0;
    m_after_gap = false;  // the keyframe is after any gap: the motion from it is one frame's
    r.keyframe = true;
  }
  return r;
}

void RgbdOdometry::noteTimeGap(double t) {
  const double interval = m_last_t ? t - *m_last_t : 0;
  m_last_t = t;
  m_interval = interval;
  if (!(interval > 0)) return;  // the first frame, or time stamps out of order
  if (m_params.prediction_max_gap > 0 && m_mean_interval > 0 &&
      interval > m_params.prediction_max_gap * m_mean_interval) {
    m_after_gap = true;
    m_twist.reset();  // the velocity before the gap is not the one after it
  }
  // a running mean, so that one short interval (jittered stamps) makes no gap of the next
  m_mean_interval = m_mean_interval > 0 ? 0.8 * m_mean_interval + 0.2 * interval : interval;
}

bool RgbdOdometry::newKeyframe(const RegistrationResult& reg) const {
  return m_params.keyframe_max_translation <= 0 ||
         reg.T.translation().norm() > m_params.keyframe_max_translation ||
         rotationDeg(reg.T) > m_params.keyframe_max_rotation_deg ||
         reg.inliers < static_cast<std::size_t>(m_params.keyframe_min_inliers);
}

FrameResult RgbdOdometry::accept(Frame frame, const mrpt::poses::CPose3D& pose, FrameResult r,
                                 bool keyframe) {
  r.status = m_ref ? FrameResult::Status::Ok : FrameResult::Status::FirstFrame;
  r.keyframe = keyframe;
  // the motion of one frame: only between two registered frames (after a predicted pose, the
  // difference would carry the prediction's error into every later prediction)
  // (nor across a time gap)
  if (m_ref && m_previous_registered && !m_after_gap) {
    m_velocity = pose - m_pose;
    // over the time between the two frames, unless a jittered stamp puts them much nearer than
    // the mean interval (1 cm in 1 ms would be 10 m/s): then the velocity stays as it was
    if (m_interval > 0 && m_interval >= 0.5 * m_mean_interval) {
      const Eigen::Isometry3d M = toIsometry(m_velocity);
      const Eigen::AngleAxisd a(M.rotation());
      m_twist.emplace();
      *m_twist << M.translation() / m_interval, a.angle() / m_interval * a.axis();
      // a reference without one (the first frame, or taken after failures) moved much the same
      if (!m_ref->frame.velocity) m_ref->frame.velocity = m_twist;
    }
  }
  m_previous_registered = true;
  m_failures = 0;
  m_flagged_run = 0;
  m_after_gap = false;
  m_pose = pose;
  if (keyframe) {
    frame.velocity = m_twist;  // this frame's own motion, when measured now
    m_ref = Reference{std::move(frame), pose};
  }
  r.pose = m_pose;
  return r;
}

}  // namespace hrgbd
