#pragma once
/** \file ThreadLimit.h
 * The thread count of the libraries the methods run on, for timings on a stated number of
 * cores. */

namespace hrgbd {

/** While it lives, OpenCV (every method) and the OpenMP runtime (Open3D's peers) use at most
 * `threads` threads; the counts they had come back when it goes. */
class ThreadLimit {
 public:
  explicit ThreadLimit(int threads);
  ~ThreadLimit();
  ThreadLimit(const ThreadLimit&) = delete;
  ThreadLimit& operator=(const ThreadLimit&) = delete;

 private:
  int m_opencv, m_openmp;
};

}  // namespace hrgbd
