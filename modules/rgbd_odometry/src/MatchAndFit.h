#pragma once
// Private: the steps both feature paths share: mutual matching, then a robust fit.
#include "rgbd_odometry/FeatureRegistration.h"

namespace hrgbd {

/** Matches `source` (current frame) with `target` (reference) mutually under `norm` and fits
 * the correspondences with `estimate`. Fills status, T, detail, matches, inliers, scale,
 * inlier points and the matching / estimation times of the result. */
RegistrationResult matchAndFit(const FeatureSet& source, const FeatureSet& target, int norm,
                               double max_distance, const RigidEstimator& estimate);

/** ORB features with depth of `f` (0 when they were not computed). */
inline std::size_t orbCount(const Frame& f) { return f.orb ? f.orb->size() : 0; }

}  // namespace hrgbd
