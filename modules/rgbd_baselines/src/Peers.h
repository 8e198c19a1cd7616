#pragma once
/** \file Peers.h
 * The dense peers (private to rgbd_baselines): each in its own file, so the peer libraries'
 * headers stay out of the rest of the project. */
#include <memory>
#include <string>

#include "rgbd_odometry/DepthAgreement.h"
#include "rgbd_odometry/OdometryParams.h"
#include "rgbd_odometry/Registration.h"

namespace hrgbd {

/** OpenCV contrib's opencv_rgbd, opencv_icp or opencv_rgbd_icp (OpenCvPeer.cpp). */
std::unique_ptr<Registration> makeOpenCvPeer(Method method);

/** Open3D's open3d_color or open3d_hybrid (Open3dPeer.cpp). */
std::unique_ptr<Registration> makeOpen3dPeer(Method method);

/** The peers' plausibility check (DepthAgreement.h), on every 4th pixel: a current point agrees
 * within kDepthAgreementTolerance of the reference depth. */
constexpr double kDepthAgreementTolerance = 0.05;  //!< [fraction of the reference depth]
/** Fewer agreeing among the compared: the peer's estimate is not plausible. Measured (4-pixel
 * grid, the peers' accepted estimates): 0.94 and more on fr3/teddy and fr1/desk, 0.46 on fr1/rpy,
 * 0.19 on the far-apart fr3/cabinet keyframes; frames of random noise 0.06. */
constexpr double kMinDepthAgreement = 0.15;
/** "" when the estimate passes the depth agreement check, else why not (for the detail). */
std::string checkDepthAgreement(const RgbdImage& cur, const RgbdImage& ref,
                                const Eigen::Isometry3d& T);

/** The value a peer keeps in `frame.peer`, made by `make(frame)` the first time. */
template <class T, class Make>
T peerData(Frame& frame, Make&& make) {
  if (!frame.peer.has_value()) frame.peer = T(make(frame));
  return std::any_cast<T>(frame.peer);
}

}  // namespace hrgbd
