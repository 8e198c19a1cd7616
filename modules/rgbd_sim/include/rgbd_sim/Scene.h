#pragma once
/** \file Scene.h
 * Scenes of textured or plain rectangles (planes, box faces) for the RGB-D simulator. World frame:
 * z up, metres. */
#include <Eigen/Core>
#include <string>
#include <vector>

namespace hrgbd::sim {

/** A rectangle: points origin + a*u + b*v for a in [0, |u|], b in [0, |v|] (u, v orthogonal). */
struct Quad {
  Eigen::Vector3d origin, u, v;           //!< [m] corner and the two edge vectors
  Eigen::Vector3d colour{0.7, 0.7, 0.7};  //!< base albedo, RGB in [0, 1]
  int texture = -1;            //!< procedural texture seed; -1 = plain (matte, no texture)
  double texture_scale = 1.0;  //!< [1/m] texture features per metre
  bool stripes = false;        //!< the texture varies along u only: lines along v
};

/** An axis-aligned ellipsoid (rounded objects: the fr3/teddy-like scene). */
struct Ellipsoid {
  Eigen::Vector3d centre, radii;          //!< [m]
  Eigen::Vector3d colour{0.7, 0.7, 0.7};  //!< base albedo, RGB in [0, 1]
  int texture = -1;                       //!< as Quad::texture
  double texture_scale = 12.0;            //!< [1/m]
};

/** A scene and where the camera should look. */
struct Scene {
  std::string name;
  std::vector<Quad> quads;
  std::vector<Ellipsoid> ellipsoids;
  Eigen::Vector3d look_at{0, 0, 0};      //!< [m] centre of interest
  Eigen::Vector3d sweep_axis{1, 0, 0};   //!< direction of procedural sweeps
  Eigen::Vector3d view_dir{0, -1, 0.4};  //!< from look_at towards the camera (normalised on use)
  double distance = 1.0;                 //!< [m] nominal camera-to-structure distance
};

/** Adds the 5 faces (no bottom) of an axis-aligned box. */
void addBox(Scene& s, const Eigen::Vector3d& min, const Eigen::Vector3d& max,
            const Eigen::Vector3d& colour, int texture);

/** Scene types of the paper's Table I: "texture" (textured floor, no structure), "structure"
 * (zig-zag of plain panels on a plain floor), "structure_texture" (the same zig-zag textured),
 * "desk" (office room with a desk and boxes, like fr1/desk), "wall" (plain flat wall: neither
 * texture nor structure); and "object" (a rounded furry object on a plain pedestal in an open
 * hall, like fr3/teddy: the counterpart of the real frames in the realism check). `far` puts the
 * camera at ~2 m instead of ~1 m. Throws for other names. */
Scene makeScene(const std::string& type, bool far);

/** `scene` at time `t` [s] with a person-sized textured box walking back and forth across it at
 * `speed` [m/s] (> 0; a moving object, as in TUM's fr2/desk_with_person or fr3/walking): 0.45 m
 * wide, 0.15 m deep, 1.7 m tall, on the floor 0.6 m beyond look_at (away from the camera), its
 * centre moving +-0.8 m along sweep_axis, starting at one end. It is placed at time t only (no
 * motion blur, no rolling shutter of its own). */
Scene withWalker(Scene scene, double t, double speed);

/** The scene type names makeScene() accepts. */
const std::vector<std::string>& sceneTypes();

}  // namespace hrgbd::sim
