#include <mrpt/core/bits_math.h>

#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>

#include "rgbd_core/PoseGap.h"
#include "rgbd_core/Timing.h"
#include "rgbd_odometry/DepthAgreement.h"
#include "rgbd_odometry/FeatureRegistration.h"

namespace hrgbd {
namespace {

// Whether b is within `metres` and `deg` of a.
bool near(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, double metres, double deg) {
  const PoseGap g = poseGap(a, b);
  return g.metres <= metres && mrpt::RAD2DEG(g.radians) <= deg;
}

// The depth check of a motion (DenseParams::min_depth_agreement).
struct DepthCheck {
  bool judged = false;  //!< at least min_pixels points landed on known reference depth
  bool passed = false;  //!< agrees, or not judged (nothing to judge by)
  std::string why;      //!< why it does not vouch for the motion: short, or not judged
};

// every `stride`-th pixel (2: as many points as the default finest level's), within 3 sigma of
// the depth-noise model of two readings, at least `floor` of them (min_depth_agreement or
// min_depth_agreement_sparse); its time is added to `ms`
DepthCheck checkDepth(const Frame& cur, const Frame& ref, const Eigen::Isometry3d& T,
                      const DenseParams& p, double& ms, double floor, int stride = 2) {
  const DepthTolerance within3sigma{0, 3 * std::sqrt(2.0) * p.depth_noise};
  const DepthAgreement a =
      timed(ms, [&] { return depthAgreement(cur.image, ref.image, T, within3sigma, stride); });
  DepthCheck c;
  c.judged = a.compared * stride * stride >= static_cast<std::size_t>(4 * p.min_pixels);
  c.passed = !c.judged || a.share() >= floor;
  if (!c.judged) c.why = "too few points on known reference depth";
  if (!c.passed) {
    std::ostringstream why;
    why << std::setprecision(2) << a.share()
        << " of the points on known reference depth agree with the reference depth (< " << floor
        << ")";
    c.why = why.str();
  }
  return c;
}

// Why the refined motion d is not constrained by the data (DenseParams::min_texture_pairs), or
// nothing.
std::optional<std::string> unconstrained(const DenseResult& d, const DenseParams& p) {
  const bool textured = d.photometric_pairs >= static_cast<std::size_t>(p.min_texture_pairs) &&
                        d.texture_isotropy >= p.min_texture_isotropy;
  if (textured || d.normal_spread >= p.min_normal_spread) return std::nullopt;
  std::ostringstream why;
  why << std::setprecision(2);
  if (d.photometric_pairs < static_cast<std::size_t>(p.min_texture_pairs))
    why << d.photometric_pairs << " intensity pairs (< min_texture_pairs " << p.min_texture_pairs
        << ")";
  else
    why << "texture in one direction (isotropy " << d.texture_isotropy << " < min_texture_isotropy "
        << p.min_texture_isotropy << ")";
  why << " and surfaces facing fewer than three directions (normal spread " << d.normal_spread
      << " < min_normal_spread " << p.min_normal_spread << ")";
  return why.str();
}

}  // namespace

DenseRefined::DenseRefined(std::unique_ptr<Registration> inner, const DenseParams& params,
                           std::size_t min_inliers)
    : m_inner(std::move(inner)), m_params(params), m_min_inliers(min_inliers) {}

FrameFeatures DenseRefined::prepare(Frame& frame) {
  FrameFeatures seen = m_inner->prepare(frame);
  // its derivatives only once it is a reference (align): they are 1.05 of a pyramid's 1.63 ms
  // (odometry_benchmark), and 132 of fr1/rpy's 240 frames, 143 of teddy's 193 never become one
  if (!frame.dense)
    frame.dense =
        timed(seen.ms.refine, [&] { return buildDensePyramid(frame.image, m_params, false); });
  return seen;
}

RegistrationResult DenseRefined::align(Frame& cur, Frame& ref) {
  RegistrationResult r = m_inner->align(cur, ref);
  if (m_min_inliers > 0 && (!r.ok() || r.inliers < m_min_inliers)) return r;
  if (!ref.dense) prepare(ref);
  std::vector<Eigen::Isometry3d> starts;
  if (r.ok()) starts.push_back(r.T);
  // the prediction competes with the sparse estimate when they disagree (beyond 1 cm, 1 deg)
  if (cur.guess && (starts.empty() || !near(starts[0], *cur.guess, 0.01, 1.0)))
    starts.push_back(*cur.guess);
  if (starts.empty()) return r;
  // the rolling shutter of both frames or of neither: the skews of two frames moving alike
  // mostly cancel, and undoing one alone would leave the other's whole
  const double readout = m_params.rolling_shutter_ms * 1e-3;  // [s]
  ReadoutMotion cur_readout = ReadoutMotion::Zero(), ref_readout = ReadoutMotion::Zero();
  if (readout > 0 && cur.velocity && ref.velocity) {
    cur_readout = *cur.velocity * readout;
    ref_readout = *ref.velocity * readout;
  }
  const DenseResult d = timed(r.seen.ms.refine, [&] {
    addDerivatives(*ref.dense, m_params);  // on its first use as a reference
    return refineDense(*cur.dense, *ref.dense, starts, m_params, cur_readout, ref_readout);
  });
  r.seen.path.refined = FramePath::Refined::Refused;  // until a start is taken below
  if (!d.ok) {
    if (!r.ok()) r.detail += "; " + d.detail;
    return r;  // too little to refine with: the sparse estimate stands (or the failure)
  }
  if (const auto why = unconstrained(d, m_params)) {
    r.status = FrameResult::Status::Degenerate;
    r.detail = "dense: the scene does not constrain the motion: " + *why;
    return r;
  }
  // A refinement that no sparse estimate supports must explain the reference's depth: one alone,
  // or one from the prediction that fitted better than the sparse fit's. Where it does not, the
  // sparse fit's own refinement is taken if that explains it, and otherwise the frame is refused.
  // Where fewer than min_pixels points land on known reference depth (a keyframe without depth),
  // there is nothing to judge by, and the intensity pairs stand.
  Eigen::Isometry3d T = d.T;
  std::size_t start = d.start;
  if (m_params.min_depth_agreement > 0 && (!r.ok() || d.start != 0)) {
    const DepthCheck winner =
        checkDepth(cur, ref, d.T, m_params, r.seen.ms.refine, m_params.min_depth_agreement);
    if (!winner.passed && !r.ok()) {
      r.detail += "; dense: " + winner.why + ": the motion found does not explain it";
      return r;
    }
    if (!winner.passed) {
      const DepthCheck sparse = d.first_start_refined
                                    ? checkDepth(cur, ref, *d.first_start_refined, m_params,
                                                 r.seen.ms.refine, m_params.min_depth_agreement)
                                    : DepthCheck{};
      if (!sparse.judged || !sparse.passed) {
        r.status = FrameResult::Status::LargeResiduals;
        r.detail = "dense: from the motion prediction, " + winner.why + "; from the sparse fit, " +
                   (d.first_start_refined ? sparse.why : "its normal equations not finite") +
                   ": neither motion explains it";
        return r;
      }
      T = *d.first_start_refined, start = 0;
    }
  }
  // the sparse fit's refinement must explain some of the reference's depth too: frames of noise
  // (random colour and depth), whose features match by chance, do not
  if (m_params.min_depth_agreement_sparse > 0 && start == 0 && r.ok()) {
    const DepthCheck c =
        checkDepth(cur, ref, T, m_params, r.seen.ms.refine, m_params.min_depth_agreement_sparse, 4);
    if (!c.passed) {
      r.status = FrameResult::Status::LargeResiduals;
      r.detail = "dense: from the sparse fit, " + c.why + ": the motion does not explain it";
      return r;
    }
  }
  if (!near(starts[start], T, m_params.max_correction, m_params.max_correction_deg)) {
    r.status = FrameResult::Status::LargeResiduals;
    r.detail = "dense refinement moved the start that fitted best too far: not trusted";
    return r;
  }
  // start 0 is the sparse fit's when there was one, else the prediction's
  r.seen.path.refined =
      r.ok() && start == 0 ? FramePath::Refined::Sparse : FramePath::Refined::Prediction;
  r.T = T;
  r.status = FrameResult::Status::Ok;
  return r;
}

}  // namespace hrgbd
