#include "rgbd_odometry/DescriptorMatching.h"

#include <cstdint>
#include <cstring>
#include <limits>
#include <opencv2/core.hpp>

namespace hrgbd {
namespace {

// Both nearest neighbours of a distance matrix: source->target is the row minimum,
// target->source the column minimum (first index on ties).
struct Nearest {
  std::vector<int> row, col;
  std::vector<float> row_distance;
};

// Float descriptors (SHOT): one OpenCV distance matrix.
Nearest nearestFloat(const cv::Mat& source, const cv::Mat& target, int norm) {
  cv::Mat dist;
  cv::batchDistance(source, target, dist, CV_32F, cv::noArray(), norm, 0);
  Nearest n{std::vector<int>(dist.rows), std::vector<int>(dist.cols, -1),
            std::vector<float>(dist.rows)};
  std::vector<float> col_min(dist.cols, std::numeric_limits<float>::max());
  for (int i = 0; i < dist.rows; ++i) {
    const float* d = dist.ptr<float>(i);
    int bi = 0;
    for (int j = 0; j < dist.cols; ++j) {
      if (d[j] < d[bi]) bi = j;
      if (d[j] < col_min[j]) col_min[j] = d[j], n.col[j] = i;
    }
    n.row[i] = bi, n.row_distance[i] = d[bi];
  }
  return n;
}

std::vector<std::uint64_t> packWords(const cv::Mat& m, int words) {
  std::vector<std::uint64_t> out(static_cast<std::size_t>(m.rows) * words, 0);
  for (int i = 0; i < m.rows; ++i) std::memcpy(&out[i * words], m.ptr(i), m.cols);
  return out;
}

// Binary descriptors (ORB), written by hand: cv::batchDistance calls its norm once per pair,
// and that call overhead made matching 1000 x 1000 ORB descriptors cost 10 ms on one core.
// The popcount clone is chosen at load time on CPUs that have the instruction.
__attribute__((target_clones("popcnt", "default"))) void hammingNearest(
    const std::uint64_t* a, int na, const std::uint64_t* b, int nb, int words, Nearest& n) {
  std::vector<int> col_min(nb, std::numeric_limits<int>::max());
  for (int i = 0; i < na; ++i) {
    const std::uint64_t* ai = a + static_cast<std::size_t>(i) * words;
    int best = std::numeric_limits<int>::max(), bi = 0;
    for (int j = 0; j < nb; ++j) {
      const std::uint64_t* bj = b + static_cast<std::size_t>(j) * words;
      int d = 0;
      for (int w = 0; w < words; ++w) d += __builtin_popcountll(ai[w] ^ bj[w]);
      if (d < best) best = d, bi = j;
      if (d < col_min[j]) col_min[j] = d, n.col[j] = i;
    }
    n.row[i] = bi, n.row_distance[i] = static_cast<float>(best);
  }
}

Nearest nearestHamming(const cv::Mat& source, const cv::Mat& target) {
  CV_Assert(source.type() == CV_8U && target.type() == CV_8U && source.cols == target.cols);
  const int words = (source.cols + 7) / 8;
  const auto a = packWords(source, words), b = packWords(target, words);
  Nearest n{std::vector<int>(source.rows), std::vector<int>(target.rows, -1),
            std::vector<float>(source.rows)};
  hammingNearest(a.data(), source.rows, b.data(), target.rows, words, n);
  return n;
}

}  // namespace

MatchResult matchMutual(const cv::Mat& source, const cv::Mat& target, int norm,
                        double max_distance) {
  MatchResult out;
  if (source.empty() || target.empty()) return out;
  const bool hamming = norm == cv::NORM_HAMMING;
  const auto n = hamming ? nearestHamming(source, target) : nearestFloat(source, target, norm);
  for (int i = 0; i < source.rows; ++i) {
    const int j = n.row[i];
    if (n.col[j] != i) {
      ++out.rejected_by_mutual_check;
    } else if (n.row_distance[i] > max_distance) {
      ++out.rejected_by_distance;
    } else {
      out.matches.push_back({i, j, n.row_distance[i]});
    }
  }
  return out;
}

}  // namespace hrgbd
