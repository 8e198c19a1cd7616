// Image pyramids for the dense refinement: intensity by 2x2 means (OpenCV), depth by a 2x2 rule
// written here because OpenCV's pyramids blend unknown depth (0) into known depth.
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "rgbd_odometry/DenseRefinement.h"

namespace hrgbd {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// Half-size depth: the mean of the known values of each 2x2 block that lie on the nearest
// surface (within 3 % of the nearest); NaN when none is known.
cv::Mat halveDepth(const cv::Mat& d) {
  cv::Mat out(d.rows / 2, d.cols / 2, CV_32F);
  for (int v = 0; v < out.rows; ++v)
    for (int u = 0; u < out.cols; ++u) {
      const float z[4] = {d.at<float>(2 * v, 2 * u), d.at<float>(2 * v, 2 * u + 1),
                          d.at<float>(2 * v + 1, 2 * u), d.at<float>(2 * v + 1, 2 * u + 1)};
      float nearest = std::numeric_limits<float>::infinity();
      for (float zi : z)
        if (zi < nearest) nearest = zi;  // false for NaN
      float sum = 0;
      int n = 0;
      for (float zi : z)
        if (zi <= nearest * 1.03f) sum += zi, ++n;
      out.at<float>(v, u) = n ? sum / n : kNaN;
    }
  return out;
}

// Unit normals from the cross product of central differences of the back-projected depth; NaN
// where a neighbour is unknown or across a jump larger than `max_jump` [m].
cv::Mat depthNormals(const cv::Mat& depth, const PinholeCamera& cam, double max_jump) {
  cv::Mat n(depth.size(), CV_32FC3, cv::Scalar::all(kNaN));
  // the back-projection's factors per column and row: vertex = (xs[u] z, ys[v] z, z)
  std::vector<float> xs(depth.cols), ys(depth.rows);
  for (int u = 0; u < depth.cols; ++u) xs[u] = static_cast<float>((u - cam.cx) / cam.fx);
  for (int v = 0; v < depth.rows; ++v) ys[v] = static_cast<float>((v - cam.cy) / cam.fy);
  auto vertex = [&](int u, int v) {
    const float z = depth.at<float>(v, u);
    return Eigen::Vector3f(xs[u] * z, ys[v] * z, z);
  };
  for (int v = 1; v + 1 < depth.rows; ++v)
    for (int u = 1; u + 1 < depth.cols; ++u) {
      const float z = depth.at<float>(v, u);
      const float zs[4] = {depth.at<float>(v, u - 1), depth.at<float>(v, u + 1),
                           depth.at<float>(v - 1, u), depth.at<float>(v + 1, u)};
      bool ok = std::isfinite(z);
      for (float zi : zs) ok = ok && std::abs(zi - z) <= max_jump;  // false for NaN
      if (!ok) continue;
      const Eigen::Vector3f dx = vertex(u + 1, v) - vertex(u - 1, v);
      const Eigen::Vector3f dy = vertex(u, v + 1) - vertex(u, v - 1);
      Eigen::Vector3f nv = dx.cross(dy);
      if (nv.norm() <= 0) continue;
      nv.normalize();
      if (nv.dot(vertex(u, v)) > 0) nv = -nv;
      n.at<cv::Vec3f>(v, u) = cv::Vec3f(nv.x(), nv.y(), nv.z());
    }
  return n;
}

// Non-zero where a corner of the 2x2 cell has a gradient of at least `min_gradient`: a bilinear
// sample of the gradient is a convex combination of the corners', never longer than the longest.
cv::Mat texturedCells(const cv::Mat& gx, const cv::Mat& gy, double min_gradient) {
  // (a margin of 1e-4 for the rounding of the float samples)
  cv::Mat strong = gx.mul(gx) + gy.mul(gy) >= min_gradient * min_gradient * (1 - 1e-4);
  cv::Mat cells;
  cv::dilate(strong, cells, cv::Mat::ones(2, 2, CV_8U), cv::Point(0, 0));
  return cells;
}

PinholeCamera halveCamera(PinholeCamera c) {
  c.fx /= 2, c.fy /= 2;
  c.cx = (c.cx + 0.5) / 2 - 0.5, c.cy = (c.cy + 0.5) / 2 - 0.5;
  c.width /= 2, c.height /= 2;
  return c;
}

}  // namespace

