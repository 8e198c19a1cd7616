#pragma once
/** \file Median.h
 * The median used for robust scales (1.4826 x the median absolute residual) and timing figures. */
#include <algorithm>
#include <vector>

namespace hrgbd {

/** The upper median of `v` (element size / 2 in order): `v` is reordered, and must not be empty. */
template <class T>
T median(std::vector<T>& v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

}  // namespace hrgbd
