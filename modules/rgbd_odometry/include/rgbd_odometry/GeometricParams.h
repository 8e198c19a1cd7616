#pragma once
/** \file GeometricParams.h
 * Parameters of the geometric path (paper sections III-C to III-F): down-sampling, normals,
 * IS3D sampling and SHOT descriptors. INI section [Geometric]. */
#include "rgbd_core/Params.h"

namespace hrgbd {

/** Parameters of extractGeometricFeatures() and its stages. INI section [Geometric]. */
struct GeometricParams : public Params<GeometricParams> {
  // III-C: pre-processing
  double max_depth = 5.0;    //!< [m] farther points are dropped (paper III-C)
  int pixel_stride = 2;      //!< [px] every n-th depth pixel in u and v is back-projected
  int target_points = 3500;  //!< [count] wanted after down-sampling (radius adapted per frame)
  // III-D: normals
  /** Plane-fit neighbourhood radius / down-sampling radius. Deliberately large (III-D), so
   * normals near edges and corners differ from those of the planes. */
  double normal_radius_factor = 3.0;
  // III-E: IS3D sampling (Algorithm 1)
  int is3d_points = 350;     //!< [count] most IS3D points kept (random subset when more)
  int is3d_references = 40;  //!< random reference normals tried per dominant orientation
  /** k' / points: a dominant orientation is shared by at least this share of the cloud; the
   * reference with the least k'-th order squared angle residual defines it (eq. 3). */
  double is3d_k_fraction = 0.05;
  /** [deg] when even the best reference's k'-th order angle residual exceeds this, no dominant
   * orientation is left and the remaining points are the IS3D points. */
  double is3d_max_group_angle_deg = 10;
  double is3d_T = 2.5;      //!< MSSE threshold of eq. (4) separating a dominant group
  int is3d_max_groups = 8;  //!< most dominant orientations removed
  // III-F: SHOT descriptors and matching
  double shot_radius_factor = 5.0;       //!< SHOT support radius / down-sampling radius
  int shot_min_neighbours = 10;          //!< IS3D points with fewer support points are dropped
  double max_descriptor_distance = 1.0;  //!< L2 between unit SHOT vectors; farther: no match
  int seed = 1;                          //!< random generator seed (same seed, same result)
  // Addition to the paper: point-to-plane ICP on the down-sampled clouds after MSSE.
  /** Refinement iterations, 0 = the paper's geometric path exactly. The IS3D keypoints are cell
   * centroids whose position jitters by up to half a cell between frames, which limits the
   * MSSE fit to about 1 cm / 1 deg per frame. 0 while the dense refinement (the default) fits
   * point-to-plane on the full depth image: the ICP on the cell centroids only repeats that, and
   * on wide baselines pulls the fits away (config.ini says what was measured). 10 without it. */
  int refine_iterations = 0;
  double refine_max_distance = 0.05;  //!< [m] farther point pairs are not used
  /** Share of the source cloud paired after the refinement below which the frame is rejected
   * (status large_residuals): a wrong match set leaves the clouds apart. */
  double refine_min_overlap = 0.5;

  template <class P, class V>
  static void declare(P& p, V& v) {
    HRGBD_PARAM(max_depth, "[m] farther points are dropped (III-C)", Range::above(0));
    HRGBD_PARAM(pixel_stride, "[px] every n-th depth pixel is back-projected",
                Range::closed(1, 16));
    HRGBD_PARAM(target_points, "[count] wanted after down-sampling", Range::atLeast(100));
    HRGBD_PARAM(normal_radius_factor, "normal neighbourhood / cell size (III-D)",
                Range::atLeast(1));
    HRGBD_PARAM(is3d_points, "[count] most IS3D points kept", Range::atLeast(10));
    HRGBD_PARAM(is3d_references, "reference normals tried per orientation", Range::atLeast(1));
    HRGBD_PARAM(is3d_k_fraction, "k' / points of a dominant orientation", Range::open(0, 1));
    HRGBD_PARAM(is3d_max_group_angle_deg, "[deg] k'-th residual limit", Range::open(0, 90));
    HRGBD_PARAM(is3d_T, "MSSE threshold of eq. (4)", Range::above(0));
    HRGBD_PARAM(is3d_max_groups, "most dominant orientations removed", Range::atLeast(0));
    HRGBD_PARAM(shot_radius_factor, "SHOT support radius / cell size", Range::atLeast(1));
    HRGBD_PARAM(shot_min_neighbours, "fewer support points: keypoint dropped", Range::atLeast(3));
    HRGBD_PARAM(max_descriptor_distance, "L2 SHOT match limit", Range::above(0));
    HRGBD_PARAM(seed, "random seed");
    HRGBD_PARAM(refine_iterations, "point-to-plane ICP after MSSE, 0 = paper", Range::atLeast(0));
    HRGBD_PARAM(refine_max_distance, "[m] ICP pairing distance", Range::above(0));
    HRGBD_PARAM(refine_min_overlap, "paired share of the cloud; less: rejected",
                Range::closed(0, 1));
  }
};

}  // namespace hrgbd
