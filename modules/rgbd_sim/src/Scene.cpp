#include "rgbd_sim/Scene.h"

#include <cmath>
#include <stdexcept>

namespace hrgbd::sim {
namespace {

using V = Eigen::Vector3d;

Quad quad(V o, V u, V v, V colour, int texture, double scale = 12.0) {
  return {o, u, v, colour, texture, scale, false};
}

// A zig-zag of panels along x, standing on the floor: each panel 0.5 m wide, 0.8 m tall,
// alternately turned +-45 deg about z (like the TUM fr3 structure sequences).
void addZigZag(Scene& s, bool textured) {
  const double w = 0.5, h = 0.8, a = M_PI / 4;
  V p(-1.4, 0.0, 0.0);
  for (int i = 0; i < 8; ++i) {
    const double ang = (i % 2 == 0) ? a : -a;
    const V u(w * std::cos(ang), w * std::sin(ang), 0.0);
    s.quads.push_back(quad(p, u, V(0, 0, h), V(0.82, 0.74, 0.60), textured ? 100 + i : -1));
    p += u;
  }
}

// A large textured poster on the floor; the camera looks down at it.
void addTexture(Scene& s) {
  s.quads.push_back(quad(V(-3, -3, 0), V(6, 0, 0), V(0, 6, 0), V(0.8, 0.8, 0.8), 1, 10.0));
  s.look_at = V(0, 0, 0);
  s.view_dir = V(0, -0.6, 1.0);
}

// The zig-zag on a plain floor, plain or textured.
void addStructure(Scene& s, bool textured) {
  s.quads.push_back(quad(V(-3, -3, 0), V(6, 0, 0), V(0, 6, 0), V(0.55, 0.55, 0.52), -1));
  addZigZag(s, textured);
  s.look_at = V(0.0, 0.0, 0.35);
}

// An office corner with a desk and boxes (like fr1/desk), and the rest of the room.
void addDeskRoom(Scene& s) {
  s.quads.push_back(quad(V(-2, -1, 0), V(4, 0, 0), V(0, 3, 0), V(0.45, 0.42, 0.40), 7, 8.0));
  s.quads.push_back(quad(V(-2, 2, 0), V(4, 0, 0), V(0, 0, 2.5), V(0.85, 0.85, 0.80), -1));
  s.quads.push_back(quad(V(-2, -1, 0), V(0, 3, 0), V(0, 0, 2.5), V(0.80, 0.82, 0.85), -1));
  // The rest of the room, seen when replayed hand-held motion turns around the desk.
  s.quads.push_back(quad(V(-2, -2.5, 0), V(4, 0, 0), V(0, 1.5, 0), V(0.45, 0.42, 0.40), 8, 8.0));
  s.quads.push_back(quad(V(-2, -2.5, 0), V(0, 1.5, 0), V(0, 0, 2.5), V(0.80, 0.82, 0.85), -1));
  s.quads.push_back(quad(V(2, -2.5, 0), V(0, 4.5, 0), V(0, 0, 2.5), V(0.78, 0.80, 0.76), -1));
  s.quads.push_back(quad(V(-2, -2.5, 0), V(4, 0, 0), V(0, 0, 2.5), V(0.84, 0.80, 0.74), -1));
  addBox(s, V(-0.8, 1.0, 0.0), V(0.8, 1.8, 0.72), V(0.60, 0.45, 0.30), 11);  // desk
  addBox(s, V(-0.5, 1.2, 0.72), V(-0.1, 1.5, 0.95), V(0.2, 0.3, 0.6), 21);   // box
  addBox(s, V(0.2, 1.3, 0.72), V(0.45, 1.6, 1.05), V(0.7, 0.2, 0.2), 31);    // box
  addBox(s, V(0.55, 1.1, 0.72), V(0.75, 1.25, 0.80), V(0.9, 0.9, 0.9), 41);  // book
  addBox(s, V(-1.6, 1.4, 0.0), V(-1.1, 1.9, 0.5), V(0.3, 0.5, 0.3), 51);     // crate
  s.look_at = V(0.0, 1.3, 0.75);
  s.view_dir = V(0, -1, 0.6);
  s.sweep_axis = V(1, 0, 0);
}

// A plain flat wall: neither texture nor structure.
void addWall(Scene& s) {
  s.quads.push_back(quad(V(-4, 0, -1), V(8, 0, 0), V(0, 0, 4), V(0.85, 0.84, 0.80), -1));
  s.look_at = V(0, 0, 1.0);
  s.view_dir = V(0, -1, 0.05);
}

// A flat wall with vertical stripes (a texture that varies along x only): no structure, and no
// texture along the stripes.
void addStripes(Scene& s) {
  Quad q = quad(V(-4, 0, -1), V(8, 0, 0), V(0, 0, 4), V(0.85, 0.84, 0.80), 61, 6.0);
  q.stripes = true;
  s.quads.push_back(q);
  s.look_at = V(0, 0, 1.0);
  s.view_dir = V(0, -1, 0.05);
  s.sweep_axis = V(0, 0, 1);  // along the stripes
}

// A plain corridor 2 m wide and 2.5 m high, 30 m long (its ends beyond the depth range), the
// camera looking along it and sweeping along it.
void addCorridor(Scene& s) {
  const V grey(0.80, 0.80, 0.78);
  s.quads.push_back(quad(V(-15, -1, 0), V(30, 0, 0), V(0, 2, 0), V(0.55, 0.55, 0.52), -1));
  s.quads.push_back(quad(V(-15, -1, 2.5), V(30, 0, 0), V(0, 2, 0), grey, -1));
  s.quads.push_back(quad(V(-15, -1, 0), V(30, 0, 0), V(0, 0, 2.5), grey, -1));
  s.quads.push_back(quad(V(-15, 1, 0), V(30, 0, 0), V(0, 0, 2.5), grey, -1));
  s.look_at = V(0, 0, 1.3);
  s.view_dir = V(1, 0, 0.02);
  s.sweep_axis = V(1, 0, 0);
}

// A furry bear-like object made of ellipsoids, centred above (0, 0, 0.75).
void addBear(Scene& s) {
  const V fur(0.55, 0.36, 0.2), shirt(0.95, 0.85, 0.15);
  s.ellipsoids.push_back({V(0, 0, 1.00), V(0.21, 0.18, 0.26), shirt, 81, 10});    // body
  s.ellipsoids.push_back({V(0, 0, 1.35), V(0.15, 0.14, 0.14), fur, 82, 14});      // head
  s.ellipsoids.push_back({V(0, -0.12, 1.32), V(0.06, 0.06, 0.05), fur, 83, 14});  // snout
  for (double side : {-1.0, 1.0}) {
    s.ellipsoids.push_back({V(side * 0.11, 0, 1.48), V(0.05, 0.03, 0.05), fur, 84, 14});    // ear
    s.ellipsoids.push_back({V(side * 0.1, -0.2, 0.82), V(0.08, 0.16, 0.08), fur, 85, 14});  // leg
    s.ellipsoids.push_back({V(side * 0.24, -0.05, 1.05), V(0.06, 0.07, 0.17), fur, 86, 14});
  }
}

// An open hall (fr3/teddy): plain floor and walls 3.5 m away with posters, a table, a crate, a
// plain pedestal and on it the bear.
void addObjectHall(Scene& s) {
  s.quads.push_back(quad(V(-3.5, -3.5, 0), V(7, 0, 0), V(0, 7, 0), V(0.62, 0.62, 0.60), 91, 3));
  const V wall(0.86, 0.86, 0.84);
  s.quads.push_back(quad(V(-3.5, 3.5, 0), V(7, 0, 0), V(0, 0, 3), wall, -1));
  s.quads.push_back(quad(V(-3.5, -3.5, 0), V(7, 0, 0), V(0, 0, 3), wall, -1));
  s.quads.push_back(quad(V(-3.5, -3.5, 0), V(0, 7, 0), V(0, 0, 3), wall, -1));
  s.quads.push_back(quad(V(3.5, -3.5, 0), V(0, 7, 0), V(0, 0, 3), wall, -1));
  s.quads.push_back(quad(V(-1.0, 3.49, 0.2), V(1.6, 0, 0), V(0, 0, 0.9), V(0.9, 0.7, 0.2), 61, 4));
  s.quads.push_back(quad(V(3.49, -1.5, 0.8), V(0, 1.2, 0), V(0, 0, 1.0), V(0.8, 0.8, 0.9), 71, 4));
  s.quads.push_back(quad(V(-3.49, 0.5, 0.3), V(0, 1.5, 0), V(0, 0, 1.2), V(0.7, 0.8, 0.9), 75, 3));
  s.quads.push_back(quad(V(1.0, -3.49, 0.0), V(0.9, 0, 0), V(0, 0, 2.0), V(0.5, 0.4, 0.3), 77, 6));
  addBox(s, V(1.6, 2.2, 0.0), V(2.8, 3.0, 0.75), V(0.6, 0.5, 0.4), 93);     // table
  addBox(s, V(-2.6, -2.4, 0.0), V(-2.0, -1.8, 0.5), V(0.4, 0.5, 0.6), 95);  // crate
  addBox(s, V(-0.2, -0.2, 0.0), V(0.2, 0.2, 0.75), V(0.9, 0.9, 0.88), -1);  // pedestal
  addBear(s);
  s.look_at = V(0, 0, 1.05);
  s.view_dir = V(0, -1, 0.6);
}

}  // namespace

void addBox(Scene& s, const V& mn, const V& mx, const V& colour, int texture) {
  const V d = mx - mn;
  const V ex(d.x(), 0, 0), ey(0, d.y(), 0), ez(0, 0, d.z());
  s.quads.push_back(quad(mn, ex, ez, colour, texture));       // front (y = min)
  s.quads.push_back(quad(mn + ey, ex, ez, colour, texture));  // back
  s.quads.push_back(quad(mn, ey, ez, colour, texture));       // left
  s.quads.push_back(quad(mn + ex, ey, ez, colour, texture));  // right
  s.quads.push_back(quad(mn + ez, ex, ey, colour, texture < 0 ? -1 : texture + 1));  // top
}

Scene withWalker(Scene s, double t, double speed) {
  constexpr double kRange = 0.8;   // [m] either side of the path's centre
  constexpr double kBeyond = 0.6;  // [m] from look_at, away from the camera
  constexpr double kWidth = 0.45;  // [m] along the path
  constexpr double kDepth = 0.15;  // [m] across it (behind the desk, short of its wall)
  constexpr double kHeight = 1.7;  // [m]
  // horizontal unit vectors: away from the camera, and along the path (every scene's sweep_axis
  // and view direction lie along x or y, so the box stays axis-aligned)
  V away = -s.view_dir;
  away.z() = 0;
  away = away.norm() > 1e-9 ? away.normalized() : V(0, 1, 0);
  V axis = s.sweep_axis - s.sweep_axis.dot(away) * away;
  axis.z() = 0;
  axis = axis.norm() > 1e-9 ? axis.normalized() : away.cross(V(0, 0, 1));
  // a triangle wave: -kRange at t = 0, +kRange half a period later, back after a whole one
  const double period = 4 * kRange / speed;  // [s]
  double phase = std::fmod(t, period) / period;
  phase -= std::floor(phase);  // t < 0
  const double x = kRange * (phase < 0.5 ? 4 * phase - 1 : 3 - 4 * phase);
  V centre = s.look_at + kBeyond * away + x * axis;
  centre.z() = 0;
  const V half = 0.5 * (kWidth * axis.cwiseAbs() + kDepth * away.cwiseAbs());
  addBox(s, centre - half, centre + half + V(0, 0, kHeight), V(0.25, 0.35, 0.55), 121);
  return s;
}

const std::vector<std::string>& sceneTypes() {
  static const std::vector<std::string> t{"texture", "structure", "structure_texture", "desk",
                                          "wall",    "object",    "stripes",           "corridor"};
  return t;
}

Scene makeScene(const std::string& type, bool far) {
  Scene s;
  s.name = type + (far ? "_far" : "_near");
  s.distance = far ? 2.0 : 1.0;
  if (type == "texture")
    addTexture(s);
  else if (type == "structure" || type == "structure_texture")
    addStructure(s, type == "structure_texture");
  else if (type == "desk")
    addDeskRoom(s);
  else if (type == "wall")
    addWall(s);
  else if (type == "object")
    addObjectHall(s);
  else if (type == "stripes")
    addStripes(s);
  else if (type == "corridor")
    addCorridor(s);
  else
    throw std::invalid_argument(
        "unknown scene type '" + type +
        "' (texture, structure, structure_texture, desk, wall, object, stripes, "
        "corridor)");
  return s;
}

}  // namespace hrgbd::sim
