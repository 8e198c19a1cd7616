#include "rgbd_odometry/DescriptorMatching.h"

#include <opencv2/features2d.hpp>

namespace hrgbd {

MatchResult matchMutual(const cv::Mat& source, const cv::Mat& target, int norm,
                        double max_distance) {
  MatchResult out;
  if (source.empty() || target.empty()) return out;
  cv::BFMatcher matcher(norm, false);
  std::vector<cv::DMatch> fwd, bwd;
  matcher.match(source, target, fwd);
  matcher.match(target, source, bwd);
  std::vector<int> back(target.rows, -1);
  for (const auto& m : bwd) back[m.queryIdx] = m.trainIdx;
  for (const auto& m : fwd) {
    if (back[m.trainIdx] != m.queryIdx) {
      ++out.rejected_by_mutual_check;
    } else if (m.distance > max_distance) {
      ++out.rejected_by_distance;
    } else {
      out.matches.push_back({m.queryIdx, m.trainIdx, m.distance});
    }
  }
  return out;
}

}  // namespace hrgbd
