#include "rgbd_sim/Render.h"

#include <mrpt/math/slerp.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "Texture.h"

namespace hrgbd::sim {
namespace {

struct QuadData {
  Eigen::Vector3d o, n, ud, vd, colour;  // ud, vd: unit edge directions
  double ul, vl, scale;
  int texture;
};

}  // namespace

IdealFrame renderIdeal(const Scene& scene, const mrpt::poses::CPose3D& pose,
                       const PinholeCamera& cam,
                       const std::optional<mrpt::poses::CPose3D>& last_row_pose) {
  std::vector<QuadData> qs;
  for (const auto& q : scene.quads)
    qs.push_back({q.origin, q.u.cross(q.v).normalized(), q.u.normalized(), q.v.normalized(),
                  q.colour, q.u.norm(), q.v.norm(), q.texture_scale, q.texture});
  const Eigen::Vector3d light = Eigen::Vector3d(0.3, -0.5, 1.0).normalized();

  IdealFrame f;
  f.colour.create(cam.height, cam.width, CV_32FC3);
  f.depth.create(cam.height, cam.width, CV_32FC1);
  f.incidence.create(cam.height, cam.width, CV_32FC1);
  for (int v = 0; v < cam.height; ++v) {
    mrpt::math::TPose3D row = pose.asTPose();
    if (last_row_pose)
      mrpt::math::slerp(pose.asTPose(), last_row_pose->asTPose(), v / (cam.height - 1.0), row);
    const mrpt::poses::CPose3D row_pose(row);
    const Eigen::Matrix3d R = row_pose.getRotationMatrix().asEigen();
    const Eigen::Vector3d c(row.x, row.y, row.z);
    for (int u = 0; u < cam.width; ++u) {
      // Ray with unit z in the camera: the hit's parameter t is its depth.
      const Eigen::Vector3d d =
          R * Eigen::Vector3d((u - cam.cx) / cam.fx, (v - cam.cy) / cam.fy, 1);
      double best = 1e9;
      int hit = -1;
      double ha = 0, hb = 0;
      for (std::size_t k = 0; k < qs.size(); ++k) {
        const auto& q = qs[k];
        const double den = q.n.dot(d);
        if (std::abs(den) < 1e-9) continue;
        const double t = q.n.dot(q.o - c) / den;
        if (t <= 0.05 || t >= best) continue;
        const Eigen::Vector3d p = c + t * d - q.o;
        const double a = p.dot(q.ud), b = p.dot(q.vd);
        if (a < 0 || b < 0 || a > q.ul || b > q.vl) continue;
        best = t, hit = static_cast<int>(k), ha = a, hb = b;
      }
      int blob = -1;
      for (std::size_t k = 0; k < scene.ellipsoids.size(); ++k) {
        // The ray in the ellipsoid's unit-sphere coordinates: |o + t d|^2 = 1.
        const auto& e = scene.ellipsoids[k];
        const Eigen::Vector3d o = (c - e.centre).cwiseQuotient(e.radii);
        const Eigen::Vector3d de = d.cwiseQuotient(e.radii);
        const double a = de.squaredNorm(), bh = o.dot(de),
                     disc = bh * bh - a * (o.squaredNorm() - 1);
        if (disc < 0) continue;
        const double t = (-bh - std::sqrt(disc)) / a;
        if (t <= 0.05 || t >= best) continue;
        best = t, blob = static_cast<int>(k), hit = -1;
      }
      auto& col = f.colour.at<cv::Vec3f>(v, u);
      if (hit < 0 && blob < 0) {
        col = cv::Vec3f(0.05f, 0.05f, 0.06f);
        f.depth.at<float>(v, u) = 0;
        f.incidence.at<float>(v, u) = 0;
        continue;
      }
      // The surface's normal, albedo and Lambertian term (planes are lit from both sides).
      Eigen::Vector3d normal, albedo;
      double lambert = 0;
      if (blob >= 0) {
        const auto& e = scene.ellipsoids[blob];
        const Eigen::Vector3d p = c + best * d - e.centre;
        normal = p.cwiseQuotient(e.radii.cwiseProduct(e.radii)).normalized();
        // Texture coordinates [m]: around the vertical axis and up it.
        const double around = std::atan2(p.y(), p.x()) * 0.5 * (e.radii.x() + e.radii.y());
        albedo = e.colour;
        if (e.texture >= 0)
          albedo = albedo.cwiseProduct(textureColour(e.texture, around, p.z(), e.texture_scale));
        lambert = std::max(0.0, normal.dot(light));
      } else {
        const auto& q = qs[hit];
        normal = q.n;
        albedo = q.colour;
        if (q.texture >= 0) albedo = albedo.cwiseProduct(textureColour(q.texture, ha, hb, q.scale));
        lambert = std::abs(normal.dot(light));
      }
      const Eigen::Vector3d rgb = albedo * (0.35 + 0.65 * lambert);
      col = cv::Vec3f(static_cast<float>(rgb.z()), static_cast<float>(rgb.y()),
                      static_cast<float>(rgb.x()));  // stored BGR, as OpenCV
      f.depth.at<float>(v, u) = static_cast<float>(best);
      f.incidence.at<float>(v, u) = static_cast<float>(std::abs(normal.dot(d.normalized())));
    }
  }
  return f;
}

void applyKinectModel(const IdealFrame& ideal, const Scene& /*scene*/, const PinholeCamera& cam,
                      const mrpt::poses::CPose3D& pose, const mrpt::poses::CPose3D& previous_pose,
                      double gain, const KinectModel& m, double depth_factor, std::mt19937& rng,
                      cv::Mat& bgr, cv::Mat& depth_raw) {
  std::normal_distribution<double> g(0, 1);
  std::uniform_real_distribution<double> u01(0, 1);
  const int H = cam.height, W = cam.width;

  // Depth: disparity with smooth + per-pixel noise, quantised to 1/8 px (steps grow as z^2).
  const double fb = cam.fx * m.baseline;
  auto smoothField = [&](std::mt19937& r, int cells) {  // unit-std noise, blobs of ~W/cells px
    cv::Mat low(H * cells / W + 2, cells + 2, CV_32FC1), field;
    for (int i = 0; i < low.rows; ++i)
      for (int j = 0; j < low.cols; ++j) low.at<float>(i, j) = static_cast<float>(g(r));
    cv::resize(low, field, cv::Size(W, H), 0, 0, cv::INTER_CUBIC);
    cv::Scalar mean, sd;
    cv::meanStdDev(field, mean, sd);
    return cv::Mat((field - mean[0]) / std::max(1e-6, sd[0]));
  };
  cv::Mat noise = smoothField(rng, W / 16) * m.disparity_noise_correlated;
  if (m.disparity_distortion > 0) {
    std::mt19937 unit(20121);  // one sensor unit: the same pattern in every frame and sequence
    noise += smoothField(unit, 6) * m.disparity_distortion;
  }
  cv::Mat white(H, W, CV_32FC1);
  for (int v = 0; v < H; ++v)
    for (int u = 0; u < W; ++u) white.at<float>(v, u) = static_cast<float>(g(rng));
  if (m.correlation_window > 1) {  // mean over the window, rescaled to keep the per-pixel std
    cv::blur(white, white, cv::Size(m.correlation_window, m.correlation_window), cv::Point(-1, -1),
             cv::BORDER_REFLECT);
    white *= m.correlation_window;
  }
  noise += white * m.disparity_noise;

  // The surface each pixel's block matching settles on: a nearer surface within edge_fattening
  // px wins (its disparity is the largest in the window).
  cv::Mat z = ideal.depth.clone();
  cv::Mat fattened = cv::Mat::zeros(H, W, CV_8UC1);
  if (m.edge_fattening > 0) {
    cv::Mat disp(H, W, CV_32FC1), near;
    for (int v = 0; v < H; ++v)
      for (int u = 0; u < W; ++u) {
        const float zi = ideal.depth.at<float>(v, u);
        disp.at<float>(v, u) = zi > 0 ? static_cast<float>(fb / zi) : 0.f;
      }
    const int k = 2 * m.edge_fattening + 1;
    cv::dilate(disp, near, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(k, k)));
    for (int v = 0; v < H; ++v)
      for (int u = 0; u < W; ++u)
        if (near.at<float>(v, u) > 1.04f * disp.at<float>(v, u)) {
          z.at<float>(v, u) = static_cast<float>(fb / near.at<float>(v, u));
          fattened.at<uint8_t>(v, u) = 1;
        }
  }

