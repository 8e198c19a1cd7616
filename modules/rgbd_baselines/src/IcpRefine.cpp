#include "rgbd_baselines/IcpRefine.h"

#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/poses/CPose3DPDF.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>
#include <mrpt/slam/CICP.h>

#include <cmath>

#include "rgbd_core/Config.h"

namespace hrgbd {
namespace {

mrpt::maps::CSimplePointsMap cloudOf(const RgbdImage& f, int target_points, double max_depth) {
  const int valid = cv::countNonZero(f.depth > 0);
  const int stride = std::max(1, static_cast<int>(std::sqrt(valid / std::max(1, target_points))));
  mrpt::maps::CSimplePointsMap m;
  m.reserve(valid / (stride * stride) + 1);
  for (int v = 0; v < f.depth.rows; v += stride)
    for (int u = 0; u < f.depth.cols; u += stride) {
      const float z = f.depth.at<float>(v, u);
      if (!(z > 0 && z <= max_depth)) continue;
      const auto p = f.cam.backProject(u, v, z);
      m.insertPointFast(p.x(), p.y(), p.z());
    }
  return m;
}

}  // namespace

IcpResult refineIcp(const RgbdImage& source, const RgbdImage& target,
                    const Eigen::Isometry3d& initial, const IcpParams& p) {
  const auto ms = cloudOf(source, p.target_points, p.max_depth);
  const auto mt = cloudOf(target, p.target_points, p.max_depth);
  mrpt::slam::CICP icp;
  icp.options.maxIterations = p.max_iterations;
  icp.options.thresholdDist = p.max_distance;
  icp.options.thresholdAng = 0;
  icp.options.smallestThresholdDist = 0.2 * p.max_distance;
  mrpt::slam::CICP::TReturnInfo info;
  mrpt::poses::CPose3DPDFGaussian init;
  init.mean = toPose(initial);
  // Align3DPDF(m1, m2, x) finds the pose of m2 in m1's frame: m1 = target, m2 = source.
  const auto pdf = icp.Align3DPDF(&mt, &ms, init, info);
  IcpResult r;
  r.iterations = info.nIterations;
  r.goodness = info.goodness;
  const auto H = pdf->getMeanVal().getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>();
  r.T.matrix() = H.asEigen();
  return r;
}

}  // namespace hrgbd
