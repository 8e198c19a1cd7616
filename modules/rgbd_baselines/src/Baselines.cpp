#include "rgbd_baselines/Baselines.h"

#include "Peers.h"
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
      return makeOpenCvPeer(p.method);
    case Method::Open3dColor:
    case Method::Open3dHybrid:
      return makeOpen3dPeer(p.method);
    default:
      return makeRegistration(p);
  }
}

}  // namespace hrgbd
