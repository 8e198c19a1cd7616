#include "rgbd_sim/Render.h"

#include <mrpt/math/slerp.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "Texture.h"

namespace hrgbd::sim {
namespace {

// ---- Ideal rendering ----------------------------------------------------------------------

constexpr double kNearestHit = 0.05;  // [m] hits closer along the ray are ignored

struct QuadData {
  Eigen::Vector3d o, n, ud, vd, colour;  // ud, vd: unit edge directions
  double ul, vl, scale;
  int texture;
  bool stripes;
};

std::vector<QuadData> prepareQuads(const Scene& scene) {
  std::vector<QuadData> qs;
  for (const auto& q : scene.quads)
    qs.push_back({q.origin, q.u.cross(q.v).normalized(), q.u.normalized(), q.v.normalized(),
                  q.colour, q.u.norm(), q.v.norm(), q.texture_scale, q.texture, q.stripes});
  return qs;
}

const Eigen::Vector3d& lightDirection() {
  static const Eigen::Vector3d light = Eigen::Vector3d(0.3, -0.5, 1.0).normalized();
  return light;
}

/** Where one image row is seen from: its camera rotation and centre in the world. */
struct RowView {
  Eigen::Matrix3d R;
  Eigen::Vector3d c;
};

/** Row v's view: `pose`, or with a rolling shutter interpolated towards `last_row_pose`. */
RowView rowView(const mrpt::poses::CPose3D& pose,
                const std::optional<mrpt::poses::CPose3D>& last_row_pose, int v,
                const PinholeCamera& cam) {
  mrpt::math::TPose3D row = pose.asTPose();
  if (last_row_pose)
    mrpt::math::slerp(pose.asTPose(), last_row_pose->asTPose(), v / (cam.height - 1.0), row);
  const mrpt::poses::CPose3D row_pose(row);
  return {row_pose.getRotationMatrix().asEigen(), Eigen::Vector3d(row.x, row.y, row.z)};
}

/** The nearest surface along a ray c + t d (d with unit z in the camera: t is the depth). */
struct Hit {
  double t = 1e9;       // [m]
  int quad = -1;        // index into the quads, or -1
  int ellipsoid = -1;   // index into the ellipsoids, or -1
  double a = 0, b = 0;  // [m] the quad hit's coordinates along its edges
};

void hitQuads(const std::vector<QuadData>& qs, const Eigen::Vector3d& c, const Eigen::Vector3d& d,
              Hit& hit) {
  for (std::size_t k = 0; k < qs.size(); ++k) {
    const auto& q = qs[k];
    const double den = q.n.dot(d);
    if (std::abs(den) < 1e-9) continue;
    const double t = q.n.dot(q.o - c) / den;
    if (t <= kNearestHit || t >= hit.t) continue;
    const Eigen::Vector3d p = c + t * d - q.o;
    const double a = p.dot(q.ud), b = p.dot(q.vd);
    if (a < 0 || b < 0 || a > q.ul || b > q.vl) continue;
    hit.t = t, hit.quad = static_cast<int>(k), hit.a = a, hit.b = b;
  }
}

void hitEllipsoids(const std::vector<Ellipsoid>& es, const Eigen::Vector3d& c,
                   const Eigen::Vector3d& d, Hit& hit) {
  for (std::size_t k = 0; k < es.size(); ++k) {
    // The ray in the ellipsoid's unit-sphere coordinates: |o + t d|^2 = 1.
    const auto& e = es[k];
    const Eigen::Vector3d o = (c - e.centre).cwiseQuotient(e.radii);
    const Eigen::Vector3d de = d.cwiseQuotient(e.radii);
    const double a = de.squaredNorm(), bh = o.dot(de), disc = bh * bh - a * (o.squaredNorm() - 1);
    if (disc < 0) continue;
    const double t = (-bh - std::sqrt(disc)) / a;
    if (t <= kNearestHit || t >= hit.t) continue;
    hit.t = t, hit.ellipsoid = static_cast<int>(k), hit.quad = -1;
  }
}

/** The surface's normal, albedo and Lambertian term at a hit. */
struct Surface {
  Eigen::Vector3d normal, albedo;
  double lambert = 0;
};

Surface ellipsoidSurface(const Ellipsoid& e, const Eigen::Vector3d& c, const Eigen::Vector3d& d,
                         double t) {
  const Eigen::Vector3d p = c + t * d - e.centre;
  Surface s;
  s.normal = p.cwiseQuotient(e.radii.cwiseProduct(e.radii)).normalized();
  // Texture coordinates [m]: around the vertical axis and up it.
  const double around = std::atan2(p.y(), p.x()) * 0.5 * (e.radii.x() + e.radii.y());
  s.albedo = e.colour;
  if (e.texture >= 0)
    s.albedo = s.albedo.cwiseProduct(textureColour(e.texture, around, p.z(), e.texture_scale));
  s.lambert = std::max(0.0, s.normal.dot(lightDirection()));
  return s;
}

Surface quadSurface(const QuadData& q, double a, double b) {
  Surface s;
  s.normal = q.n;
  s.albedo = q.colour;
  if (q.texture >= 0)
    s.albedo = s.albedo.cwiseProduct(textureColour(q.texture, a, q.stripes ? 0 : b, q.scale));
  s.lambert = std::abs(s.normal.dot(lightDirection()));  // planes are lit from both sides
  return s;
}

/** Writes pixel (v, u): the background, or the shaded surface hit along the ray d. */
void shadePixel(IdealFrame& f, int v, int u, const Hit& hit, const std::optional<Surface>& surface,
                const Eigen::Vector3d& d) {
  auto& col = f.colour.at<cv::Vec3f>(v, u);
  if (!surface) {
    col = cv::Vec3f(0.05f, 0.05f, 0.06f);
    f.depth.at<float>(v, u) = 0;
    f.incidence.at<float>(v, u) = 0;
    return;
  }
  const Eigen::Vector3d rgb = surface->albedo * (0.35 + 0.65 * surface->lambert);
  col = cv::Vec3f(static_cast<float>(rgb.z()), static_cast<float>(rgb.y()),
                  static_cast<float>(rgb.x()));  // stored BGR, as OpenCV
  f.depth.at<float>(v, u) = static_cast<float>(hit.t);
  f.incidence.at<float>(v, u) = static_cast<float>(std::abs(surface->normal.dot(d.normalized())));
}

// ---- Kinect model -------------------------------------------------------------------------

/** The sensor model's random draws. One engine and one normal distribution serve every step, in
 * a fixed order: std::normal_distribution keeps a spare value between calls, so the distribution
 * object is part of the state that makes a seed give the same sequence. */
struct Draws {
  std::mt19937& rng;
  std::normal_distribution<double> g{0, 1};
  std::uniform_real_distribution<double> u01{0, 1};
};

/** Unit-std noise over an H x W image, smooth in blobs of ~W/cells px. */
cv::Mat smoothField(int H, int W, int cells, std::mt19937& r, std::normal_distribution<double>& g) {
  cv::Mat low(H * cells / W + 2, cells + 2, CV_32FC1), field;
  for (int i = 0; i < low.rows; ++i)
    for (int j = 0; j < low.cols; ++j) low.at<float>(i, j) = static_cast<float>(g(r));
  cv::resize(low, field, cv::Size(W, H), 0, 0, cv::INTER_CUBIC);
  cv::Scalar mean, sd;
  cv::meanStdDev(field, mean, sd);
  return cv::Mat((field - mean[0]) / std::max(1e-6, sd[0]));
}

/** Per-pixel unit-std noise averaged over the block matcher's correlation window (rescaled to
 * keep the per-pixel std), so neighbours are correlated. */
cv::Mat windowedWhiteNoise(int H, int W, int window, Draws& draws) {
  cv::Mat white(H, W, CV_32FC1);
  for (int v = 0; v < H; ++v)
    for (int u = 0; u < W; ++u) white.at<float>(v, u) = static_cast<float>(draws.g(draws.rng));
  if (window > 1) {
    cv::blur(white, white, cv::Size(window, window), cv::Point(-1, -1), cv::BORDER_REFLECT);
    white *= window;
  }
  return white;
}

/** [px] the disparity error of each pixel: a smooth field, the sensor unit's fixed pattern and
 * the windowed per-pixel noise. */
cv::Mat disparityNoise(const PinholeCamera& cam, const KinectModel& m, Draws& draws) {
  const int H = cam.height, W = cam.width;
  cv::Mat noise = smoothField(H, W, W / 16, draws.rng, draws.g) * m.disparity_noise_correlated;
  if (m.disparity_distortion > 0) {
    std::mt19937 unit(20121);  // one sensor unit: the same pattern in every frame and sequence
    noise += smoothField(H, W, 6, unit, draws.g) * m.disparity_distortion;
  }
  noise += windowedWhiteNoise(H, W, m.correlation_window, draws) * m.disparity_noise;
  return noise;
}

/** The depth each pixel's block matching settles on, and where it is a fattened edge. */
struct MatchedDepth {
  cv::Mat z;         // CV_32FC1 [m]
  cv::Mat fattened;  // CV_8UC1, 1 = took a nearer neighbour's depth
};

/** A nearer surface within `edge_fattening` px wins (its disparity is the largest in the
 * window). `fb`: focal length times baseline [px m]. */
MatchedDepth blockMatchedDepth(const cv::Mat& ideal_depth, double fb, int edge_fattening) {
  const int H = ideal_depth.rows, W = ideal_depth.cols;
  MatchedDepth md{ideal_depth.clone(), cv::Mat::zeros(H, W, CV_8UC1)};
  if (edge_fattening <= 0) return md;
  cv::Mat disp(H, W, CV_32FC1), near;
  for (int v = 0; v < H; ++v)
    for (int u = 0; u < W; ++u) {
      const float zi = ideal_depth.at<float>(v, u);
      disp.at<float>(v, u) = zi > 0 ? static_cast<float>(fb / zi) : 0.f;
    }
  const int k = 2 * edge_fattening + 1;
  cv::dilate(disp, near, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(k, k)));
  for (int v = 0; v < H; ++v)
    for (int u = 0; u < W; ++u)
      if (near.at<float>(v, u) > 1.04f * disp.at<float>(v, u)) {
        md.z.at<float>(v, u) = static_cast<float>(fb / near.at<float>(v, u));
        md.fattened.at<uint8_t>(v, u) = 1;
      }
  return md;
}

/** [m] nearest and farthest valid depth in the 3 x 5 neighbourhood of (v, u), and zp. */
std::pair<double, double> neighbourDepthRange(const cv::Mat& z, int v, int u, double zp) {
  double zmin = zp, zmax = zp;
  for (int dv = -1; dv <= 1; ++dv)
    for (int du = -2; du <= 2; ++du) {
      const int vv = std::clamp(v + dv, 0, z.rows - 1), uu = std::clamp(u + du, 0, z.cols - 1);
      const double zn = z.at<float>(vv, uu);
      if (zn > 0) zmin = std::min(zmin, zn), zmax = std::max(zmax, zn);
    }
  return {zmin, zmax};
}

/** Depth zp [m] through noisy disparity quantised to disparity_step: the raw 16-bit value, 0 when
 * out of range. */
uint16_t quantisedDepth(double zp, double noise, double fb, const KinectModel& m,
                        double depth_factor) {
  double d = fb / zp + noise;
  if (m.disparity_step > 0) d = std::round(d / m.disparity_step) * m.disparity_step;
  if (d <= 0) return 0;
  const double zq = fb / d;
  if (zq < m.min_depth || zq > m.max_depth) return 0;
  return static_cast<uint16_t>(std::min(65535.0, std::round(zq * depth_factor)));
}

/** The raw depth image: range and incidence limits, missing or mixed ("flying") depth at
 * discontinuities (the projector's shadow), then disparity noise and quantisation. */
cv::Mat sensedDepth(const IdealFrame& ideal, const MatchedDepth& md, const cv::Mat& noise,
                    double fb, const KinectModel& m, double depth_factor, Draws& draws) {
  cv::Mat depth_raw(md.z.rows, md.z.cols, CV_16UC1);
  for (int v = 0; v < md.z.rows; ++v)
    for (int u = 0; u < md.z.cols; ++u) {
      double zp = md.z.at<float>(v, u);
      auto& out = depth_raw.at<uint16_t>(v, u);
      out = 0;
      if (!(zp >= m.min_depth && zp <= m.max_depth)) continue;
      if (!md.fattened.at<uint8_t>(v, u) && ideal.incidence.at<float>(v, u) < m.min_incidence)
        continue;
      const auto [zmin, zmax] = neighbourDepthRange(md.z, v, u, zp);
      if (zmax - zmin > 0.04 * zp) {
        const double p = draws.u01(draws.rng);
        if (p < m.edge_dropout) continue;
        if (p < m.edge_dropout + m.flying_pixels) zp = zmin + draws.u01(draws.rng) * (zmax - zmin);
      }
      out = quantisedDepth(zp, noise.at<float>(v, u), fb, m, depth_factor);
    }
  return depth_raw;
}

/** The linear colour blurred along the image motion of a point 2 m ahead during the exposure. */
cv::Mat motionBlurred(const cv::Mat& colour_in, const PinholeCamera& cam,
                      const mrpt::poses::CPose3D& pose, const mrpt::poses::CPose3D& previous_pose) {
  cv::Mat colour = colour_in.clone();
  const mrpt::math::TPoint3D centre_cam(0, 0, 2.0);
  const auto world = pose.composePoint(centre_cam);
  const auto before = previous_pose.inverseComposePoint(world);
  const double du = cam.fx * before.x / before.z - cam.fx * centre_cam.x / centre_cam.z;
  const double dv = cam.fy * before.y / before.z - cam.fy * centre_cam.y / centre_cam.z;
  const double len = std::hypot(du, dv);
  if (len <= 1.0) return colour;
  const int k = std::min(41, 2 * static_cast<int>(std::ceil(len / 2)) + 1);
  cv::Mat kernel = cv::Mat::zeros(k, k, CV_32F);
  cv::line(kernel, cv::Point(k / 2 - int(du / 2), k / 2 - int(dv / 2)),
           cv::Point(k / 2 + int(du / 2), k / 2 + int(dv / 2)), cv::Scalar(1.0), 1, cv::LINE_AA);
  kernel /= cv::sum(kernel)[0];
  cv::filter2D(colour, colour, -1, kernel, cv::Point(-1, -1), 0, cv::BORDER_REFLECT);
  return colour;
}

/** 8-bit BGR: gain, gamma 1/2.2, colour noise [grey levels]. */
cv::Mat exposed(const cv::Mat& colour, double gain, double colour_noise, Draws& draws) {
  cv::Mat bgr(colour.rows, colour.cols, CV_8UC3);
  for (int v = 0; v < colour.rows; ++v)
    for (int u = 0; u < colour.cols; ++u) {
      const auto c = colour.at<cv::Vec3f>(v, u);
      auto& o = bgr.at<cv::Vec3b>(v, u);
      for (int ch = 0; ch < 3; ++ch) {
        const double x = 255.0 * std::pow(std::max(0.0, gain * c[ch]), 1 / 2.2) +
                         colour_noise * draws.g(draws.rng);
        o[ch] = static_cast<uint8_t>(std::clamp(std::round(x), 0.0, 255.0));
      }
    }
  return bgr;
}

}  // namespace

