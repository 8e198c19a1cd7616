#pragma once
/** \file FeatureRegistration.h
 * The paper's two registration paths and its hybrid policy (sections III-A to III-H).
 * Each is a Registration; the estimator is a parameter so the RANSAC baseline reuses the
 * photometric path unchanged. */
#include <functional>
#include <memory>

#include "rgbd_odometry/GeometricParams.h"
#include "rgbd_odometry/MsseEstimator.h"
#include "rgbd_odometry/OrbFeatures.h"
#include "rgbd_odometry/Registration.h"
#include "rgbd_odometry/RigidFit.h"

namespace hrgbd {

/** A robust rigid fit of correspondences (source = current frame, target = reference). */
using RigidEstimator = std::function<RigidEstimate(const Correspondences&)>;

/** MSSE (eqs. 4-7) with `params`, as a RigidEstimator. */
RigidEstimator msseEstimator(const MsseParams& params);

/** Photometric path (III-B, Algorithm 2 lines 3, 14-15): ORB features back-projected with the
 * depth, mutual Hamming matching, robust fit. */
class PhotometricRegistration : public Registration {
 public:
  /** \param max_hamming_distance [bits] farther ORB pairs are never matched */
  PhotometricRegistration(const OrbParams& orb, int max_hamming_distance, RigidEstimator estimator);
  FrameFeatures prepare(Frame& frame) override;
  RegistrationResult align(Frame& cur, Frame& ref) override;

 private:
  OrbParams m_orb;
  int m_max_hamming;
  RigidEstimator m_estimate;
};

/** Geometric path (III-C to III-F, Algorithm 2 lines 5-10): IS3D points with SHOT descriptors,
 * mutual L2 matching, MSSE, then (beyond the paper) a point-to-plane refinement whose overlap
 * rejects wrong fits. */
class GeometricRegistration : public Registration {
 public:
  /** `msse` is used as given: pass the k' for SHOT matches (geometric_k_fraction). */
  GeometricRegistration(const GeometricParams& geometric, const MsseParams& msse);
  FrameFeatures prepare(Frame& frame) override;
  RegistrationResult align(Frame& cur, Frame& ref) override;

 private:
  GeometricParams m_params;
  MsseParams m_msse;
};

/** Parameters of the hybrid policy (fields of [Odometry]; see OdometryParams). */
struct HybridPolicy {
  int min_orb_features = 50;         //!< [count] fewer ORB features: geometric path (III-A)
  int min_photometric_inliers = 30;  //!< [count] fewer: the geometric fit replaces it if ok
  bool geometric_fallback = true;    //!< a failed photometric frame tries the geometric path
};

/** The paper's switch (III-A): the photometric path unless the frame has too few ORB features;
 * beyond the paper, a failed or weak (few inliers) photometric fit hands over to the geometric
 * path when that registers. */
class HybridRegistration : public Registration {
 public:
  HybridRegistration(std::unique_ptr<Registration> photometric,
                     std::unique_ptr<Registration> geometric, const HybridPolicy& policy);
  FrameFeatures prepare(Frame& frame) override;
  RegistrationResult align(Frame& cur, Frame& ref) override;

 private:
  bool fewOrb(const Frame& f) const;
  std::unique_ptr<Registration> m_photometric, m_geometric;
  HybridPolicy m_policy;
};

/** Any registration followed by the dense refinement (DenseRefinement.h), which starts from its
 * estimate, or from the tracker's prediction when it found none. A refinement that changes the
 * start by more than max_correction[_deg] is not trusted: the frame is flagged (LargeResiduals).
 * A scene whose texture and structure leave a direction of the motion free is flagged
 * (Degenerate: min_texture_pairs). A refinement alone (no estimate of the inner registration)
 * must also explain the reference's depth (min_depth_agreement), or the inner registration's
 * failure stands. With `min_inliers` > 0
 * only an inner estimate on at least that many inliers is refined, and the inner result stands
 * otherwise (the SLAM mode's loop verification, which needs as many: refining the others is
 * work thrown away). */
class DenseRefined : public Registration {
 public:
  DenseRefined(std::unique_ptr<Registration> inner, const DenseParams& params,
               std::size_t min_inliers = 0);
  FrameFeatures prepare(Frame& frame) override;
  RegistrationResult align(Frame& cur, Frame& ref) override;

 private:
  std::unique_ptr<Registration> m_inner;
  DenseParams m_params;
  std::size_t m_min_inliers = 0;
};

}  // namespace hrgbd
