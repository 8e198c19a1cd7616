#include "rgbd_odometry/PointCloud.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <nanoflann.hpp>
#include <unordered_map>

namespace hrgbd {
namespace {

// Every s-th depth pixel back-projected (eqs. 1-2), row by row; z = 0 where the depth is
// missing or beyond max_depth.
struct Grid {
  int rows = 0, cols = 0;
  std::vector<Eigen::Vector3d> p;
  const Eigen::Vector3d& at(int r, int c) const { return p[std::size_t(r) * cols + c]; }
};

Grid backProjectGrid(const RgbdImage& im, int s, float max_depth) {
  Grid g;
  g.rows = (im.depth.rows + s - 1) / s;
  g.cols = (im.depth.cols + s - 1) / s;
  g.p.assign(std::size_t(g.rows) * g.cols, Eigen::Vector3d::Zero());
  for (int r = 0; r < g.rows; ++r)
    for (int c = 0; c < g.cols; ++c) {
      const float z = im.depth.at<float>(r * s, c * s);
      if (z > 0 && z <= max_depth)
        g.p[std::size_t(r) * g.cols + c] = im.cam.backProject(c * s, r * s, z);
    }
  return g;
}

// Mean distance between grid-neighbouring points on the same surface (a depth jump larger than
// four pixel footprints is a discontinuity, not a neighbour).
double meanGridSpacing(const Grid& g, int s, double fx) {
  double sum = 0;
  std::size_t n = 0;
  for (int r = 0; r + 1 < g.rows; ++r)
    for (int c = 0; c + 1 < g.cols; ++c) {
      const Eigen::Vector3d& p = g.at(r, c);
      if (p.z() == 0) continue;
      double best = 4.0 * s * p.z() / fx;
      bool found = false;
      for (const Eigen::Vector3d* q : {&g.at(r, c + 1), &g.at(r + 1, c)}) {
        if (q->z() == 0) continue;
        const double d = (*q - p).norm();
        if (d < best) best = d, found = true;
      }
      if (found) sum += best, ++n;
    }
  return n ? sum / n : 0.0;
}

Points voxelCentroids(const Points& in, double cell) {
  struct Acc {
    Eigen::Vector3f sum = Eigen::Vector3f::Zero();
    int n = 0;
  };
  std::unordered_map<std::uint64_t, std::size_t> index;
  index.reserve(in.size() / 4 + 16);
  std::vector<Acc> acc;
  const double inv = 1.0 / cell;
  for (const auto& p : in) {
    // 21 bits per axis: +-1M cells, far beyond max_depth / any sensible cell size.
    auto key = [&](float x) {
      return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(x * inv)) +
                                        (1 << 20)) &
             0x1FFFFF;
    };
    const std::uint64_t k = key(p.x()) | key(p.y()) << 21 | key(p.z()) << 42;
    const auto [it, added] = index.try_emplace(k, acc.size());
    if (added) acc.emplace_back();
    acc[it->second].sum += p;
    ++acc[it->second].n;
  }
  Points out;
  out.reserve(acc.size());
  for (const auto& a : acc) out.push_back(a.sum / static_cast<float>(a.n));
  return out;
}

// nanoflann adaptor over Points.
struct PointsAdaptor {
  const Points& pts;
  std::size_t kdtree_get_point_count() const { return pts.size(); }
  float kdtree_get_pt(std::size_t i, std::size_t d) const { return pts[i][d]; }
  template <class BBox>
  bool kdtree_get_bbox(BBox&) const {
    return false;
  }
};
using KdTree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, PointsAdaptor>,
                                        PointsAdaptor, 3, std::size_t>;

}  // namespace

DownsampledCloud downsampleDepth(const RgbdImage& image, const GeometricParams& p) {
  DownsampledCloud out;
  const Grid grid = backProjectGrid(image, p.pixel_stride, static_cast<float>(p.max_depth));
  Points pts;
  pts.reserve(grid.p.size());
  for (const auto& q : grid.p)
    if (q.z() != 0) pts.push_back(q.cast<float>());
  out.input_points = pts.size();
  out.mean_spacing = meanGridSpacing(grid, p.pixel_stride, image.cam.fx);
  if (pts.empty() || out.mean_spacing <= 0) return out;

  const double target = p.target_points;
  if (pts.size() <= target) {  // already sparse enough
    out.points = std::move(pts);
    out.radius = out.mean_spacing;
    return out;
  }
  // Radius from the spacing (section III-C), then corrected: cells ~ area / radius^2.
  out.radius = out.mean_spacing * std::sqrt(pts.size() / target);
  out.points = voxelCentroids(pts, out.radius);
  for (int i = 0; i < 3 && std::abs(out.points.size() / target - 1.0) > 0.1; ++i) {
    out.radius *= std::sqrt(out.points.size() / target);
    out.points = voxelCentroids(pts, out.radius);
  }
  return out;
}

struct PointKdTree::Impl {
  explicit Impl(const Points& p) : adaptor{p}, tree(3, adaptor, {10}) { tree.buildIndex(); }
  PointsAdaptor adaptor;
  KdTree tree;
};

PointKdTree::PointKdTree(const Points& points) : m_impl(std::make_unique<Impl>(points)) {}
PointKdTree::~PointKdTree() = default;

void PointKdTree::radiusSearch(const Eigen::Vector3f& q, float radius,
                               std::vector<std::pair<std::size_t, float>>& out) const {
  out.clear();
  nanoflann::SearchParams params;
  params.sorted = false;
  m_impl->tree.radiusSearch(q.data(), radius * radius, out, params);  // L2_Simple: squared
}

bool PointKdTree::nearest(const Eigen::Vector3f& q, std::size_t& index, float& dist2) const {
  if (m_impl->adaptor.pts.empty()) return false;
  return m_impl->tree.knnSearch(q.data(), 1, &index, &dist2) == 1;
}

Points estimateNormals(const Points& pts, const PointKdTree& tree, double radius) {
  Points normals(pts.size());
  std::vector<std::pair<std::size_t, float>> nbrs;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    tree.radiusSearch(pts[i], static_cast<float>(radius), nbrs);
    Eigen::Vector3f n = -pts[i].normalized();
    if (nbrs.size() >= 3) {
      Eigen::Vector3f mean = Eigen::Vector3f::Zero();
      for (const auto& [j, d2] : nbrs) mean += pts[j];
      mean /= static_cast<float>(nbrs.size());
      Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
      for (const auto& [j, d2] : nbrs) {
        const Eigen::Vector3d d = (pts[j] - mean).cast<double>();
        cov += d * d.transpose();
      }
      // closed form (3x3, in double: accurate for the smallest eigenvector of a flat patch)
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
      eig.computeDirect(cov);
      n = eig.eigenvectors().col(0).cast<float>();  // smallest eigenvalue: the plane's normal
      if (n.dot(pts[i]) > 0) n = -n;                // towards the camera at the origin
    }
    normals[i] = n;
  }
  return normals;
}

}  // namespace hrgbd