IdealFrame renderIdeal(const Scene& scene, const mrpt::poses::CPose3D& pose,
                       const PinholeCamera& cam,
                       const std::optional<mrpt::poses::CPose3D>& last_row_pose) {
  const auto qs = prepareQuads(scene);
  IdealFrame f;
  f.colour.create(cam.height, cam.width, CV_32FC3);
  f.depth.create(cam.height, cam.width, CV_32FC1);
  f.incidence.create(cam.height, cam.width, CV_32FC1);
  for (int v = 0; v < cam.height; ++v) {
    const RowView row = rowView(pose, last_row_pose, v, cam);
    for (int u = 0; u < cam.width; ++u) {
      // Ray with unit z in the camera: the hit's parameter t is its depth.
      const Eigen::Vector3d d =
          row.R * Eigen::Vector3d((u - cam.cx) / cam.fx, (v - cam.cy) / cam.fy, 1);
      Hit hit;
      hitQuads(qs, row.c, d, hit);
      hitEllipsoids(scene.ellipsoids, row.c, d, hit);
      std::optional<Surface> surface;
      if (hit.ellipsoid >= 0)
        surface = ellipsoidSurface(scene.ellipsoids[hit.ellipsoid], row.c, d, hit.t);
      else if (hit.quad >= 0)
        surface = quadSurface(qs[hit.quad], hit.a, hit.b);
      shadePixel(f, v, u, hit, surface, d);
    }
  }
  return f;
}

SensorFrame applyKinectModel(const IdealFrame& ideal, const PinholeCamera& cam,
                             const SensorInputs& in, const KinectModel& m, std::mt19937& rng) {
  // Draw order: disparity noise, edge dropout and flying pixels, colour noise.
  Draws draws{rng};
  const double fb = cam.fx * m.baseline;  // disparity [px] = fb / depth [m]
  const cv::Mat noise = disparityNoise(cam, m, draws);
  const MatchedDepth md = blockMatchedDepth(ideal.depth, fb, m.edge_fattening);
  SensorFrame out;
  out.depth = sensedDepth(ideal, md, noise, fb, m, in.depth_factor, draws);
  const cv::Mat colour = motionBlurred(ideal.colour, cam, in.pose, in.previous_pose);
  out.bgr = exposed(colour, in.gain, m.colour_noise, draws);
  return out;
}

}  // namespace hrgbd::sim
