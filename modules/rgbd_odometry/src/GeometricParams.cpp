#include "rgbd_odometry/GeometricParams.h"

#include "rgbd_core/Config.h"

namespace hrgbd {

void GeometricParams::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                         const std::string& s) {
  rejectUnknownKeys(
      c, s,
      {"max_depth", "pixel_stride", "target_points", "normal_radius_factor", "is3d_points",
       "is3d_references", "is3d_k_fraction", "is3d_max_group_angle_deg", "is3d_T",
       "is3d_max_groups", "shot_radius_factor", "shot_min_neighbours", "max_descriptor_distance",
       "seed", "refine_iterations", "refine_max_distance", "refine_min_overlap"});
  MRPT_LOAD_CONFIG_VAR_CS(max_depth, double);
  MRPT_LOAD_CONFIG_VAR_CS(pixel_stride, int);
  MRPT_LOAD_CONFIG_VAR_CS(target_points, int);
  MRPT_LOAD_CONFIG_VAR_CS(normal_radius_factor, double);
  MRPT_LOAD_CONFIG_VAR_CS(is3d_points, int);
  MRPT_LOAD_CONFIG_VAR_CS(is3d_references, int);
  MRPT_LOAD_CONFIG_VAR_CS(is3d_k_fraction, double);
  MRPT_LOAD_CONFIG_VAR_CS(is3d_max_group_angle_deg, double);
  MRPT_LOAD_CONFIG_VAR_CS(is3d_T, double);
  MRPT_LOAD_CONFIG_VAR_CS(is3d_max_groups, int);
  MRPT_LOAD_CONFIG_VAR_CS(shot_radius_factor, double);
  MRPT_LOAD_CONFIG_VAR_CS(shot_min_neighbours, int);
  MRPT_LOAD_CONFIG_VAR_CS(max_descriptor_distance, double);
  MRPT_LOAD_CONFIG_VAR_CS(seed, int);
  MRPT_LOAD_CONFIG_VAR_CS(refine_iterations, int);
  MRPT_LOAD_CONFIG_VAR_CS(refine_max_distance, double);
  MRPT_LOAD_CONFIG_VAR_CS(refine_min_overlap, double);
  requireValid(refine_min_overlap >= 0 && refine_min_overlap <= 1, s, "refine_min_overlap",
               refine_min_overlap, "must be in [0, 1]");
  requireValid(refine_iterations >= 0, s, "refine_iterations", refine_iterations, "must be >= 0");
  requireValid(refine_max_distance > 0, s, "refine_max_distance", refine_max_distance,
               "must be > 0 m");
  requireValid(max_depth > 0, s, "max_depth", max_depth, "must be > 0 m");
  requireValid(pixel_stride >= 1 && pixel_stride <= 16, s, "pixel_stride", pixel_stride,
               "must be in [1, 16] px");
  requireValid(target_points >= 100, s, "target_points", target_points, "must be >= 100");
  requireValid(normal_radius_factor >= 1, s, "normal_radius_factor", normal_radius_factor,
               "must be >= 1");
  requireValid(is3d_points >= 10, s, "is3d_points", is3d_points, "must be >= 10");
  requireValid(is3d_references >= 1, s, "is3d_references", is3d_references, "must be >= 1");
  requireValid(is3d_k_fraction > 0 && is3d_k_fraction < 1, s, "is3d_k_fraction", is3d_k_fraction,
               "must be in (0, 1)");
  requireValid(is3d_max_group_angle_deg > 0 && is3d_max_group_angle_deg < 90, s,
               "is3d_max_group_angle_deg", is3d_max_group_angle_deg, "must be in (0, 90) deg");
  requireValid(is3d_T > 0, s, "is3d_T", is3d_T, "must be > 0");
  requireValid(is3d_max_groups >= 0, s, "is3d_max_groups", is3d_max_groups, "must be >= 0");
  requireValid(shot_radius_factor >= 1, s, "shot_radius_factor", shot_radius_factor,
               "must be >= 1");
  requireValid(shot_min_neighbours >= 3, s, "shot_min_neighbours", shot_min_neighbours,
               "must be >= 3");
  requireValid(max_descriptor_distance > 0, s, "max_descriptor_distance", max_descriptor_distance,
               "must be > 0");
}

void GeometricParams::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                       const std::string& s) const {
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_depth, "[m] farther points are dropped (III-C)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(pixel_stride, "[px] every n-th depth pixel is back-projected");
  MRPT_SAVE_CONFIG_VAR_COMMENT(target_points, "[count] wanted after down-sampling");
  MRPT_SAVE_CONFIG_VAR_COMMENT(normal_radius_factor, "normal neighbourhood / cell size (III-D)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(is3d_points, "[count] most IS3D points kept");
  MRPT_SAVE_CONFIG_VAR_COMMENT(is3d_references, "reference normals tried per orientation");
  MRPT_SAVE_CONFIG_VAR_COMMENT(is3d_k_fraction, "k' / points of a dominant orientation");
  MRPT_SAVE_CONFIG_VAR_COMMENT(is3d_max_group_angle_deg, "[deg] k'-th residual limit");
  MRPT_SAVE_CONFIG_VAR_COMMENT(is3d_T, "MSSE threshold of eq. (4)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(is3d_max_groups, "most dominant orientations removed");
  MRPT_SAVE_CONFIG_VAR_COMMENT(shot_radius_factor, "SHOT support radius / cell size");
  MRPT_SAVE_CONFIG_VAR_COMMENT(shot_min_neighbours, "fewer support points: keypoint dropped");
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_descriptor_distance, "L2 SHOT match limit");
  MRPT_SAVE_CONFIG_VAR_COMMENT(seed, "random seed");
  MRPT_SAVE_CONFIG_VAR_COMMENT(refine_iterations, "point-to-plane ICP after MSSE, 0 = paper");
  MRPT_SAVE_CONFIG_VAR_COMMENT(refine_max_distance, "[m] ICP pairing distance");
  MRPT_SAVE_CONFIG_VAR_COMMENT(refine_min_overlap, "paired share of the cloud; less: rejected");
}

}  // namespace hrgbd
