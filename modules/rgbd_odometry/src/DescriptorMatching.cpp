#include "rgbd_odometry/DescriptorMatching.h"

#include <immintrin.h>

#include <atomic>
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

// The same with AVX-512's popcount of 64-bit lanes (VPOPCNTQ), where the CPU has it: 8 targets at
// a time, their words transposed (plane w of a block holds word w of its 8 targets), so that one
// XOR and one popcount per word give 8 distances, and each row's minimum and the columns' minima
// are kept in vectors. Ties resolve as above (first index): a lane keeps its first minimum, and
// the row's is the smallest index among the lanes that hold the minimum; the rows come in order.
__attribute__((target("avx512f,avx512vpopcntdq"))) void hammingNearestAvx512(
    const std::uint64_t* a, int na, const std::uint64_t* b, int nb, int words, Nearest& n) {
  const int blocks = (nb + 7) / 8;
  std::vector<std::uint64_t> planes(static_cast<std::size_t>(blocks) * words * 8, 0);
  for (int j = 0; j < nb; ++j)
    for (int w = 0; w < words; ++w)
      planes[(static_cast<std::size_t>(j / 8) * words + w) * 8 + j % 8] =
          b[static_cast<std::size_t>(j) * words + w];
  constexpr std::int64_t kNever = std::numeric_limits<std::int64_t>::max();
  std::vector<std::int64_t> col_min(static_cast<std::size_t>(blocks) * 8, kNever),
      col_arg(static_cast<std::size_t>(blocks) * 8, -1);
  const __m512i lane = _mm512_setr_epi64(0, 1, 2, 3, 4, 5, 6, 7);
  const __mmask8 last_valid = static_cast<__mmask8>(nb % 8 ? (1u << (nb % 8)) - 1 : 0xFF);
  for (int i = 0; i < na; ++i) {
    const std::uint64_t* ai = a + static_cast<std::size_t>(i) * words;
    __m512i best = _mm512_set1_epi64(kNever), best_j = _mm512_setzero_si512();
    const __m512i iv = _mm512_set1_epi64(i);
    for (int blk = 0; blk < blocks; ++blk) {
      const std::uint64_t* plane = planes.data() + static_cast<std::size_t>(blk) * words * 8;
      __m512i d = _mm512_setzero_si512();
      for (int w = 0; w < words; ++w)
        d = _mm512_add_epi64(d, _mm512_popcnt_epi64(_mm512_xor_si512(
                                    _mm512_set1_epi64(static_cast<long long>(ai[w])),
                                    _mm512_loadu_si512(plane + 8 * w))));
      if (blk == blocks - 1) d = _mm512_mask_blend_epi64(last_valid, _mm512_set1_epi64(kNever), d);
      const __mmask8 row = _mm512_cmplt_epi64_mask(d, best);
      best = _mm512_mask_mov_epi64(best, row, d);
      best_j =
          _mm512_mask_mov_epi64(best_j, row, _mm512_add_epi64(_mm512_set1_epi64(blk * 8), lane));
      std::int64_t* cm = col_min.data() + static_cast<std::size_t>(blk) * 8;
      const __mmask8 col = _mm512_cmplt_epi64_mask(d, _mm512_loadu_si512(cm));
      _mm512_mask_storeu_epi64(cm, col, d);
      _mm512_mask_storeu_epi64(col_arg.data() + static_cast<std::size_t>(blk) * 8, col, iv);
    }
    alignas(64) std::int64_t lane_best[8], lane_j[8];  // (GCC 12's reduce intrinsics warn)
    _mm512_store_si512(lane_best, best);
    _mm512_store_si512(lane_j, best_j);
    int l = 0;
    for (int k = 1; k < 8; ++k)
      if (lane_best[k] < lane_best[l] || (lane_best[k] == lane_best[l] && lane_j[k] < lane_j[l]))
        l = k;
    n.row[i] = static_cast<int>(lane_j[l]);
    n.row_distance[i] = static_cast<float>(lane_best[l]);
  }
  for (int j = 0; j < nb; ++j) n.col[j] = static_cast<int>(col_arg[j]);
}

std::atomic<bool> g_avx512_allowed{true};

bool useAvx512() {
  static const bool has =
      __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vpopcntdq");
  return has && g_avx512_allowed;
}

Nearest nearestHamming(const cv::Mat& source, const cv::Mat& target) {
  CV_Assert(source.type() == CV_8U && target.type() == CV_8U && source.cols == target.cols);
  const int words = (source.cols + 7) / 8;
  const auto a = packWords(source, words), b = packWords(target, words);
  Nearest n{std::vector<int>(source.rows), std::vector<int>(target.rows, -1),
            std::vector<float>(source.rows)};
  (useAvx512() ? hammingNearestAvx512 : hammingNearest)(a.data(), source.rows, b.data(),
                                                        target.rows, words, n);
  return n;
}

}  // namespace

void allowAvx512Matching(bool allowed) { g_avx512_allowed = allowed; }

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
