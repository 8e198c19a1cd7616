#pragma once
/** \file DescriptorMatching.h
 * Nearest-neighbour matching with the mutual-consistency check (paper section III-F). */
#include <opencv2/core.hpp>
#include <vector>

namespace hrgbd {

/** One correspondence: row `source` of the source descriptors <-> row `target`. */
struct Match {
  int source = 0, target = 0;
  float distance = 0;
};

struct MatchResult {
  std::vector<Match> matches;
  std::size_t rejected_by_mutual_check = 0;
  std::size_t rejected_by_distance = 0;
};

/** Matches each source descriptor to its nearest target descriptor and keeps the pair only if
 * the target's nearest source descriptor is the same one (source->target and back) and their
 * distance is at most `max_distance`. `norm` is cv::NORM_HAMMING for ORB, cv::NORM_L2 for SHOT. */
MatchResult matchMutual(const cv::Mat& source, const cv::Mat& target, int norm,
                        double max_distance);

/** Whether binary descriptors (cv::NORM_HAMMING) may be matched with AVX-512's popcount where the
 * CPU has it (the default; the same matches, 4-5x faster) or only with the portable loop: the
 * tests compare both with OpenCV. */
void allowAvx512Matching(bool allowed);

}  // namespace hrgbd
