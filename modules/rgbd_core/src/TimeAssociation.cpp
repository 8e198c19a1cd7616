#include "rgbd_core/TimeAssociation.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

namespace hrgbd {

std::vector<std::pair<std::size_t, std::size_t>> associateByTime(const std::vector<double>& a,
                                                                 const std::vector<double>& b,
                                                                 double max_dt) {
  // Sort b's indices by time, then sweep a window of +-max_dt around each a[i].
  std::vector<std::size_t> order_b(b.size());
  std::iota(order_b.begin(), order_b.end(), 0);
  std::sort(order_b.begin(), order_b.end(), [&](auto x, auto y) { return b[x] < b[y]; });
  std::vector<std::tuple<double, std::size_t, std::size_t>> cand;
  for (std::size_t i = 0; i < a.size(); ++i) {
    auto it = std::lower_bound(order_b.begin(), order_b.end(), a[i] - max_dt,
                               [&](std::size_t j, double t) { return b[j] < t; });
    for (; it != order_b.end() && b[*it] <= a[i] + max_dt; ++it)
      cand.emplace_back(std::abs(b[*it] - a[i]), i, *it);
  }
  std::sort(cand.begin(), cand.end());
  std::vector<bool> used_a(a.size()), used_b(b.size());
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (const auto& [dt, i, j] : cand) {
    if (used_a[i] || used_b[j]) continue;
    used_a[i] = used_b[j] = true;
    pairs.emplace_back(i, j);
  }
  std::sort(pairs.begin(), pairs.end(), [&](auto& p, auto& q) { return a[p.first] < a[q.first]; });
  return pairs;
}

}  // namespace hrgbd
