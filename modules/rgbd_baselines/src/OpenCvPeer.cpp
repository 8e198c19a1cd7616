// OpenCV contrib's dense frame-to-frame odometries (cv::rgbd) with OpenCV's default options, fed
// as opencv_contrib's samples/odometry_evaluation.cpp feeds them.
#include <Eigen/Core>
#include <limits>
#include <opencv2/core/eigen.hpp>  // after Eigen
#include <opencv2/rgbd.hpp>

#include "Peers.h"

namespace hrgbd {
namespace {

// Unknown depth must be NaN for cv::rgbd: its depth pyramid is built by pyrDown, which blends a
// 0 into the valid depths around it (wrong depths that pass the depth-range mask at the coarse
// levels), while a NaN stays unknown. Measured on fr3/teddy (200 frames, opencv_rgbd): aligned
// ATE 0.058 m with zeros, 0.022 m with NaN.
cv::Mat depthWithNaN(const cv::Mat& depth) {
  cv::Mat d = depth.clone();
  d.setTo(std::numeric_limits<float>::quiet_NaN(), depth == 0);
  return d;
}

class OpenCvPeer : public Registration {
 public:
  explicit OpenCvPeer(Method method) : m_method(method) {}

  // The pyramids (and normals, for ICP) of each frame are made once, as the sample does with
  // its OdometryFrame objects.
  FrameFeatures prepare(Frame& frame) override {
    FrameFeatures seen{{FramePath::Sparse::Peer}, 0, 0, {}};
    timed(seen.ms.features, [&] { odometryFrame(frame); });
    return seen;
  }

  RegistrationResult align(Frame& cur, Frame& ref) override {
    RegistrationResult r;
    r.seen = {{FramePath::Sparse::Peer}, 0, 0, {}};
    auto src = timed(r.seen.ms.features, [&] { return odometryFrame(cur); });
    auto dst = timed(r.seen.ms.features, [&] { return odometryFrame(ref); });
    cv::Mat Rt;  // maps source (current) points into the destination (reference) frame
    const bool ok = timed(r.seen.ms.estimation, [&] { return m_odometry->compute(src, dst, Rt); });
    if (!ok || Rt.empty()) {
      r.status = FrameResult::Status::TooFewMatches;
      r.detail = toString(m_method) + " did not converge";
      return r;
    }
    cv::cv2eigen(Rt, r.T.matrix());
    // OpenCV reports success on frames of pure noise: its estimate must also make the depths
    // agree.
    if (r.detail = checkDepthAgreement(cur.image, ref.image, r.T); !r.detail.empty()) {
      r.status = FrameResult::Status::LargeResiduals;
      r.detail = toString(m_method) + ": " + r.detail;
      return r;
    }
    r.status = FrameResult::Status::Ok;
    return r;
  }

 private:
  cv::Ptr<cv::rgbd::OdometryFrame> odometryFrame(Frame& frame) {
    if (!m_odometry) m_odometry = make(frame.image.cam);  // needs the intrinsics
    return peerData<cv::Ptr<cv::rgbd::OdometryFrame>>(frame, [&](const Frame& f) {
      auto of = cv::rgbd::OdometryFrame::create(f.image.grey, depthWithNaN(f.image.depth));
      m_odometry->prepareFrameCache(of, cv::rgbd::OdometryFrame::CACHE_ALL);
      return of;
    });
  }

  cv::Ptr<cv::rgbd::Odometry> make(const PinholeCamera& c) const {
    const cv::Mat K = (cv::Mat_<float>(3, 3) << c.fx, 0, c.cx, 0, c.fy, c.cy, 0, 0, 1);
    if (m_method == Method::OpencvRgbd) return cv::rgbd::RgbdOdometry::create(K);
    if (m_method == Method::OpencvIcp) return cv::rgbd::ICPOdometry::create(K);
    return cv::rgbd::RgbdICPOdometry::create(K);
  }

  Method m_method;
  cv::Ptr<cv::rgbd::Odometry> m_odometry;
};

}  // namespace

std::unique_ptr<Registration> makeOpenCvPeer(Method method) {
  return std::make_unique<OpenCvPeer>(method);
}

}  // namespace hrgbd
