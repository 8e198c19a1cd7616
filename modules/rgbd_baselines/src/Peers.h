#pragma once
/** \file Peers.h
 * The dense peers (private to rgbd_baselines): each in its own file, so the peer libraries'
 * headers stay out of the rest of the project. */
#include <memory>

#include "rgbd_odometry/OdometryParams.h"
#include "rgbd_odometry/Registration.h"

namespace hrgbd {

/** OpenCV contrib's opencv_rgbd, opencv_icp or opencv_rgbd_icp (OpenCvPeer.cpp). */
std::unique_ptr<Registration> makeOpenCvPeer(Method method);

/** Open3D's open3d_color or open3d_hybrid (Open3dPeer.cpp). */
std::unique_ptr<Registration> makeOpen3dPeer(Method method);

/** The value a peer keeps in `frame.peer`, made by `make(frame)` the first time. */
template <class T, class Make>
T peerData(Frame& frame, Make&& make) {
  if (!frame.peer.has_value()) frame.peer = T(make(frame));
  return std::any_cast<T>(frame.peer);
}

}  // namespace hrgbd
