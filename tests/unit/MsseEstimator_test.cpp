#include "rgbd_odometry/MsseEstimator.h"

#include <cstdio>

#include "TestData.h"
#include "rgbd_baselines/RansacEstimator.h"
#include "unit/SyntheticCorrespondences.h"

using namespace hrgbd;

TEST(MsseEstimator, InlierCountFollowsEquations4And5) {
  // 10 residuals of 1 cm then a jump to 10 cm: with p = 6, T = 2.5 the growth stops at 10.
  std::vector<double> r(10, 0.01);
  r.insert(r.end(), {0.10, 0.11, 0.12});
  double sigma = 0;
  EXPECT_EQ(msseInlierCount(r, 7, 2.5, 6, &sigma), 10u);
  EXPECT_NEAR(sigma, std::sqrt(10 * 0.0001 / (10 - 6)), 1e-12);  // eq. (5)
}

TEST(MsseEstimator, ExactRecoveryWithoutNoise) {
  const auto T = test::knownMotion();
  const auto est = estimateMsse(test::makeCorrespondences(T, 100, 0, 0, 3), MsseParams());
  ASSERT_TRUE(est.ok()) << toString(est.status);
  EXPECT_LT(test::rotationErrorDeg(est.T, T), 1e-6);
  EXPECT_LT(test::translationError(est.T, T), 1e-8);
  EXPECT_GE(est.inliers.size(), 95u);  // sigma ~ 0: rounding noise may cut the last few
}

TEST(MsseEstimator, GracefulWithNoise) {
  const auto T = test::knownMotion();
  const auto est = estimateMsse(test::makeCorrespondences(T, 300, 0.005, 0.2, 4), MsseParams());
  ASSERT_TRUE(est.ok());
  EXPECT_LT(test::rotationErrorDeg(est.T, T), 0.2);
  EXPECT_LT(test::translationError(est.T, T), 0.005);
  EXPECT_NEAR(est.scale, 0.005 * std::sqrt(3.0), 0.004);  // 3D residual of 5 mm per axis
}

TEST(MsseEstimator, SameSeedSameResult) {
  const auto c = test::makeCorrespondences(test::knownMotion(), 200, 0.01, 0.5, 5);
  const auto a = estimateMsse(c, MsseParams()), b = estimateMsse(c, MsseParams());
  EXPECT_TRUE(a.T.isApprox(b.T, 0));
}

TEST(MsseEstimator, TooFewMatchesAndDegenerateDataAreStatuses) {
  const auto few = estimateMsse(test::makeCorrespondences(test::knownMotion(), 5, 0, 0, 6), {});
  EXPECT_EQ(few.status, RigidEstimate::Status::TooFewMatches);
  Correspondences line;
  for (int i = 0; i < 30; ++i)
    line.source.emplace_back(0.1 * i, 0, 2), line.target.emplace_back(0.1 * i, 0, 2);
  EXPECT_EQ(estimateMsse(line, {}).status, RigidEstimate::Status::DegenerateSamples);
}

// Breakdown: success (rotation < 1 deg and translation < 2 cm) over 30 random data sets of 300
// matches with 1 cm noise, per outlier ratio, for MSSE (k' = 0.2 and the default 0.5) and for
// RANSAC on the same data. Measured (30 each), outliers 50/60/70/80 %:
//   MSSE k'=0.2: 30/30/30/22   MSSE k'=0.5: 19/0/0/0   RANSAC (3 cm): 30/30/30/29
TEST(MsseEstimator, BreakdownAgainstRansac) {
  const auto T = test::knownMotion();
  MsseParams robust;
  robust.k_fraction = 0.2;
  std::printf("outliers  MSSE k'=0.2  MSSE k'=0.5  RANSAC  (successes of 30)\n");
  for (double ratio : {0.5, 0.6, 0.7, 0.8}) {
    int msse_robust = 0, msse_default = 0, ransac_ok = 0;
    for (unsigned s = 0; s < 30; ++s) {
      const auto c = test::makeCorrespondences(T, 300, 0.01, ratio, 100 + s);
      auto good = [&](const RigidEstimate& e) {
        return e.ok() && test::rotationErrorDeg(e.T, T) < 1.0 &&
               test::translationError(e.T, T) < 0.02;
      };
      msse_robust += good(estimateMsse(c, robust));
      msse_default += good(estimateMsse(c, MsseParams()));
      ransac_ok += good(estimateRansac(c, RansacParams()));
    }
    std::printf("  %.0f %%       %2d           %2d          %2d\n", 100 * ratio, msse_robust,
                msse_default, ransac_ok);
    if (ratio <= 0.7) {
      EXPECT_GE(msse_robust, 28) << ratio;
    }
    if (ratio >= 0.6) {
      EXPECT_LE(msse_default, 5) << "k' = 0.5 cannot survive a majority of outliers";
    }
    EXPECT_GE(ransac_ok, 27) << ratio;
  }
}

TEST(RansacEstimator, RecoversWithOutliers) {
  const auto T = test::knownMotion();
  const auto est = estimateRansac(test::makeCorrespondences(T, 300, 0.005, 0.5, 9), RansacParams());
  ASSERT_TRUE(est.ok());
  EXPECT_LT(test::rotationErrorDeg(est.T, T), 0.3);
  EXPECT_LT(test::translationError(est.T, T), 0.01);
}
