// A pyramid kept for later use (the SLAM mode's keyframes) packed in 2 bytes a pixel: unpacked,
// its grey and depth are within the packing's precision, unknown depth stays unknown, and it
// refines as the pyramid it was made from.
#include <gtest/gtest.h>

#include <cmath>

#include "DenseRenders.h"

using namespace hrgbd::test;  // NOLINT: the rendered frames' helpers

TEST(DensePacking, AnUnpackedPyramidIsThePyramidWithinThePackingsPrecision) {
  auto pair = renderPair("desk", kMotion);
  const hrgbd::DenseParams p;
  auto& level = pair.ref.levels.front();
  level.depth.at<float>(10, 10) = std::numeric_limits<float>::quiet_NaN();
  level.depth.at<float>(10, 11) = 20;  // beyond the packed range (16.38 m): unknown
  const hrgbd::DensePyramid before = [&] {
    hrgbd::DensePyramid copy;
    for (const auto& l : pair.ref.levels)
      copy.levels.push_back({l.cam, l.grey.clone(), l.depth.clone(), {}, {}, 0, {}});
    return copy;
  }();
  hrgbd::packLevels(pair.ref);
  for (const auto& l : pair.ref.levels) {
    EXPECT_EQ(l.grey.elemSize(), 2u);
    EXPECT_EQ(l.depth.elemSize(), 2u);
    EXPECT_FALSE(hrgbd::hasDerivatives(l));
  }
  hrgbd::unpackLevels(pair.ref);
  std::size_t known = 0;
  for (std::size_t i = 0; i < before.levels.size(); ++i) {
    const auto &a = before.levels[i], &b = pair.ref.levels[i];
    ASSERT_EQ(b.grey.type(), CV_32F);
    ASSERT_EQ(b.depth.type(), CV_32F);
    EXPECT_LE(cv::norm(a.grey, b.grey, cv::NORM_INF), 0.0625);
    for (int v = 0; v < a.depth.rows; ++v)
      for (int u = 0; u < a.depth.cols; ++u) {
        const float za = a.depth.at<float>(v, u), zb = b.depth.at<float>(v, u);
        if (std::isfinite(za) && za < 16) {
          ASSERT_NEAR(zb, za, 0.000125 + 1e-6) << u << ", " << v;
          ++known;
        } else {
          ASSERT_TRUE(std::isnan(zb)) << u << ", " << v << ": " << za << " -> " << zb;
        }
      }
  }
  EXPECT_GT(known, 50000u);
  EXPECT_TRUE(std::isnan(pair.ref.levels.front().depth.at<float>(10, 11)));
  // and it is a reference again once its derivatives are made
  hrgbd::addDerivatives(pair.ref, p);
  const auto d = hrgbd::refineDense(pair.cur, pair.ref, {perturbed(pair.truth, 0.01, 1.0)}, p);
  ASSERT_TRUE(d.ok) << d.detail;
  EXPECT_LT(error(d.T, pair.truth).first, 0.001);
}
