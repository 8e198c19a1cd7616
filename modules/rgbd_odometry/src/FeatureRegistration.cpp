#include "rgbd_odometry/FeatureRegistration.h"

#include <opencv2/core.hpp>

#include "MatchAndFit.h"
#include "rgbd_core/Config.h"
#include "rgbd_odometry/OdometryParams.h"
#include "rgbd_odometry/PlaneIcp.h"

namespace hrgbd {
namespace {

// The geometric features of `f`, computed on first use (a reference keeps them); none when the
// frame kept no depth image (the SLAM mode's keyframes keep features only).
const GeometricFeatures& geometricOf(Frame& f, const GeometricParams& p, StageTimes& ms) {
  if (!f.geometric && f.image.depth.empty()) f.geometric = GeometricFeatures{};
  if (!f.geometric)
    f.geometric = timed(ms.features, [&] { return extractGeometricFeatures(f.image, p); });
  return *f.geometric;
}

RegistrationResult withTimes(RegistrationResult r, const StageTimes& earlier) {
  r.seen.ms += earlier;
  return r;
}

}  // namespace

RigidEstimator msseEstimator(const MsseParams& params) {
  return [params](const Correspondences& c) { return estimateMsse(c, params); };
}

PhotometricRegistration::PhotometricRegistration(const OrbParams& orb, int max_hamming_distance,
                                                 RigidEstimator estimator)
    : m_orb(orb), m_max_hamming(max_hamming_distance), m_estimate(std::move(estimator)) {}

FrameFeatures PhotometricRegistration::prepare(Frame& frame) {
  FrameFeatures seen;
  seen.path.sparse = FramePath::Sparse::Photometric;
  if (!frame.orb)
    frame.orb = timed(seen.ms.features, [&] { return extractOrbFeatures(frame.image, m_orb); });
  seen.orb_features = seen.features = frame.orb->size();
  return seen;
}

RegistrationResult PhotometricRegistration::align(Frame& cur, Frame& ref) {
  StageTimes ms = prepare(cur).ms;  // no-op for prepared frames
  ms += prepare(ref).ms;
  auto r = matchAndFit(*cur.orb, *ref.orb, cv::NORM_HAMMING, m_max_hamming, m_estimate);
  r.seen.path.sparse = FramePath::Sparse::Photometric;
  r.seen.orb_features = orbCount(cur);
  return withTimes(std::move(r), ms);
}

GeometricRegistration::GeometricRegistration(const GeometricParams& geometric,
                                             const MsseParams& msse)
    : m_params(geometric), m_msse(msse) {}

FrameFeatures GeometricRegistration::prepare(Frame& frame) {
  FrameFeatures seen;
  seen.path.sparse = FramePath::Sparse::Geometric;
  seen.orb_features = orbCount(frame);
  seen.features = geometricOf(frame, m_params, seen.ms).features.size();
  return seen;
}

RegistrationResult GeometricRegistration::align(Frame& cur, Frame& ref) {
  // Algorithm 2 lines 5-10 for both frames (the reference's are kept once computed).
  StageTimes ms;
  const GeometricFeatures& src = geometricOf(cur, m_params, ms);
  const GeometricFeatures& dst = geometricOf(ref, m_params, ms);
  auto r = matchAndFit(src.features, dst.features, cv::NORM_L2, m_params.max_descriptor_distance,
                       msseEstimator(m_msse));
  r.seen.path.sparse = FramePath::Sparse::Geometric;
  r.seen.orb_features = orbCount(cur);
  r.seen.ms += ms;
  if (!r.ok() || m_params.refine_iterations == 0) return r;
  const auto icp = timed(r.seen.ms.refine, [&] {
    const PointKdTree tree(dst.cloud);
    return refinePointToPlane(src.cloud, dst.cloud, dst.normals, tree, r.T,
                              m_params.refine_iterations, m_params.refine_max_distance);
  });
  r.T = icp.T;
  // A wrong MSSE estimate leaves most of the clouds unpaired (measured on fr3/teddy: 21 % for a
  // 26 cm error, >= 80 % for every frame within 2 cm).
  const double overlap = double(icp.pairs) / std::max<std::size_t>(src.cloud.size(), 1);
  if (overlap < m_params.refine_min_overlap) {
    r.status = FrameResult::Status::LargeResiduals;
    r.sparse_ok = false;
    r.detail = "clouds overlap " + std::to_string(int(100 * overlap)) + " % after refinement";
  }
  return r;
}

HybridRegistration::HybridRegistration(std::unique_ptr<Registration> photometric,
                                       std::unique_ptr<Registration> geometric,
                                       const HybridPolicy& policy)
    : m_photometric(std::move(photometric)), m_geometric(std::move(geometric)), m_policy(policy) {}

bool HybridRegistration::fewOrb(const Frame& f) const {
  return orbCount(f) < static_cast<std::size_t>(m_policy.min_orb_features);
}

FrameFeatures HybridRegistration::prepare(Frame& frame) {
  FrameFeatures seen = m_photometric->prepare(frame);
  if (!fewOrb(frame)) return seen;
  // Line 4: too few visual features -> geometric path (III-A).
  FrameFeatures geo = m_geometric->prepare(frame);
  geo.ms += seen.ms;
  return geo;
}

RegistrationResult HybridRegistration::align(Frame& cur, Frame& ref) {
  if (fewOrb(cur)) return m_geometric->align(cur, ref);
  auto photometric = m_photometric->align(cur, ref);
  if (!photometric.ok() && !m_policy.geometric_fallback) return photometric;
  // Beyond the paper: a photometric fit on few inliers (a plain structure seen from afar has
  // 80-94 ORB features but 9-26 inliers) is replaced by the geometric path's when that
  // registers; otherwise it stands (on fr3/cabinet such fits erred 0.3-17 cm on 7-23 cm
  // steps, mostly better than a prediction). A failed photometric frame takes the geometric
  // result, whatever it is.
  if (photometric.ok() &&
      photometric.inliers >= static_cast<std::size_t>(m_policy.min_photometric_inliers))
    return photometric;
  auto geometric = m_geometric->align(cur, ref);
  if (geometric.ok() || !photometric.ok())
    return withTimes(std::move(geometric), photometric.seen.ms);
  return withTimes(std::move(photometric), geometric.seen.ms);
}

namespace {

std::unique_ptr<Registration> makeSparseRegistration(const OdometryParams& p) {
  auto photometric = [&] {
    return std::make_unique<PhotometricRegistration>(p.orb, p.max_hamming_distance,
                                                     msseEstimator(p.msse));
  };
  auto geometric = [&] {
    MsseParams msse = p.msse;  // SHOT matches are mostly outliers: k' of their own
    msse.k_fraction = p.geometric_k_fraction;
    return std::make_unique<GeometricRegistration>(p.geometric, msse);
  };
  switch (p.method) {
    case Method::Hybrid:
      return std::make_unique<HybridRegistration>(
          photometric(), geometric(),
          HybridPolicy{p.min_orb_features, p.min_photometric_inliers, p.geometric_fallback});
    case Method::RgbOnly:
      return photometric();
    case Method::DepthOnly:
      return geometric();
    default:
      throw ConfigError("[Odometry] method = " + toString(p.method) +
                        ": a baseline or peer, made by rgbd_baselines (makeAnyRegistration)");
  }
}

}  // namespace

std::unique_ptr<Registration> makeRegistration(const OdometryParams& p,
                                               std::size_t refine_min_inliers) {
  auto sparse = makeSparseRegistration(p);
  if (!p.dense.enabled) return sparse;
  return std::make_unique<DenseRefined>(std::move(sparse), p.dense, refine_min_inliers);
}

}  // namespace hrgbd
