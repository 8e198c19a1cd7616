#include "rgbd_odometry/DepthAgreement.h"

#include <algorithm>
#include <cmath>

namespace hrgbd {

DepthAgreement depthAgreement(const RgbdImage& cur, const RgbdImage& ref,
                              const Eigen::Isometry3d& T, const DepthTolerance& tolerance,
                              int stride) {
  DepthAgreement a;
  stride = std::max(stride, 1);
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
      const double ur = std::round(r.fx * q.x() / q.z() + r.cx);
      const double vr = std::round(r.fy * q.y() / q.z() + r.cy);
      if (!(ur >= 0 && vr >= 0 && ur < ref.depth.cols && vr < ref.depth.rows)) continue;
      const float zr = ref.depth.at<float>(static_cast<int>(vr), static_cast<int>(ur));
      if (!(zr > 0)) continue;
      ++a.compared;
      const double within = (tolerance.relative + tolerance.quadratic * zr) * zr;
      if (std::abs(q.z() - zr) <= within) ++a.agreeing;
    }
  }
  return a;
}

}  // namespace hrgbd
