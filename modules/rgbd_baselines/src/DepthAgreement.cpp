#include <cmath>

#include "Peers.h"

namespace hrgbd {

DepthAgreement depthAgreement(const RgbdImage& cur, const RgbdImage& ref,
                              const Eigen::Isometry3d& T, int stride) {
  // Hand-written: neither OpenCV's cv::rgbd odometries nor Open3D's report how well the depths
  // agree after the motion they return. A point of the current frame is warped into the
  // reference (optical frames, pinhole) and compared with the depth found there.
  DepthAgreement a;
  const auto& c = cur.cam;
  const auto& r = ref.cam;
  const Eigen::Matrix3f R = T.linear().cast<float>();
  const Eigen::Vector3f t = T.translation().cast<float>();
  for (int v = 0; v < cur.depth.rows; v += stride) {
    const float* row = cur.depth.ptr<float>(v);
    for (int u = 0; u < cur.depth.cols; u += stride) {
      const float z = row[u];
      if (!(z > 0)) continue;
      const Eigen::Vector3f p(float((u - c.cx) * z / c.fx), float((v - c.cy) * z / c.fy), z);
      const Eigen::Vector3f q = R * p + t;
      if (!(q.z() > 0)) continue;
      const long ur = std::lround(r.fx * q.x() / q.z() + r.cx);
      const long vr = std::lround(r.fy * q.y() / q.z() + r.cy);
      if (ur < 0 || vr < 0 || ur >= ref.depth.cols || vr >= ref.depth.rows) continue;
      const float zr = ref.depth.at<float>(int(vr), int(ur));
      if (!(zr > 0)) continue;
      ++a.compared;
      if (std::abs(q.z() - zr) <= kDepthAgreementTolerance * zr) ++a.agreeing;
    }
  }
  return a;
}

std::string checkDepthAgreement(const RgbdImage& cur, const RgbdImage& ref,
                                const Eigen::Isometry3d& T) {
  const auto a = depthAgreement(cur, ref, T);
  if (a.compared > 0 && a.agreeing >= kMinDepthAgreement * a.compared) return "";
  return "the depths do not agree after the estimated motion: " + std::to_string(a.agreeing) +
         " of " + std::to_string(a.compared) + " sampled points within " +
         std::to_string(int(100 * kDepthAgreementTolerance)) +
         " % of the reference depth (at least " + std::to_string(int(100 * kMinDepthAgreement)) +
         " % needed)";
}

}  // namespace hrgbd
