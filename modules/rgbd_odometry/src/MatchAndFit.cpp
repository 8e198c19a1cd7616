#include "MatchAndFit.h"

#include "rgbd_odometry/DescriptorMatching.h"

namespace hrgbd {
namespace {

FrameResult::Status fromEstimate(RigidEstimate::Status s) {
  using E = RigidEstimate::Status;
  using F = FrameResult::Status;
  switch (s) {
    case E::Ok:
      return F::Ok;
    case E::TooFewMatches:
      return F::TooFewMatches;
    case E::DegenerateSamples:
      return F::DegenerateSamples;
    case E::TooFewInliers:
      return F::TooFewInliers;
    case E::LargeResiduals:
      return F::LargeResiduals;
  }
  return F::TooFewInliers;  // unreachable: every status is handled above
}

Correspondences correspondences(const MatchResult& m, const FeatureSet& source,
                                const FeatureSet& target) {
  Correspondences c;
  for (const auto& x : m.matches) {
    c.source.push_back(source.points[x.source]);
    c.target.push_back(target.points[x.target]);
  }
  return c;
}

}  // namespace

RegistrationResult matchAndFit(const FeatureSet& source, const FeatureSet& target, int norm,
                               double max_distance, const RigidEstimator& estimate) {
  RegistrationResult r;
  r.seen.features = source.size();
  // Algorithm 2 line 14: mutual matching against the reference frame.
  const Correspondences corr = timed(r.seen.ms.matching, [&] {
    return correspondences(matchMutual(source.descriptors, target.descriptors, norm, max_distance),
                           source, target);
  });
  r.matches = corr.size();
  // Line 15: robust estimation.
  const RigidEstimate est = timed(r.seen.ms.estimation, [&] { return estimate(corr); });
  r.status = fromEstimate(est.status);
  r.T = est.T;
  r.detail = toString(est.status);
  r.inliers = est.inliers.size();
  r.scale = est.scale;
  r.sparse_ok = r.ok();
  if (est.ok())
    for (const auto i : est.inliers) r.inlier_points.push_back(corr.source[i].cast<float>());
  return r;
}

}  // namespace hrgbd
