#include "rgbd_eval/EvalPlot.h"

#include <mrpt/img/CImage.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>
#include <vector>

#include "rgbd_core/OutputFile.h"

namespace hrgbd {
namespace {

using mrpt::img::TColor;

struct Box {
  int x0, y0, w, h;
};

// Maps data coordinates into a panel, keeping the aspect ratio when `equal_axes`.
struct Mapper {
  double minx, maxx, miny, maxy;
  Box b;
  int px(double x) const { return b.x0 + int((x - minx) / (maxx - minx) * b.w); }
  int py(double y) const { return b.y0 + b.h - int((y - miny) / (maxy - miny) * b.h); }
};

Mapper makeMapper(double minx, double maxx, double miny, double maxy, Box b, bool equal_axes) {
  const double pad_x = std::max(1e-6, 0.05 * (maxx - minx)),
               pad_y = std::max(1e-6, 0.05 * (maxy - miny));
  minx -= pad_x, maxx += pad_x, miny -= pad_y, maxy += pad_y;
  if (equal_axes) {
    const double sx = (maxx - minx) / b.w, sy = (maxy - miny) / b.h, s = std::max(sx, sy);
    const double cx = 0.5 * (minx + maxx), cy = 0.5 * (miny + maxy);
    minx = cx - 0.5 * s * b.w, maxx = cx + 0.5 * s * b.w;
    miny = cy - 0.5 * s * b.h, maxy = cy + 0.5 * s * b.h;
  }
  return {minx, maxx, miny, maxy, b};
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), f, v);
  return buf;
}

}  // namespace

void plotEvaluation(const EvalResult& r, const std::string& png_path, const std::string& title) {
  mrpt::img::CImage img(1200, 560, mrpt::img::CH_RGB);
  img.filledRectangle(0, 0, 1199, 559, TColor(255, 255, 255));
  const TColor black(0, 0, 0), grey(170, 170, 170), blue(30, 60, 200), red(210, 40, 40);

  // Top view: the two axes with the largest ground-truth extent.
  std::array<double, 3> lo{1e18, 1e18, 1e18}, hi{-1e18, -1e18, -1e18};
  for (const auto& p : r.ground_truth)
    for (int k = 0; k < 3; ++k)
      lo[k] = std::min(lo[k], p.pose[k]), hi[k] = std::max(hi[k], p.pose[k]);
  std::array<int, 3> ax{0, 1, 2};
  std::sort(ax.begin(), ax.end(), [&](int a, int b) { return hi[a] - lo[a] > hi[b] - lo[b]; });
  const int a0 = std::min(ax[0], ax[1]), a1 = std::max(ax[0], ax[1]);
  double mx = 1e18, Mx = -1e18, my = 1e18, My = -1e18;
  for (const auto* traj : {&r.ground_truth, &r.estimate_aligned})
    for (const auto& p : *traj)
      mx = std::min(mx, p.pose[a0]), Mx = std::max(Mx, p.pose[a0]), my = std::min(my, p.pose[a1]),
      My = std::max(My, p.pose[a1]);
  const Mapper m = makeMapper(mx, Mx, my, My, {40, 50, 540, 470}, true);
  img.rectangle(m.b.x0, m.b.y0, m.b.x0 + m.b.w, m.b.y0 + m.b.h, black);
  for (std::size_t i = 0; i < r.ground_truth.size(); ++i) {
    const auto& g = r.ground_truth[i].pose;
    const auto& e = r.estimate_aligned[i].pose;
    img.line(m.px(g[a0]), m.py(g[a1]), m.px(e[a0]), m.py(e[a1]), grey);
    if (i == 0) continue;
    const auto& g0 = r.ground_truth[i - 1].pose;
    const auto& e0 = r.estimate_aligned[i - 1].pose;
    img.line(m.px(g0[a0]), m.py(g0[a1]), m.px(g[a0]), m.py(g[a1]), blue, 2);
    img.line(m.px(e0[a0]), m.py(e0[a1]), m.px(e[a0]), m.py(e[a1]), red, 2);
  }
  const char* names = "xyz";
  img.textOut(40, 8, title.empty() ? "trajectory (aligned), seen from above" : title, black);
  img.textOut(40, 26,
              std::string("axes ") + names[a0] + "-" + names[a1] + ", scale " +
                  fmt("%.3f m", (m.maxx - m.minx)) + " across",
              black);
  img.textOut(60, 60, "ground truth", blue);
  img.textOut(60, 76, "estimate (Horn-aligned)", red);
  img.textOut(60, 92, "error", grey);

  // Error over time.
  double emax = 1e-6;
  for (double e : r.error_aligned) emax = std::max(emax, e);
  const Mapper te =
      makeMapper(0, std::max(1e-3, r.t.back() - r.t.front()), 0, emax, {640, 50, 530, 470}, false);
  img.rectangle(te.b.x0, te.b.y0, te.b.x0 + te.b.w, te.b.y0 + te.b.h, black);
  for (std::size_t i = 1; i < r.t.size(); ++i)
    img.line(te.px(r.t[i - 1] - r.t[0]), te.py(r.error_aligned[i - 1]), te.px(r.t[i] - r.t[0]),
             te.py(r.error_aligned[i]), red, 2);
  img.textOut(640, 8, "aligned position error [m] over time [s]", black);
  img.textOut(640, 26,
              "ATE RMSE " + fmt("%.4f m", r.ate_rmse) + "   unaligned mean " +
                  fmt("%.4f m", r.ate_mean_unaligned) + "   max " + fmt("%.4f m", emax),
              black);
  img.textOut(645, te.b.y0 + 4, fmt("%.3f", te.maxy), black);
  img.textOut(645, te.b.y0 + te.b.h - 14, "0", black);
  img.textOut(te.b.x0 + te.b.w - 50, te.b.y0 + te.b.h + 6, fmt("%.1f s", te.maxx), black);
  // Encoded here and written as an OutputFile: CImage::saveToFile (cv::imwrite) does not report
  // a full disk.
  std::vector<uchar> png;
  if (!cv::imencode(".png", img.asCvMatRef(), png))
    throw std::runtime_error("cannot encode plot '" + png_path + "'");
  writeOutputFile(png_path, "plot", png.data(), png.size());
}

}  // namespace hrgbd
