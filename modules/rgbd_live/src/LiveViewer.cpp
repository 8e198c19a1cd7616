#include "rgbd_live/LiveViewer.h"

#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/stock_objects.h>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "rgbd_core/RgbdImage.h"

namespace hrgbd {

namespace {
mrpt::opengl::TFontParams font(const mrpt::img::TColorf& colour) {
  mrpt::opengl::TFontParams f;
  f.color = colour;
  f.vfont_scale = 14;
  f.draw_shadow = true;
  return f;
}
}  // namespace

LiveViewer::LiveViewer(const std::string& title) {
  if (const char* d = std::getenv("DISPLAY"); !d || !*d)
    throw std::runtime_error("no X display: set DISPLAY, or run under xvfb-run");
  m_win = mrpt::gui::CDisplayWindow3D::Create(title, 1024, 720);
  m_win->setCameraElevationDeg(35);
  m_win->setCameraAzimuthDeg(-150);
  m_win->setCameraZoom(4);
  m_cloud = mrpt::opengl::CPointCloudColoured::Create();
  m_cloud->setPointSize(3);
  m_path = mrpt::opengl::CSetOfLines::Create();
  m_path->setColor_u8(255, 200, 0);
  m_path->setLineWidth(2);
  m_frustum = mrpt::opengl::CFrustum::Create(0.02f, 0.25f, 62.f, 48.f, 2.f, true, false);
  m_frustum->setColor_u8(255, 60, 60);
  {
    auto& scene = m_win->get3DSceneAndLock();
    scene->insert(mrpt::opengl::stock_objects::CornerXYZSimple(0.2f, 2.f));
    scene->insert(m_cloud);
    scene->insert(m_path);
    scene->insert(m_frustum);
    auto image = scene->createViewport("image");
    image->setViewportPosition(0, 0, 0.32, 0.32);
    m_win->unlockAccess3DScene();
  }
  m_win->addTextMessage(10, -20, "[p] pause  [r] reset  [s] save  [q] quit", 0,
                        font({0.8f, 0.8f, 0.8f}));
  m_win->repaint();
}

int LiveViewer::key() {
  if (!m_win->keyHit()) return 0;
  return std::tolower(m_win->getPushedKey());
}

void LiveViewer::clear() {
  auto& scene = m_win->get3DSceneAndLock();
  (void)scene;
  m_cloud->clear();
  m_path->clear();
  if (m_loops) m_loops->clear();
  m_shown = 0;
  m_loop_count = 0;
  m_win->unlockAccess3DScene();
  m_win->repaint();
}

void LiveViewer::status(const std::string& text) {
  m_win->addTextMessage(10, -60, text, 3, font({1.f, 1.f, 0.3f}));
  m_win->repaint();
}

void LiveViewer::showNewPoints(const ColouredMap& map) {
  const auto& pts = map.points();
  for (; m_shown < pts.size(); ++m_shown) {
    float x, y, z, cr, cg, cb;
    pts.getPointRGB(m_shown, x, y, z, cr, cg, cb);
    m_cloud->push_back(x, y, z, cr, cg, cb);
  }
}

void LiveViewer::snap(const ColouredMap& map, const std::vector<mrpt::poses::CPose3D>& path,
                      const std::vector<std::pair<std::size_t, std::size_t>>& loops) {
  auto& scene = m_win->get3DSceneAndLock();
  m_cloud->clear();
  m_shown = 0;
  showNewPoints(map);
  m_path->clear();
  for (std::size_t i = 1; i < path.size(); ++i)
    m_path->appendLine(path[i - 1].x(), path[i - 1].y(), path[i - 1].z(), path[i].x(), path[i].y(),
                       path[i].z());
  if (!m_loops) {
    m_loops = mrpt::opengl::CSetOfLines::Create();
    m_loops->setColor(1, 0, 0);
    m_loops->setLineWidth(2);
    scene->insert(m_loops);
  }
  m_loops->clear();
  for (const auto& [a, b] : loops)
    if (a < path.size() && b < path.size())
      m_loops->appendLine(path[a].x(), path[a].y(), path[a].z(), path[b].x(), path[b].y(),
                          path[b].z());
  m_loop_count = loops.size();
  m_win->unlockAccess3DScene();
  m_win->repaint();
}

void LiveViewer::update(const mrpt::obs::CObservation3DRangeScan& obs, const FrameResult& r,
                        const ColouredMap& map, const std::vector<mrpt::poses::CPose3D>& path,
                        double fps) {
  // The colour image with the inlier features: green photometric, magenta geometric.
  cv::Mat img = obs.intensityImage.asCvMat<cv::Mat>(mrpt::img::DEEP_COPY);
  if (img.channels() == 1) cv::cvtColor(img, img, cv::COLOR_GRAY2BGR);
  if (obs.hasIntensityImage) {
    const auto& cam = obs.cameraParamsIntensity;
    const cv::Scalar colour = r.path.sparse == FramePath::Sparse::Geometric
                                  ? cv::Scalar(255, 0, 255)
                                  : cv::Scalar(0, 255, 0);
    for (const auto& p : r.inlier_points)
      if (p.z() > 0)
        cv::circle(img,
                   {static_cast<int>(cam.fx() * p.x() / p.z() + cam.cx()),
                    static_cast<int>(cam.fy() * p.y() / p.z() + cam.cy())},
                   4, colour, 1, cv::LINE_AA);
  }
  auto& scene = m_win->get3DSceneAndLock();
  scene->getViewport("image")->setImageView(mrpt::img::CImage(img, mrpt::img::DEEP_COPY));
  const auto& pts = map.points();
  if (pts.size() < m_shown) m_cloud->clear(), m_shown = 0;
  showNewPoints(map);
  if (path.size() >= 2) {
    const auto &a = path[path.size() - 2], &b = path.back();
    m_path->appendLine(a.x(), a.y(), a.z(), b.x(), b.y(), b.z());
  }
  if (!path.empty()) {
    // Follow the camera from behind and above, looking at what it sees 1.5 m ahead.
    const auto& c = path.back();
    m_frustum->setPose(c);
    const auto ahead = c.composePoint(mrpt::math::TPoint3D(1.5, 0, 0));
    m_win->setCameraPointingToPoint(ahead.x, ahead.y, ahead.z);
    m_win->setCameraAzimuthDeg(mrpt::RAD2DEG(c.yaw()) + 180);
  }
  m_win->unlockAccess3DScene();

  char line[256];
  std::snprintf(
      line, sizeof line, "frame %zu%s  path %s  %s  inliers %zu/%zu  %.1f fps  map %zu pts",
      path.size(), m_loop_count ? ("  loops " + std::to_string(m_loop_count)).c_str() : "",
      toString(r.path).c_str(), toString(r.status), r.inliers, r.matches, fps, pts.size());
  m_win->addTextMessage(10, -40, line, 1,
                        font(r.registered() ? mrpt::img::TColorf(0.3f, 1.f, 0.3f)
                                            : mrpt::img::TColorf(1.f, 0.3f, 0.3f)));
  m_win->repaint();
}

}  // namespace hrgbd
