// Open3D's dense RGB-D odometry (Steinbrucker et al. 2011's photometric term, or Park et al.
// 2017's photometric + geometric hybrid) with Open3D's default OdometryOption.
#include <open3d/geometry/Image.h>
#include <open3d/geometry/RGBDImage.h>
#include <open3d/pipelines/odometry/Odometry.h>
#include <open3d/utility/Logging.h>

#include <cstring>

#include "Peers.h"

namespace hrgbd {
namespace {

namespace o3d = open3d;
namespace odo = open3d::pipelines::odometry;

// An 8-bit or float single-channel cv::Mat as an Open3D image (copied).
o3d::geometry::Image toOpen3d(const cv::Mat& m, int bytes_per_channel) {
  o3d::geometry::Image img;
  img.Prepare(m.cols, m.rows, 1, bytes_per_channel);
  for (int r = 0; r < m.rows; ++r)
    std::memcpy(img.data_.data() + std::size_t(r) * m.cols * bytes_per_channel, m.ptr(r),
                std::size_t(m.cols) * bytes_per_channel);
  return img;
}

class Open3dPeer : public Registration {
 public:
  explicit Open3dPeer(Method method) : m_method(method) {
    // Open3D prints a warning for every frame it cannot register; the status says it instead.
    o3d::utility::SetVerbosityLevel(o3d::utility::VerbosityLevel::Error);
  }

  FrameFeatures prepare(Frame& frame) override {
    FrameFeatures seen{{FramePath::Sparse::Peer}, 0, 0, {}};
    timed(seen.ms.features, [&] { rgbdImage(frame); });
    return seen;
  }

  RegistrationResult align(Frame& cur, Frame& ref) override {
    RegistrationResult r;
    r.seen = {{FramePath::Sparse::Peer}, 0, 0, {}};
    auto source = timed(r.seen.ms.features, [&] { return rgbdImage(cur); });
    auto target = timed(r.seen.ms.features, [&] { return rgbdImage(ref); });
    const auto& c = cur.image.cam;
    const o3d::camera::PinholeCameraIntrinsic K(cur.image.grey.cols, cur.image.grey.rows, c.fx,
                                                c.fy, c.cx, c.cy);
    // The transform maps the source's (current frame's) points into the target (reference).
    const auto [ok, T, information] = timed(r.seen.ms.estimation, [&] {
      const Eigen::Matrix4d init = Eigen::Matrix4d::Identity();
      if (m_method == Method::Open3dColor)
        return odo::ComputeRGBDOdometry(*source, *target, K, init,
                                        odo::RGBDOdometryJacobianFromColorTerm(), m_option);
      return odo::ComputeRGBDOdometry(*source, *target, K, init,
                                      odo::RGBDOdometryJacobianFromHybridTerm(), m_option);
    });
    (void)information;
    if (!ok || !T.allFinite()) {
      r.status = FrameResult::Status::TooFewMatches;
      r.detail = toString(m_method) + " did not converge";
      return r;
    }
    r.T.matrix() = T;
    // Open3D reports success on frames of pure noise: its estimate must also make the depths
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
  using Image = std::shared_ptr<o3d::geometry::RGBDImage>;

  // Open3D's RGBDImage of a frame, as CreateFromTUMFormat makes it: intensity in [0, 1] (from the
  // prepared grey, which has Open3D's RGB weights, rounded to 8 bits), depth in metres cut at
  // 4 m (OdometryOption's depth_max, which the odometry applies anyway), 0 = unknown.
  Image rgbdImage(Frame& frame) {
    return peerData<Image>(frame, [&](const Frame& f) {
      return o3d::geometry::RGBDImage::CreateFromColorAndDepth(
          toOpen3d(f.image.grey, 1), toOpen3d(f.image.depth, 4), 1.0 /* already metres */,
          m_option.depth_max_, true);
    });
  }

  Method m_method;
  odo::OdometryOption m_option;
};

}  // namespace

std::unique_ptr<Registration> makeOpen3dPeer(Method method) {
  return std::make_unique<Open3dPeer>(method);
}

}  // namespace hrgbd
