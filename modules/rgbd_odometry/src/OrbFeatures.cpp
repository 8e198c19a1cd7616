#include "rgbd_odometry/OrbFeatures.h"

#include <algorithm>
#include <cmath>
#include <opencv2/features2d.hpp>

#include "rgbd_core/Config.h"

namespace hrgbd {

void OrbParams::checkTogether(const std::string& s) const {
  requireValid(max_depth > min_depth, s, "max_depth", max_depth, "must be > min_depth");
}

FeatureSet extractOrbFeatures(const RgbdImage& image, const OrbParams& p) {
  // ORB keeps no keypoint within its 31-pixel edge threshold of the border, so a smaller image
  // has none; OpenCV's ORB pyramid throws an assertion on a 1-pixel image instead of saying so.
  constexpr int kEdge = 31;
  if (std::min(image.grey.cols, image.grey.rows) <= 2 * kEdge) {
    FeatureSet none;
    none.descriptors.create(0, 32, CV_8UC1);
    return none;
  }
  auto orb = cv::ORB::create(p.n_features, static_cast<float>(p.scale_factor), p.n_levels, kEdge, 0,
                             2, cv::ORB::HARRIS_SCORE, kEdge, p.fast_threshold);
  std::vector<cv::KeyPoint> kps;
  cv::Mat desc;
  orb->detectAndCompute(image.grey, cv::noArray(), kps, desc);
  FeatureSet out;
  out.detected = kps.size();
  out.descriptors.create(0, desc.cols, desc.type());
  for (std::size_t i = 0; i < kps.size(); ++i) {
    const int u = static_cast<int>(std::lround(kps[i].pt.x));
    const int v = static_cast<int>(std::lround(kps[i].pt.y));
    const float z = (u >= 0 && v >= 0 && u < image.depth.cols && v < image.depth.rows)
                        ? image.depth.at<float>(v, u)
                        : 0.f;
    if (!(z >= p.min_depth && z <= p.max_depth)) {
      ++out.dropped_no_depth;
      continue;
    }
    out.keypoints.push_back(kps[i]);
    out.descriptors.push_back(desc.row(static_cast<int>(i)));
    out.points.push_back(image.cam.backProject(kps[i].pt.x, kps[i].pt.y, z));  // eqs. (1)-(2)
  }
  return out;
}

}  // namespace hrgbd