  depth_raw.create(H, W, CV_16UC1);
  for (int v = 0; v < H; ++v)
    for (int u = 0; u < W; ++u) {
      double zp = z.at<float>(v, u);
      auto& out = depth_raw.at<uint16_t>(v, u);
      out = 0;
      if (!(zp >= m.min_depth && zp <= m.max_depth)) continue;
      if (!fattened.at<uint8_t>(v, u) && ideal.incidence.at<float>(v, u) < m.min_incidence)
        continue;
      // Discontinuities: missing depth (shadow of the projector) or mixed "flying" depth.
      double zmin = zp, zmax = zp;
      for (int dv = -1; dv <= 1; ++dv)
        for (int du = -2; du <= 2; ++du) {
          const int vv = std::clamp(v + dv, 0, H - 1), uu = std::clamp(u + du, 0, W - 1);
          const double zn = z.at<float>(vv, uu);
          if (zn > 0) zmin = std::min(zmin, zn), zmax = std::max(zmax, zn);
        }
      if (zmax - zmin > 0.04 * zp) {
        const double p = u01(rng);
        if (p < m.edge_dropout) continue;
        if (p < m.edge_dropout + m.flying_pixels) zp = zmin + u01(rng) * (zmax - zmin);
      }
      double d = fb / zp + noise.at<float>(v, u);
      if (m.disparity_step > 0) d = std::round(d / m.disparity_step) * m.disparity_step;
      if (d <= 0) continue;
      const double zq = fb / d;
      if (zq < m.min_depth || zq > m.max_depth) continue;
      out = static_cast<uint16_t>(std::min(65535.0, std::round(zq * depth_factor)));
    }

