// A pyramid kept for later use (the SLAM mode's keyframes) packed in 2 bytes a pixel: refused while
// packed; unpacked,
// its grey and depth are within the packing's precision, unknown depth stays unknown, and it
// refines as the pyramid it was made from.
#include <gtest/gtest.h>

#include <cmath>

#include "DenseRenders.h"

using namespace hrgbd::test;  // NOLINT: the rendered frames' helpers

TEST(DensePacking, AnUnpackedPyramidIsThePyramidWithinThePackingsPrecision) {
  auto pair = renderPair("desk", kMotion);
  const hrgbd::DenseParams p;
  auto& finest = pair.ref.levels.front();
  finest.depth.at<float>(10, 10) = std::numeric_limits<float>::quiet_NaN();
  finest.depth.at<float>(10, 11) = 20;  // far beyond max_depth: the units follow the farthest
  std::vector<cv::Mat> grey, depth;
  for (const auto& l : pair.ref.levels)
    grey.push_back(l.grey.clone()), depth.push_back(l.depth.clone());
  hrgbd::packLevels(pair.ref);
  std::vector<double> units;
  for (const auto& l : pair.ref.levels) {
    EXPECT_EQ(l.grey.elemSize(), 2u);
    EXPECT_EQ(l.depth.elemSize(), 2u);
    EXPECT_FALSE(hrgbd::hasDerivatives(l));
    units.push_back(l.packed_depth_units);
  }
  EXPECT_NEAR(units.front(), 65534 / 20.0, 1e-9);
  // packed, it is refused, not read as what it was
  const auto refused = hrgbd::refineDense(pair.cur, pair.ref, {pair.truth}, p);
  EXPECT_FALSE(refused.ok);
  EXPECT_NE(refused.detail.find("packed"), std::string::npos) << refused.detail;
  hrgbd::unpackLevels(pair.ref);
  std::size_t known = 0;
  for (std::size_t i = 0; i < grey.size(); ++i) {
    const auto& b = pair.ref.levels[i];
    ASSERT_EQ(b.grey.type(), CV_32F);
    ASSERT_EQ(b.depth.type(), CV_32F);
    EXPECT_EQ(b.packed_depth_units, 0);
    EXPECT_LE(cv::norm(grey[i], b.grey, cv::NORM_INF), 1.0 / 16);
    for (int v = 0; v < depth[i].rows; ++v)
      for (int u = 0; u < depth[i].cols; ++u) {
        const float za = depth[i].at<float>(v, u), zb = b.depth.at<float>(v, u);
        if (std::isfinite(za)) {
          ASSERT_NEAR(zb, za, 0.5 / units[i] + 1e-6) << u << ", " << v;
          ++known;
        } else {
          ASSERT_TRUE(std::isnan(zb)) << u << ", " << v << ": " << za << " -> " << zb;
        }
      }
  }
  EXPECT_GT(known, 50000u);
  EXPECT_NEAR(pair.ref.levels.front().depth.at<float>(10, 11), 20, 1e-3);
  // and it is a reference again once its derivatives are made
  hrgbd::addDerivatives(pair.ref, p);
  const auto d = hrgbd::refineDense(pair.cur, pair.ref, {perturbed(pair.truth, 0.01, 1.0)}, p);
  ASSERT_TRUE(d.ok) << d.detail;
  EXPECT_LT(error(d.T, pair.truth).first, 0.001);
}
