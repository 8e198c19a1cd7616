#pragma once
/** \file TimeAssociation.h
 * Matching two lists of time stamps, as TUM's associate.py does. */
#include <cstddef>
#include <utility>
#include <vector>

namespace hrgbd {

/** Pairs (i, j) with |a[i] - b[j]| <= max_dt [s], chosen greedily by increasing difference,
 * each index used at most once; returned sorted by a[i]. Inputs need not be sorted. */
std::vector<std::pair<std::size_t, std::size_t>> associateByTime(const std::vector<double>& a,
                                                                 const std::vector<double>& b,
                                                                 double max_dt);

}  // namespace hrgbd
