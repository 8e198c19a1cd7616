#include "rgbd_odometry/OrbFeatures.h"

#include <cmath>
#include <opencv2/features2d.hpp>

#include "rgbd_core/Config.h"

namespace hrgbd {

void OrbParams::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) {
  rejectUnknownKeys(
      c, s, {"n_features", "scale_factor", "n_levels", "fast_threshold", "min_depth", "max_depth"});
  MRPT_LOAD_CONFIG_VAR_CS(n_features, int);
  MRPT_LOAD_CONFIG_VAR_CS(scale_factor, double);
  MRPT_LOAD_CONFIG_VAR_CS(n_levels, int);
  MRPT_LOAD_CONFIG_VAR_CS(fast_threshold, int);
  MRPT_LOAD_CONFIG_VAR_CS(min_depth, double);
  MRPT_LOAD_CONFIG_VAR_CS(max_depth, double);
  requireValid(n_features >= 10, s, "n_features", n_features, "must be >= 10");
  requireValid(scale_factor > 1.0 && scale_factor <= 2.0, s, "scale_factor", scale_factor,
               "must be in (1, 2]");
  requireValid(n_levels >= 1 && n_levels <= 16, s, "n_levels", n_levels, "must be in [1, 16]");
  requireValid(fast_threshold >= 1 && fast_threshold <= 255, s, "fast_threshold", fast_threshold,
               "must be in [1, 255]");
  requireValid(min_depth >= 0, s, "min_depth", min_depth, "must be >= 0 m");
  requireValid(max_depth > min_depth, s, "max_depth", max_depth, "must be > min_depth");
}

void OrbParams::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const {
  MRPT_SAVE_CONFIG_VAR_COMMENT(n_features, "[count] most ORB keypoints per frame");
  MRPT_SAVE_CONFIG_VAR_COMMENT(scale_factor, "pyramid decimation ratio, (1, 2]");
  MRPT_SAVE_CONFIG_VAR_COMMENT(n_levels, "pyramid levels");
  MRPT_SAVE_CONFIG_VAR_COMMENT(fast_threshold, "[grey levels] FAST threshold");
  MRPT_SAVE_CONFIG_VAR_COMMENT(min_depth, "[m] keypoints nearer are dropped");
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_depth, "[m] keypoints farther are dropped");
}

FeatureSet extractOrbFeatures(const RgbdImage& image, const OrbParams& p) {
  auto orb = cv::ORB::create(p.n_features, static_cast<float>(p.scale_factor), p.n_levels, 31, 0, 2,
                             cv::ORB::HARRIS_SCORE, 31, p.fast_threshold);
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