  // Colour: motion blur along the image motion during the exposure, gain, noise, 8 bits.
  cv::Mat colour = ideal.colour.clone();
  const mrpt::math::TPoint3D centre_cam(0, 0, 2.0);
  const auto world = pose.composePoint(centre_cam);
  const auto before = previous_pose.inverseComposePoint(world);
  const double du = cam.fx * before.x / before.z - cam.fx * centre_cam.x / centre_cam.z;
  const double dv = cam.fy * before.y / before.z - cam.fy * centre_cam.y / centre_cam.z;
  const double len = std::hypot(du, dv);
  if (len > 1.0) {
    const int k = std::min(41, 2 * static_cast<int>(std::ceil(len / 2)) + 1);
    cv::Mat kernel = cv::Mat::zeros(k, k, CV_32F);
    cv::line(kernel, cv::Point(k / 2 - int(du / 2), k / 2 - int(dv / 2)),
             cv::Point(k / 2 + int(du / 2), k / 2 + int(dv / 2)), cv::Scalar(1.0), 1, cv::LINE_AA);
    kernel /= cv::sum(kernel)[0];
    cv::filter2D(colour, colour, -1, kernel, cv::Point(-1, -1), 0, cv::BORDER_REFLECT);
  }
  bgr.create(H, W, CV_8UC3);
  for (int v = 0; v < H; ++v)
    for (int u = 0; u < W; ++u) {
      const auto c = colour.at<cv::Vec3f>(v, u);
      auto& o = bgr.at<cv::Vec3b>(v, u);
      for (int ch = 0; ch < 3; ++ch) {
        const double x =
            255.0 * std::pow(std::max(0.0, gain * c[ch]), 1 / 2.2) + m.colour_noise * g(rng);
        o[ch] = static_cast<uint8_t>(std::clamp(std::round(x), 0.0, 255.0));
      }
    }
}

}  // namespace hrgbd::sim
