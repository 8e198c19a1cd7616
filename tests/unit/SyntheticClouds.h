#pragma once
// Synthetic point clouds with known geometry for the geometric-path tests (optical frame: z
// forward, camera at the origin).
#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "rgbd_odometry/PointCloud.h"

namespace hrgbd::test {

/** Grid points of the plane z = z0 + slope * x, |x|, |y| <= half, spacing `step`. */
inline Points tiltedPlane(double z0, double slope, double half, double step) {
  Points p;
  for (double x = -half; x <= half + 1e-9; x += step)
    for (double y = -half; y <= half + 1e-9; y += step)
      p.emplace_back(float(x), float(y), float(z0 + slope * x));
  return p;
}

/** The rotation taking the cube diagonal (-1,-1,-1) to the camera direction (0,0,-1). */
inline Eigen::Matrix3d cornerRotation() {
  return Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d(-1, -1, -1).normalized(),
                                            Eigen::Vector3d(0, 0, -1))
      .toRotationMatrix();
}

/** The three faces of the cube [0, side]^3 that meet at its origin O (the convex corner), turned
 * so the corner points at the camera, O at `distance` [m] on the optical axis. Face k holds the
 * points with coordinate k == 0 before the rotation. */
inline Points boxCorner(double side, double step, double distance) {
  const Eigen::Matrix3d R = cornerRotation();
  Points p;
  for (int face = 0; face < 3; ++face)
    for (double a = 0; a <= side + 1e-9; a += step)
      for (double b = 0; b <= side + 1e-9; b += step) {
        if (face > 0 && a < step / 2) continue;  // each edge once
        if (face == 2 && b < step / 2) continue;
        Eigen::Vector3d q = Eigen::Vector3d::Zero();
        q[(face + 1) % 3] = a;
        q[(face + 2) % 3] = b;
        p.push_back((R * q + Eigen::Vector3d(0, 0, distance)).cast<float>());
      }
  return p;
}

/** Distance of a box-corner point to the nearest of the corner's three edges [m]. */
inline double distanceToCornerEdge(const Eigen::Vector3f& pt, double distance) {
  const Eigen::Vector3d q =
      cornerRotation().transpose() * (pt.cast<double>() - Eigen::Vector3d(0, 0, distance));
  // On face k (q[k] ~ 0, nearest of the three) the edges are where one more coordinate is 0.
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(q[i]) < std::abs(q[k])) k = i;
  return std::min(std::abs(q[(k + 1) % 3]), std::abs(q[(k + 2) % 3]));
}

/** Zig-zag panels: z = distance + amplitude * tri(x / period), |x| <= half_width, |y| <= 0.5. */
inline Points zigZag(double distance, double amplitude, double period, double half_width,
                     double step) {
  Points p;
  for (double x = -half_width; x <= half_width + 1e-9; x += step)
    for (double y = -0.5; y <= 0.5 + 1e-9; y += step) {
      const double phase = x / period - std::floor(x / period);  // [0, 1)
      const double tri = phase < 0.5 ? 4 * phase - 1 : 3 - 4 * phase;
      p.emplace_back(float(x), float(y), float(distance + amplitude * tri));
    }
  return p;
}

/** Distance in x to the nearest fold of zigZag() [m]. */
inline double distanceToFold(double x, double period) {
  const double half = period / 2;
  return std::abs(x / half - std::round(x / half)) * half;
}

inline Points withNoise(Points p, double sigma, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> n(0, float(sigma));
  for (auto& q : p) q += Eigen::Vector3f(n(rng), n(rng), n(rng));
  return p;
}

inline Points transformed(const Points& p, const Eigen::Isometry3f& T, bool rotate_only = false) {
  Points out;
  for (const auto& q : p) out.push_back(rotate_only ? Eigen::Vector3f(T.linear() * q) : T * q);
  return out;
}

}  // namespace hrgbd::test
