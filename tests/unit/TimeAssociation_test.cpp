#include "rgbd_core/TimeAssociation.h"

#include "TestData.h"

TEST(TimeAssociation, GreedyByDifferenceEachUsedOnce) {
  // b[0] is 0.004 from a[0] and 0.006 from a[1]: a[0] gets it; a[1] takes b[1] (0.009 away).
  const std::vector<double> a{10.000, 10.010}, b{10.004, 10.019};
  const auto p = hrgbd::associateByTime(a, b, 0.01);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0].first, 0u);
  EXPECT_EQ(p[0].second, 0u);
  EXPECT_EQ(p[1].first, 1u);
  EXPECT_EQ(p[1].second, 1u);
}

TEST(TimeAssociation, UnsortedInputAndNoMatches) {
  const std::vector<double> a{3.0, 1.0, 2.0}, b{2.001, 0.999, 7.0};
  const auto p = hrgbd::associateByTime(a, b, 0.02);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0].first, 1u);  // sorted by a's time: 1.0 first
  EXPECT_EQ(p[0].second, 1u);
  EXPECT_EQ(p[1].first, 2u);
  EXPECT_TRUE(hrgbd::associateByTime(a, {100.0}, 0.02).empty());
}
