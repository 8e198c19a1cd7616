#pragma once
/** \file Peers.h
 * The dense peers (private to rgbd_baselines): each in its own file, so the peer libraries'
 * headers stay out of the rest of the project. */
#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "rgbd_odometry/OdometryParams.h"
#include "rgbd_odometry/Registration.h"

namespace hrgbd {

/** OpenCV contrib's opencv_rgbd, opencv_icp or opencv_rgbd_icp (OpenCvPeer.cpp). */
std::unique_ptr<Registration> makeOpenCvPeer(Method method);

/** Open3D's open3d_color or open3d_hybrid (Open3dPeer.cpp). */
std::unique_ptr<Registration> makeOpen3dPeer(Method method);

/** What a peer made of a prepared frame (its own image types, pyramids), made once per frame:
 * a frame is the current one now and the reference next time. Frames are told apart by their
 * grey image's buffer, which the cache holds on to, so no other frame can be given that buffer
 * while the entry lives; a prepared frame's images are not changed afterwards. */
template <class T>
class PeerFrameCache {
 public:
  /** The entry of `frame`, made by `make(frame)` if there is none. */
  template <class Make>
  T get(const Frame& frame, Make&& make) {
    for (const auto& e : m_entries)
      if (e.grey.data == frame.image.grey.data) return e.value;
    m_entries.push_back({frame.image.grey, make(frame)});
    return m_entries.back().value;
  }
  /** Drops every entry but those of `a` and `b` (the frames an alignment used). */
  void keepOnly(const Frame& a, const Frame& b) {
    std::vector<Entry> kept;
    for (auto& e : m_entries)
      if (e.grey.data == a.image.grey.data || e.grey.data == b.image.grey.data)
        kept.push_back(std::move(e));
    m_entries = std::move(kept);
  }

 private:
  struct Entry {
    cv::Mat grey;
    T value;
  };
  std::vector<Entry> m_entries;
};

}  // namespace hrgbd
