#include "rgbd_map/ColouredMap.h"

#include <mrpt/opengl/CFrustum.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/stock_objects.h>

#include <cmath>
#include <stdexcept>

#include "rgbd_core/Config.h"
#include "rgbd_core/GzOutput.h"
#include "rgbd_core/OutputFile.h"
#include "rgbd_core/RgbdImage.h"
#include "rgbd_core/Trajectory.h"

namespace hrgbd {

void MapParams::checkTogether(const std::string& s) const {
  requireValid(max_depth > min_depth, s, "max_depth", max_depth, "must be > min_depth");
}

ColouredMap::ColouredMap(const MapParams& params) : m_params(params) {}

void ColouredMap::clear() {
  m_voxels = {};
  m_points.clear();
  m_frozen = false;
}

void ColouredMap::freeze() {
  m_voxels = {};  // a new empty set: clear() would keep the buckets
  m_frozen = true;
}

std::size_t ColouredMap::insert(const mrpt::obs::CObservation3DRangeScan& obs,
                                const mrpt::poses::CPose3D& optical_pose) {
  const RgbdImage img = prepareRgbdImage(obs);  // depth registered to the colour image
  const cv::Mat& colour = obs.intensityImage.asCvMatRef();
  const bool bgr = colour.channels() == 3;
  // The point in the MRPT camera frame is M^-1 (+) p_optical, M = mrptFrameInOptical().
  const auto world = opticalToMrptWorld(optical_pose) + (-mrptFrameInOptical());
  std::size_t added = 0;
  for (int v = 0; v < img.depth.rows; v += m_params.pixel_stride) {
    const float* z = img.depth.ptr<float>(v);
    for (int u = 0; u < img.depth.cols; u += m_params.pixel_stride) {
      if (!(z[u] >= m_params.min_depth && z[u] <= m_params.max_depth)) continue;
      const auto p = img.cam.backProject(u, v, z[u]);
      double x, y, zz;
      world.composePoint(p.x(), p.y(), p.z(), x, y, zz);
      float r, g, b;
      if (bgr) {
        const auto& px = colour.at<cv::Vec3b>(v, u);
        b = px[0] / 255.f, g = px[1] / 255.f, r = px[2] / 255.f;
      } else {
        r = g = b = colour.at<std::uint8_t>(v, u) / 255.f;
      }
      added += addPoint(x, y, zz, r, g, b);
    }
  }
  return added;
}

bool ColouredMap::addPoint(double x, double y, double z, float r, float g, float b) {
  if (m_frozen) throw std::logic_error("ColouredMap: inserted into after freeze()");
  const double inv = 1.0 / m_params.voxel_size;
  // 21 bits per axis: +-10 km at 1 cm voxels.
  auto cell = [inv](double c) {
    return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(c * inv)) + (1 << 20)) &
           0x1FFFFF;
  };
  if (!m_voxels.insert(cell(x) | cell(y) << 21 | cell(z) << 42).second) return false;
  m_points.insertPointRGB(x, y, z, r, g, b);
  return true;
}

std::size_t ColouredMap::insert(const ColouredMap& local,
                                const mrpt::poses::CPose3D& optical_pose) {
  // local points are in the MRPT world of the identity optical pose, W0; here they go to W:
  // p_W = W (+) W0^-1 (+) p
  const auto move =
      opticalToMrptWorld(optical_pose) + (-opticalToMrptWorld(mrpt::poses::CPose3D()));
  std::size_t added = 0;
  for (std::size_t i = 0; i < local.m_points.size(); ++i) {
    float x, y, z, r, g, b;
    local.m_points.getPointRGB(i, x, y, z, r, g, b);
    double wx, wy, wz;
    move.composePoint(x, y, z, wx, wy, wz);
    added += addPoint(wx, wy, wz, r, g, b);
  }
  return added;
}

// Hand-written: MRPT 2.5's PLY exporter writes a grey "intensity" per point, not its colour.
void ColouredMap::savePly(const std::string& path) const {
  StreamOutput file(path, "PLY", true);
  std::ostream& out = file.stream();
  out << "ply\nformat binary_little_endian 1.0\ncomment hybrid-rgbd-odometry coloured map, "
         "MRPT world frame (z up) [m]\nelement vertex "
      << m_points.size()
      << "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\n"
         "property uchar green\nproperty uchar blue\nend_header\n";
  for (std::size_t i = 0; i < m_points.size(); ++i) {
    float xyz[3], r, g, b;
    m_points.getPointRGB(i, xyz[0], xyz[1], xyz[2], r, g, b);
    const std::uint8_t rgb[3] = {static_cast<std::uint8_t>(r * 255.f + 0.5f),
                                 static_cast<std::uint8_t>(g * 255.f + 0.5f),
                                 static_cast<std::uint8_t>(b * 255.f + 0.5f)};
    out.write(reinterpret_cast<const char*>(xyz), sizeof xyz);  // x86/ARM: little endian
    out.write(reinterpret_cast<const char*>(rgb), sizeof rgb);
  }
  file.commit();
}

mrpt::opengl::CSetOfObjects::Ptr trajectoryObject(const std::vector<mrpt::poses::CPose3D>& poses,
                                                  std::size_t frustums) {
  auto obj = mrpt::opengl::CSetOfObjects::Create();
  auto path = mrpt::opengl::CSetOfLines::Create();
  path->setColor_u8(255, 200, 0);
  path->setLineWidth(2);
  for (std::size_t i = 1; i < poses.size(); ++i)
    path->appendLine(poses[i - 1].x(), poses[i - 1].y(), poses[i - 1].z(), poses[i].x(),
                     poses[i].y(), poses[i].z());
  obj->insert(path);
  const std::size_t step =
      std::max<std::size_t>(1, poses.size() / std::max<std::size_t>(1, frustums));
  for (std::size_t i = 0; i < poses.size(); i += step) {
    auto f = mrpt::opengl::CFrustum::Create(0.02f, 0.12f, 62.f, 48.f, 1.f, true, false);
    f->setPose(poses[i]);
    f->setColor_u8(255, 200, 0);
    obj->insert(f);
  }
  return obj;
}

mrpt::opengl::CSetOfObjects::Ptr loopObject(
    const std::vector<mrpt::poses::CPose3D>& poses,
    const std::vector<std::pair<std::size_t, std::size_t>>& loops) {
  auto obj = mrpt::opengl::CSetOfObjects::Create();
  obj->setName("loop closures");
  auto lines = mrpt::opengl::CSetOfLines::Create();
  lines->setColor(1, 0, 0);
  lines->setLineWidth(2);
  for (const auto& [a, b] : loops)
    if (a < poses.size() && b < poses.size())
      lines->appendLine(poses[a].x(), poses[a].y(), poses[a].z(), poses[b].x(), poses[b].y(),
                        poses[b].z());
  obj->insert(lines);
  return obj;
}

void saveScene(const ColouredMap& map, const std::vector<mrpt::poses::CPose3D>& poses,
               const std::string& path,
               const std::vector<std::pair<std::size_t, std::size_t>>& loops) {
  mrpt::opengl::COpenGLScene scene;
  auto cloud = mrpt::opengl::CSetOfObjects::Create();
  map.points().getVisualizationInto(*cloud);
  scene.insert(cloud);
  scene.insert(trajectoryObject(poses));
  if (!loops.empty()) scene.insert(loopObject(poses, loops));
  scene.insert(mrpt::opengl::stock_objects::CornerXYZSimple(0.3f, 2.f));
  saveCompressed(scene, path, ".3Dscene");  // as COpenGLScene::saveToFile(), checked
}

}  // namespace hrgbd
