#pragma once
/** \file SlamPoses.h
 * What the SLAM mode hands to the outputs: optimised poses and the loops that hold. */
#include <mrpt/poses/CPose3D.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace hrgbd {

/** Poses of every frame since the start or the last reset (optical frame of the first camera),
 * and the loop edges that hold, as pairs of frame indices (older, newer). */
struct SlamPoses {
  std::vector<mrpt::poses::CPose3D> poses;
  std::vector<std::pair<std::size_t, std::size_t>> loops;
  /** per loop: the relative pose its registration measured (newer in older's frame) */
  std::vector<mrpt::poses::CPose3D> loop_measured;
};

}  // namespace hrgbd
