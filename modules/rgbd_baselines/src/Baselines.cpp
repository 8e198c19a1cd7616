#include "rgbd_baselines/Baselines.h"

#include <opencv2/core/eigen.hpp>
#include <opencv2/rgbd.hpp>

#include "rgbd_odometry/FeatureRegistration.h"

namespace hrgbd {
namespace {

// ORB + RANSAC refined by MRPT's ICP on ~15,000 points (paper section IV-C).
class IcpRefined : public Registration {
 public:
  IcpRefined(std::unique_ptr<Registration> inner, const IcpParams& icp)
      : m_inner(std::move(inner)), m_icp(icp) {}
  FrameFeatures prepare(Frame& frame) override { return m_inner->prepare(frame); }
  RegistrationResult align(Frame& cur, Frame& ref) override {
    auto r = m_inner->align(cur, ref);
    if (r.ok())
      r.T = timed(r.seen.ms.refine, [&] { return refineIcp(cur.image, ref.image, r.T, m_icp).T; });
    return r;
  }

 private:
  std::unique_ptr<Registration> m_inner;
  IcpParams m_icp;
};

// OpenCV contrib's dense frame-to-frame odometries on the prepared grey and depth images.
class OpenCvPeer : public Registration {
 public:
  explicit OpenCvPeer(Method method) : m_method(method) {}
  FrameFeatures prepare(Frame&) override { return {"dense", 0, 0, {}}; }
  RegistrationResult align(Frame& cur, Frame& ref) override {
    if (!m_odometry) m_odometry = make(cur.image.cam);  // needs the intrinsics
    RegistrationResult r;
    r.seen = prepare(cur);
    cv::Mat Rt;  // maps source (current) points into the destination (reference) frame
    const bool ok = timed(r.seen.ms.estimation, [&] {
      return m_odometry->compute(cur.image.grey, cur.image.depth, cv::Mat(), ref.image.grey,
                                 ref.image.depth, cv::Mat(), Rt);
    });
    if (!ok || Rt.empty()) {
      r.status = FrameResult::Status::TooFewMatches;
      r.detail = toString(m_method) + " did not converge";
      return r;
    }
    cv::cv2eigen(Rt, r.T.matrix());
    r.status = FrameResult::Status::Ok;
    return r;
  }

 private:
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

std::unique_ptr<Registration> makeAnyRegistration(const OdometryParams& p,
                                                  const BaselineParams& b) {
  auto ransac = [&] {
    const RansacParams params = b.ransac;
    return std::make_unique<PhotometricRegistration>(
        p.orb, p.max_hamming_distance,
        [params](const Correspondences& c) { return estimateRansac(c, params); });
  };
  switch (p.method) {
    case Method::Ransac:
      return ransac();
    case Method::RansacIcp:
      return std::make_unique<IcpRefined>(ransac(), b.icp);
    case Method::OpencvRgbd:
    case Method::OpencvIcp:
    case Method::OpencvRgbdIcp:
      return std::make_unique<OpenCvPeer>(p.method);
    default:
      return makeRegistration(p);
  }
}

}  // namespace hrgbd
