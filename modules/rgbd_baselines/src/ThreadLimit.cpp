#include "rgbd_baselines/ThreadLimit.h"

#include <omp.h>

#include <opencv2/core/utility.hpp>

namespace hrgbd {

ThreadLimit::ThreadLimit(int threads)
    : m_opencv(cv::getNumThreads()), m_openmp(omp_get_max_threads()) {
  cv::setNumThreads(threads);
  omp_set_num_threads(threads);
}

ThreadLimit::~ThreadLimit() {
  cv::setNumThreads(m_opencv);
  omp_set_num_threads(m_openmp);
}

}  // namespace hrgbd
