#include "rgbd_core/RgbdFrame.h"

#include <mrpt/system/datetime.h>

#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "rgbd_core/Timestamp.h"

namespace hrgbd {

mrpt::obs::CObservation3DRangeScan::Ptr makeRgbdObservation(const cv::Mat& bgr,
                                                            const cv::Mat& depth_raw,
                                                            double depth_unit,
                                                            const mrpt::img::TCamera& cam, double t,
                                                            const std::string& label) {
  return makeRgbdObservation(bgr, depth_raw, depth_unit, cam, frameTimeFromSeconds(t), label);
}

mrpt::obs::CObservation3DRangeScan::Ptr makeRgbdObservation(
    const cv::Mat& bgr, const cv::Mat& depth_raw, double depth_unit, const mrpt::img::TCamera& cam,
    mrpt::Clock::time_point t, const std::string& label) {
  if (depth_raw.type() != CV_16UC1) throw std::invalid_argument("depth image must be 16-bit");
  if (!bgr.empty() && bgr.type() != CV_8UC3)
    throw std::invalid_argument("colour image must be 8-bit, 3 channels");
  if (!bgr.empty() && bgr.size() != depth_raw.size())
    throw std::invalid_argument("colour and depth images differ in size");
  if (depth_raw.cols != static_cast<int>(cam.ncols) ||
      depth_raw.rows != static_cast<int>(cam.nrows))
    throw std::invalid_argument("image size differs from the intrinsics' size");
  if (!(depth_unit > 0)) throw std::invalid_argument("depth unit must be > 0");

  auto obs = mrpt::obs::CObservation3DRangeScan::Create();
  obs->sensorLabel = label;
  obs->timestamp = t;
  obs->range_is_depth = true;
  obs->hasRangeImage = true;
  obs->rangeUnits = static_cast<float>(depth_unit);
  obs->rangeImage.resize(depth_raw.rows, depth_raw.cols);
  for (int r = 0; r < depth_raw.rows; ++r) {
    const auto* row = depth_raw.ptr<uint16_t>(r);
    for (int c = 0; c < depth_raw.cols; ++c) obs->rangeImage(r, c) = row[c];
  }
  obs->maxRange = 65535.0f * static_cast<float>(depth_unit);
  obs->cameraParams = cam;
  obs->cameraParamsIntensity = cam;
  // Identity between the cameras (depth registered to colour): MRPT's convention for "coincide".
  obs->relativePoseIntensityWRTDepth =
      mrpt::poses::CPose3D(0, 0, 0, mrpt::DEG2RAD(-90.0), 0, mrpt::DEG2RAD(-90.0));
  if (!bgr.empty()) {
    obs->hasIntensityImage = true;
    obs->intensityImage = mrpt::img::CImage(bgr.clone(), mrpt::img::DEEP_COPY);
  }
  return obs;
}

cv::Mat depthMetres(const mrpt::obs::CObservation3DRangeScan& obs) {
  if (!obs.hasRangeImage) return {};
  if (!obs.range_is_depth)
    throw std::invalid_argument("observation stores ranges, not depths (range_is_depth=false)");
  const auto& R = obs.rangeImage;
  cv::Mat d(static_cast<int>(R.rows()), static_cast<int>(R.cols()), CV_32FC1);
  const float u = obs.rangeUnits;
  for (int r = 0; r < d.rows; ++r) {
    auto* row = d.ptr<float>(r);
    for (int c = 0; c < d.cols; ++c) row[c] = R(r, c) * u;
  }
  return d;
}

cv::Mat colourBgr(const mrpt::obs::CObservation3DRangeScan& obs) {
  if (!obs.hasIntensityImage) return {};
  cv::Mat m = obs.intensityImage.asCvMatRef();
  if (m.empty()) return {};
  if (m.type() == CV_8UC3) return m;
  cv::Mat out;
  if (m.type() == CV_8UC1) cv::cvtColor(m, out, cv::COLOR_GRAY2BGR);
  return out;
}

double timestampSeconds(const mrpt::obs::CObservation& obs) { return frameSeconds(obs.timestamp); }

}  // namespace hrgbd
