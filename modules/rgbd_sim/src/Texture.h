#pragma once
// Procedural textures with natural (1/f) statistics: fractal value noise, coloured. Private.
#include <Eigen/Core>
#include <cmath>
#include <cstdint>

namespace hrgbd::sim {

inline double hash01(int x, int y, int seed) {
  uint32_t h = static_cast<uint32_t>(x) * 374761393u + static_cast<uint32_t>(y) * 668265263u +
               static_cast<uint32_t>(seed) * 2246822519u;
  h = (h ^ (h >> 13)) * 1274126177u;
  return ((h ^ (h >> 16)) & 0xffffff) / double(0xffffff);
}

inline double valueNoise(double x, double y, int seed) {
  const int xi = static_cast<int>(std::floor(x)), yi = static_cast<int>(std::floor(y));
  double fx = x - xi, fy = y - yi;
  fx = fx * fx * (3 - 2 * fx), fy = fy * fy * (3 - 2 * fy);
  const double a = hash01(xi, yi, seed), b = hash01(xi + 1, yi, seed);
  const double c = hash01(xi, yi + 1, seed), d = hash01(xi + 1, yi + 1, seed);
  return (a + (b - a) * fx) + ((c + (d - c) * fx) - (a + (b - a) * fx)) * fy;
}

/** Fractal noise: 5 octaves, amplitude halving per octave (1/f spectrum), in [0, 1]. */
inline double fbm(double x, double y, int seed) {
  double s = 0, amp = 0.5, norm = 0;
  for (int o = 0; o < 5; ++o, x *= 2.03, y *= 2.03, amp *= 0.5) {
    s += amp * valueNoise(x, y, seed + 17 * o);
    norm += amp;
  }
  return s / norm;
}

/** RGB albedo multiplier of texture `seed` at surface coordinates (a, b) [m]. */
inline Eigen::Vector3d textureColour(int seed, double a, double b, double scale) {
  const double x = a * scale, y = b * scale;
  const double n1 = fbm(x, y, seed), n2 = fbm(x * 1.7 + 3.1, y * 1.7 - 1.3, seed + 5);
  const double edges = std::pow(std::abs(2 * fbm(x * 3, y * 3, seed + 9) - 1), 0.2);
  const double speckle = valueNoise(x * 9, y * 9, seed + 13) > 0.72 ? 0.45 : 1.0;  // small marks
  const Eigen::Vector3d c1(0.25 + 0.7 * hash01(seed, 1, 3), 0.25 + 0.7 * hash01(seed, 2, 3),
                           0.25 + 0.7 * hash01(seed, 3, 3));
  const Eigen::Vector3d c2(0.9 - c1.x() * 0.6, 0.2 + c1.z() * 0.5, 0.9 - c1.y() * 0.7);
  return ((n1 * c1 + (1 - n1) * c2) * (0.3 + 0.7 * edges) * (0.5 + n2) * speckle).cwiseMin(1.3);
}

}  // namespace hrgbd::sim