void DenseParams::checkTogether(const std::string& section) const {
  if (finest_level >= levels)
    throw ConfigError("[" + section + "] finest_level = " + std::to_string(finest_level) +
                      " must be below levels = " + std::to_string(levels));
}

void addDerivatives(DenseLevel& level, const DenseParams& params) {
  cv::Mat gx, gy;
  cv::Sobel(level.grey, gx, CV_32F, 1, 0, 1, 0.5);  // central differences
  cv::Sobel(level.grey, gy, CV_32F, 0, 1, 1, 0.5);
  level.textured = texturedCells(gx, gy, params.min_gradient);
  level.textured_gradient = params.min_gradient;
  level.normals = depthNormals(level.depth, level.cam, params.max_depth_difference);
  cv::Mat samples;  // new data: never written into a copy's
  cv::merge(std::vector<cv::Mat>{level.grey, gx, gy, cv::Mat::zeros(level.grey.size(), CV_32F)},
            samples);
  level.samples = samples;
}

void dropDerivatives(DenseLevel& level) {
  level.samples.release(), level.normals.release(), level.textured.release();
}

bool hasDerivatives(const DenseLevel& level) { return !level.samples.empty(); }

void packLevels(DensePyramid& pyramid) {
  for (auto& l : pyramid.levels) {
    if (l.packed_depth_units > 0) continue;
    dropDerivatives(l);
    l.grey.convertTo(l.grey, CV_16F);
    const cv::Mat known = (l.depth > 0) & (l.depth < std::numeric_limits<float>::max());
    double farthest = 0;
    cv::minMaxLoc(l.depth, nullptr, &farthest, nullptr, nullptr, known);
    // the farthest known depth is 65534 units: the precision follows the depth's scale
    l.packed_depth_units = farthest > 0 ? 65534 / farthest : 1;
    cv::Mat depth = l.depth.clone();  // (its buffer may be shared with the tracker's keyframe)
    depth.setTo(0, ~known);           // NaN (unknown)
    depth.convertTo(l.depth, CV_16U, l.packed_depth_units);
  }
}

void unpackLevels(DensePyramid& pyramid) {
  for (auto& l : pyramid.levels) {
    if (l.packed_depth_units <= 0) continue;
    l.grey.convertTo(l.grey, CV_32F);
    const cv::Mat unknown = l.depth == 0;
    l.depth.convertTo(l.depth, CV_32F, 1 / l.packed_depth_units);
    l.depth.setTo(kNaN, unknown);
    l.packed_depth_units = 0;
  }
}

void addDerivatives(DensePyramid& pyramid, const DenseParams& params) {
  for (auto& level : pyramid.levels)
    if (!hasDerivatives(level)) addDerivatives(level, params);
}

void dropDerivatives(DensePyramid& pyramid) {
  for (auto& level : pyramid.levels) dropDerivatives(level);
}

DensePyramid buildDensePyramid(const RgbdImage& image, const DenseParams& params,
                               bool derivatives) {
  DenseLevel level;
  level.cam = image.cam;
  image.grey.convertTo(level.grey, CV_32F);
  image.depth.copyTo(level.depth);
  level.depth.setTo(kNaN, ~((level.depth > 0) & (level.depth <= params.max_depth)));
  DensePyramid pyramid;
  for (int l = 0; l < params.levels; ++l) {
    if (l > 0) {
      if (level.depth.cols < 4 || level.depth.rows < 4) break;  // tiny images: fewer levels
      cv::resize(level.grey, level.grey, cv::Size(level.depth.cols / 2, level.depth.rows / 2), 0, 0,
                 cv::INTER_AREA);
      level.depth = halveDepth(level.depth);
      level.cam = halveCamera(level.cam);
    }
    if (l < params.finest_level) continue;
    DenseLevel out;
    out.cam = level.cam, out.grey = level.grey, out.depth = level.depth;
    if (derivatives) addDerivatives(out, params);
    pyramid.levels.push_back(std::move(out));
  }
  return pyramid;
}

}  // namespace hrgbd
