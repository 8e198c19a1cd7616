#include "rgbd_odometry/DescriptorMatching.h"

#include "TestData.h"

namespace {
cv::Mat rows(std::initializer_list<std::initializer_list<uint8_t>> v) {
  cv::Mat m(0, 1, CV_8U);
  for (auto r : v) m.push_back(cv::Mat(std::vector<uint8_t>(r)).t());
  return m;
}
}  // namespace

TEST(DescriptorMatching, MutualCheckAndDistanceLimit) {
  // One-byte binary descriptors. Source 0 and 1 both prefer target 0 (0x00); target 0 prefers
  // source 0 (distance 0), so source 1 fails the mutual check. Source 2 <-> target 1 is mutual
  // but 3 bits apart.
  const cv::Mat src = rows({{0x00}, {0x01}, {0xF0}});
  const cv::Mat tgt = rows({{0x00}, {0xF7}});
  const auto r = hrgbd::matchMutual(src, tgt, cv::NORM_HAMMING, 8);
  ASSERT_EQ(r.matches.size(), 2u);
  EXPECT_EQ(r.matches[0].source, 0);
  EXPECT_EQ(r.matches[0].target, 0);
  EXPECT_EQ(r.matches[1].source, 2);
  EXPECT_EQ(r.matches[1].target, 1);
  EXPECT_FLOAT_EQ(r.matches[1].distance, 3);
  EXPECT_EQ(r.rejected_by_mutual_check, 1u);
  const auto strict = hrgbd::matchMutual(src, tgt, cv::NORM_HAMMING, 2);
  EXPECT_EQ(strict.matches.size(), 1u);
  EXPECT_EQ(strict.rejected_by_distance, 1u);
  EXPECT_TRUE(hrgbd::matchMutual(cv::Mat(), tgt, cv::NORM_HAMMING, 8).matches.empty());
}

TEST(DescriptorMatching, FloatDescriptorsWithL2) {
  cv::Mat src = (cv::Mat_<float>(2, 2) << 0, 0, 1, 1),
          tgt = (cv::Mat_<float>(2, 2) << 1, 1.1f, 0, 0.1f);
  const auto r = hrgbd::matchMutual(src, tgt, cv::NORM_L2, 1.0);
  ASSERT_EQ(r.matches.size(), 2u);
  EXPECT_EQ(r.matches[0].target, 1);
  EXPECT_EQ(r.matches[1].target, 0);
}

TEST(DescriptorMatching, HandWrittenHammingAgreesWithOpenCv) {
  // 32-byte descriptors as ORB's, few distinct bytes so that ties are frequent. The reference is
  // OpenCV's distance matrix with the same first-index rule on ties. 283 targets: the AVX-512
  // path (where the CPU has it) takes them 8 at a time, and the last block is 3.
  cv::RNG rng(7);
  cv::Mat src(300, 32, CV_8U), tgt(283, 32, CV_8U);
  rng.fill(src, cv::RNG::UNIFORM, 0, 4);
  rng.fill(tgt, cv::RNG::UNIFORM, 0, 4);
  cv::Mat dist;
  cv::batchDistance(src, tgt, dist, CV_32S, cv::noArray(), cv::NORM_HAMMING, 0);
  std::vector<std::pair<int, int>> expected;
  for (int i = 0; i < dist.rows; ++i) {
    int bj = 0;
    for (int j = 1; j < dist.cols; ++j)
      if (dist.at<int>(i, j) < dist.at<int>(i, bj)) bj = j;
    int bi = 0;
    for (int k = 1; k < dist.rows; ++k)
      if (dist.at<int>(k, bj) < dist.at<int>(bi, bj)) bi = k;
    if (bi == i && dist.at<int>(i, bj) <= 40) expected.emplace_back(i, bj);
  }
  ASSERT_GT(expected.size(), 10u);
  struct Restore {  // the default again, also when an assertion leaves the loop
    ~Restore() { hrgbd::allowAvx512Matching(true); }
  } restore;
  for (const bool avx512 : {true, false}) {  // AVX-512 where the CPU has it, the portable loop
    hrgbd::allowAvx512Matching(avx512);
    const auto r = hrgbd::matchMutual(src, tgt, cv::NORM_HAMMING, 40);
    ASSERT_EQ(r.matches.size(), expected.size());
    for (std::size_t m = 0; m < expected.size(); ++m) {
      EXPECT_EQ(r.matches[m].source, expected[m].first);
      EXPECT_EQ(r.matches[m].target, expected[m].second);
      EXPECT_FLOAT_EQ(r.matches[m].distance, dist.at<int>(expected[m].first, expected[m].second));
    }
  }
}
