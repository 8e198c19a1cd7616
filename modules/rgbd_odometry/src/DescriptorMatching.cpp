#include "rgbd_odometry/DescriptorMatching.h"

#include <limits>
#include <opencv2/core.hpp>

namespace hrgbd {

MatchResult matchMutual(const cv::Mat& source, const cv::Mat& target, int norm,
                        double max_distance) {
  MatchResult out;
  if (source.empty() || target.empty()) return out;
  // One distance matrix (OpenCV), then both nearest neighbours from it: source->target is the
  // row minimum, target->source the column minimum.
  cv::Mat dist;
  const bool hamming = norm == cv::NORM_HAMMING || norm == cv::NORM_HAMMING2;
  cv::batchDistance(source, target, dist, hamming ? CV_32S : CV_32F, cv::noArray(), norm, 0);
  if (hamming) dist.convertTo(dist, CV_32F);
  std::vector<int> best_row(dist.rows), best_col(dist.cols, -1);
  std::vector<float> col_min(dist.cols, std::numeric_limits<float>::max());
  for (int i = 0; i < dist.rows; ++i) {
    const float* d = dist.ptr<float>(i);
    int bi = 0;
    for (int j = 0; j < dist.cols; ++j) {
      if (d[j] < d[bi]) bi = j;
      if (d[j] < col_min[j]) col_min[j] = d[j], best_col[j] = i;
    }
    best_row[i] = bi;
  }
  for (int i = 0; i < dist.rows; ++i) {
    const int j = best_row[i];
    const float d = dist.at<float>(i, j);
    if (best_col[j] != i) {
      ++out.rejected_by_mutual_check;
    } else if (d > max_distance) {
      ++out.rejected_by_distance;
    } else {
      out.matches.push_back({i, j, d});
    }
  }
  return out;
}

}  // namespace hrgbd
