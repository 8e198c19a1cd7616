#include <mrpt/poses/CPose3D.h>
#include <mrpt/poses/CPose3DQuat.h>
#include <mrpt/tfest/se3.h>

#include "TestData.h"
#include "unit/SyntheticCorrespondences.h"

using namespace hrgbd;

TEST(RigidFit, ExactRecoveryWithoutNoise) {
  const auto T = test::knownMotion();
  const auto c = test::makeCorrespondences(T, 20, 0, 0, 1);
  const auto est = fitRigidWeighted(c, depthWeights(c, true));
  EXPECT_LT(test::rotationErrorDeg(est, T), 1e-6);
  EXPECT_LT(test::translationError(est, T), 1e-9);
}

TEST(RigidFit, UnitWeightsAgreeWithMrptHorn) {
  const auto c = test::makeCorrespondences(test::knownMotion(), 50, 0.01, 0, 2);
  const auto ours = fitRigidWeighted(c, std::vector<double>(c.size(), 1.0));
  std::vector<mrpt::math::TPoint3D> tgt, src;
  for (size_t i = 0; i < c.size(); ++i) {
    tgt.emplace_back(c.target[i].x(), c.target[i].y(), c.target[i].z());
    src.emplace_back(c.source[i].x(), c.source[i].y(), c.source[i].z());
  }
  mrpt::poses::CPose3DQuat q;
  double scale;
  ASSERT_TRUE(mrpt::tfest::se3_l2(tgt, src, q, scale, true));
  const Eigen::Matrix4d H =
      mrpt::poses::CPose3D(q).getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>().asEigen();
  EXPECT_LT((H - ours.matrix()).norm(), 1e-8);
}

TEST(RigidFit, WeightsFavourNearPairs) {
  Correspondences c;
  c.source = {{0, 0, 1}, {0, 0, 4}};
  c.target = c.source;
  const auto w = depthWeights(c, true);
  EXPECT_GT(w[0], 10 * w[1]);            // (1+1) vs (16+16)
  EXPECT_NEAR(w[0] + w[1], 2.0, 1e-12);  // normalised to mean 1
  EXPECT_EQ(depthWeights(c, false), std::vector<double>(2, 1.0));
}

TEST(RigidFit, DegenerateTriplesAreDetected) {
  const Eigen::Vector3d a(0, 0, 1), b(1, 0, 1), c(2, 0.001, 1), d(0, 1, 1);
  EXPECT_TRUE(isDegenerateTriple(a, b, c, 0.01));   // nearly collinear
  EXPECT_TRUE(isDegenerateTriple(a, a, d, 0.01));   // two coincide
  EXPECT_FALSE(isDegenerateTriple(a, b, d, 0.01));  // a proper triangle
}

TEST(RigidFit, CollinearDataYieldsOnlyDegenerateSamples) {
  Correspondences c;
  for (int i = 0; i < 30; ++i) {
    c.source.emplace_back(0.1 * i, 0, 2);
    c.target.emplace_back(0.1 * i + 0.05, 0, 2);
  }
  int visited = 0;
  const auto degenerate = forEachHypothesis(c, std::vector<double>(30, 1.0), 100, 7, 0.01,
                                            [&](const Eigen::Isometry3d&) { ++visited; });
  EXPECT_EQ(visited, 0);
  EXPECT_EQ(degenerate, 100u);
}
