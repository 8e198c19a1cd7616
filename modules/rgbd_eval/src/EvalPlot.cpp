#include "rgbd_eval/EvalPlot.h"

// Drawn with PLplot rather than gnuplot: PLplot is a library (Debian libplplot-dev), so the apps
// need no external program at run time, and its cairo driver (plplot-driver-cairo) writes PNG,
// SVG and PDF without a display.
#include <plplot.h>
#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <vector>

#include "rgbd_core/Median.h"
#include "rgbd_core/OutputFile.h"

namespace hrgbd {
namespace {
namespace fs = std::filesystem;

enum class Format { None, Png, Svg, Pdf };

/** By the extension; a device or FIFO (/dev/stdout) without one gets PNG. */
Format formatOf(const std::string& path) {
  auto ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".png") return Format::Png;
  if (ext == ".svg") return Format::Svg;
  if (ext == ".pdf") return Format::Pdf;
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (fs::exists(status) && !fs::is_regular_file(status) && !fs::is_directory(status))
    return Format::Png;
  return Format::None;
}

const char* deviceFor(Format f) {
  return f == Format::Png ? "pngcairo" : f == Format::Svg ? "svgcairo" : "pdfcairo";
}

/** PLplot ends the program when asked for a device it lacks: check its list first. */
bool deviceAvailable(const std::string& device) {
  std::array<const char*, 128> menus{}, names{};
  const char** menu_list = menus.data();
  const char** name_list = names.data();
  int n = static_cast<int>(names.size());
  plgDevs(&menu_list, &name_list, &n);
  return std::any_of(names.begin(), names.begin() + n,
                     [&](const char* name) { return name && device == name; });
}

// Colour map 0 entries used here.
enum Colour : PLINT { kBackground = 0, kInk = 1, kGrid = 2, kTruth = 3, kFirstSeries = 4 };
// Tableau 10, matplotlib's and evo's default colour cycle.
constexpr int kPalette[10][3] = {{31, 119, 180},  {255, 127, 14}, {44, 160, 44},   {214, 39, 40},
                                 {148, 103, 189}, {140, 86, 75},  {227, 119, 194}, {127, 127, 127},
                                 {188, 189, 34},  {23, 190, 207}};
constexpr int kPaletteSize = 10;

void setColours() {
  plscmap0n(kFirstSeries + kPaletteSize);
  plscol0(kBackground, 255, 255, 255);
  plscol0(kInk, 0, 0, 0);
  plscol0(kGrid, 222, 222, 222);
  plscol0(kTruth, 70, 70, 70);
  for (int k = 0; k < kPaletteSize; ++k)
    plscol0(kFirstSeries + k, kPalette[k][0], kPalette[k][1], kPalette[k][2]);
}

PLINT seriesColour(std::size_t k) { return kFirstSeries + static_cast<PLINT>(k % kPaletteSize); }
// Past ten estimates the colours repeat with another dash pattern.
PLINT seriesStyle(std::size_t k) { return 1 + static_cast<PLINT>((k / kPaletteSize) % 8); }

/** PLplot reads '#' as the start of an escape sequence. */
std::string plainText(std::string s) {
  for (std::size_t i = 0; (i = s.find('#', i)) != std::string::npos; i += 2) s.insert(i, "#");
  return s;
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), f, v);
  return buf;
}

struct Range {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  void add(double v) { lo = std::min(lo, v), hi = std::max(hi, v); }
};

/** A temporary file PLplot writes to; the figure is then copied into place as an OutputFile. */
class TempFile {
 public:
  TempFile() {
    m_path = (fs::temp_directory_path() / "hrgbd-plot-XXXXXX").string();
    const int fd = mkstemp(m_path.data());
    if (fd < 0) throw std::runtime_error("cannot create a temporary file for the plot");
    close(fd);
  }
  ~TempFile() {
    std::error_code ec;
    fs::remove(m_path, ec);
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  const std::string& path() const { return m_path; }

 private:
  std::string m_path;
};

/** Axes, grid and labels of the current viewport and window; `xlabel` null: the x axis has
 * ticks but no numbers (a panel above another with the same time axis). Fixed-point numbers:
 * no "(x10^-2)" beside the axis. */
void drawFrame(const char* xlabel, const char* ylabel, const std::string& title) {
  plcol0(kGrid);
  plwidth(0.8);
  pllsty(1);
  plbox("g", 0, 0, "g", 0, 0);
  plcol0(kInk);
  plwidth(1.0);
  plbox(xlabel ? "bcnstf" : "bcst", 0, 0, "bcnstvf", 0, 0);
  if (xlabel) plmtex("b", 3.0, 0.5, 0.5, xlabel);
  plmtex("l", 5.4, 0.5, 0.5, ylabel);
  plmtex("t", 0.7, 0.0, 0.0, title.c_str());
}

/** A polyline; with `gap` > 0 it is broken where consecutive x differ by more than `gap`
 * (time series: no line across data that is missing). */
void drawLine(const std::vector<PLFLT>& x, const std::vector<PLFLT>& y, PLINT colour, PLINT style,
              PLFLT width, double gap = 0) {
  plcol0(colour);
  pllsty(style);
  plwidth(width);
  std::size_t begin = 0;
  for (std::size_t i = 1; i <= x.size(); ++i)
    if (i == x.size() || (gap > 0 && x[i] - x[i - 1] > gap)) {
      if (i - begin >= 2) plline(static_cast<PLINT>(i - begin), &x[begin], &y[begin]);
      begin = i;
    }
  pllsty(1);
}

/** [s] A pause in `t` longer than this is a gap in the data: ten typical steps, at least 0.5 s. */
double gapOf(const std::vector<double>& t) {
  std::vector<double> dt;
  for (std::size_t i = 1; i < t.size(); ++i) dt.push_back(t[i] - t[i - 1]);
  if (dt.empty()) return 0;
  return std::max(0.5, 10 * median(dt));
}

/** The axes of `plane`; Auto: the two along which the ground truth spreads most, in order. */
std::array<int, 2> planeAxes(PlotPlane plane, const Trajectory& gt) {
  if (plane == PlotPlane::XY) return {0, 1};
  if (plane == PlotPlane::XZ) return {0, 2};
  if (plane == PlotPlane::YZ) return {1, 2};
  std::array<Range, 3> r;
  for (const auto& p : gt)
    for (int k = 0; k < 3; ++k) r[k].add(p.pose[k]);
  std::array<int, 3> ax{0, 1, 2};
  std::stable_sort(ax.begin(), ax.end(),
                   [&](int a, int b) { return r[a].hi - r[a].lo > r[b].hi - r[b].lo; });
  return {std::min(ax[0], ax[1]), std::max(ax[0], ax[1])};
}

// Figure layout in normalized page coordinates: trajectories left, three time panels right.
constexpr PLFLT kBottom = 0.08, kPanelGap = 0.055, kLegendRow = 0.031;
constexpr PLFLT kLeftX0 = 0.07, kLeftX1 = 0.50, kRightX0 = 0.60, kRightX1 = 0.975;
constexpr PLFLT kTextScale = 0.62;

void drawTrajectories(const std::vector<PlotSeries>& series, const Trajectory& gt,
                      std::array<int, 2> ax, PLFLT top) {
  Range rx, ry;
  for (const auto& p : gt) rx.add(p.pose[ax[0]]), ry.add(p.pose[ax[1]]);
  for (const auto& s : series)
    for (const auto& p : s.result->estimate_aligned) rx.add(p.pose[ax[0]]), ry.add(p.pose[ax[1]]);
  // Equal scale: the window gets the viewport's physical aspect ratio, the data centred in it.
  PLFLT sx0, sx1, sy0, sy1;
  plgspa(&sx0, &sx1, &sy0, &sy1);
  const double w_mm = (kLeftX1 - kLeftX0) * (sx1 - sx0), h_mm = (top - kBottom) * (sy1 - sy0);
  const double dx = std::max(1e-3, rx.hi - rx.lo) * 1.08, dy = std::max(1e-3, ry.hi - ry.lo) * 1.08;
  const double m_per_mm = std::max(dx / w_mm, dy / h_mm);
  const double cx = 0.5 * (rx.lo + rx.hi), cy = 0.5 * (ry.lo + ry.hi);
  plvpor(kLeftX0, kLeftX1, kBottom, top);
  plwind(cx - 0.5 * m_per_mm * w_mm, cx + 0.5 * m_per_mm * w_mm, cy - 0.5 * m_per_mm * h_mm,
         cy + 0.5 * m_per_mm * h_mm);
  const char* names[] = {"x [m]", "y [m]", "z [m]"};
  const std::string plane = std::string(1, "xyz"[ax[0]]) + "-" + "xyz"[ax[1]];
  drawFrame(names[ax[0]], names[ax[1]], "trajectories (" + plane + " plane), estimates aligned");
  auto line = [&](const Trajectory& t, PLINT colour, PLINT style, PLFLT width) {
    std::vector<PLFLT> x, y;
    for (const auto& p : t) x.push_back(p.pose[ax[0]]), y.push_back(p.pose[ax[1]]);
    drawLine(x, y, colour, style, width);
  };
  line(gt, kTruth, 2, 1.6);
  for (std::size_t k = 0; k < series.size(); ++k)
    line(series[k].result->estimate_aligned, seriesColour(k), seriesStyle(k), 1.4);
  // The start, where every trajectory begins.
  PLFLT x0 = gt.front().pose[ax[0]], y0 = gt.front().pose[ax[1]];
  plcol0(kInk);
  plssym(0, 0.8);
  plpoin(1, &x0, &y0, 4);
  PLFLT wx0, wx1, wy0, wy1;
  plgvpw(&wx0, &wx1, &wy0, &wy1);
  const bool right_half = x0 > 0.5 * (wx0 + wx1);  // the label goes toward the middle
  plptex(x0, y0, 1, 0, right_half ? 1.25 : -0.25, "start");
}

/** One time panel: `value(r)` gives (times, values) of a series. */
template <class Values>
void drawTimePanel(const std::vector<PlotSeries>& series, double t0, double t1, PLFLT y0, PLFLT y1,
                   const char* ylabel, const std::string& title, bool time_label, double min_top,
                   Values values) {
  double vmax = min_top;  // rounding noise of a perfect estimate is not magnified
  bool any = false;
  for (const auto& s : series) {
    const auto [t, v] = values(*s.result);
    for (double e : v) vmax = std::max(vmax, e), any = true;
    (void)t;
  }
  plvpor(kRightX0, kRightX1, y0, y1);
  const double span = std::max(1e-3, t1 - t0);
  plwind(-0.01 * span, 1.01 * span, 0, vmax * 1.08);  // end points not cut by the frame
  drawFrame(time_label ? "time [s]" : nullptr, ylabel, title);
  if (!any) {
    plcol0(kInk);
    plmtex("t", -2.0, 0.5, 0.5, "no interval without a gap");
    return;
  }
  for (std::size_t k = 0; k < series.size(); ++k) {
    const auto [t, v] = values(*series[k].result);
    std::vector<PLFLT> x, y;
    for (std::size_t i = 0; i < t.size(); ++i) x.push_back(t[i] - t0), y.push_back(v[i]);
    drawLine(x, y, seriesColour(k), seriesStyle(k), 1.2, gapOf(series[k].result->t));
    if (x.size() <= 60) {  // few values (short sequence): each one visible, even a single one
      plssym(0, 0.6);
      plpoin(static_cast<PLINT>(x.size()), x.data(), y.data(), 17);
    }
  }
}

/** Draws the legend below the title; returns its number of rows. */
PLINT drawLegend(const std::vector<PlotSeries>& series) {
  const std::size_t n = series.size() + 1;
  std::vector<std::string> text{"ground truth"};
  for (const auto& s : series)
    text.push_back(plainText(s.label) + "  (ATE " + fmt("%.4f", s.result->ate_rmse) + " m)");
  std::vector<const char*> ctext;
  for (const auto& t : text) ctext.push_back(t.c_str());
  std::vector<PLINT> opts(n, PL_LEGEND_LINE), text_colours(n, kInk), colours{kTruth}, styles{2};
  std::vector<PLFLT> widths(n, 2.0);
  for (std::size_t k = 0; k < series.size(); ++k)
    colours.push_back(seriesColour(k)), styles.push_back(seriesStyle(k));
  // As many columns (at most 4) as fit across the page at this text size (~150 characters).
  std::size_t longest = 0;
  for (const auto& t : text) longest = std::max(longest, t.size());
  const PLINT columns = static_cast<PLINT>(
      std::clamp<std::size_t>(150 / (longest + 14), 1, std::min<std::size_t>(n, 4)));
  const PLINT rows = static_cast<PLINT>((n + columns - 1) / columns);
  plvpor(kLeftX0, kRightX1, 0.0, 1.0);
  plwind(0, 1, 0, 1);
  PLFLT w, h;
  pllegend(&w, &h, PL_LEGEND_ROW_MAJOR,
           PL_POSITION_VIEWPORT | PL_POSITION_INSIDE | PL_POSITION_TOP | PL_POSITION_LEFT, 0.0,
           0.075, 0.03, kBackground, kInk, 1, rows, columns, static_cast<PLINT>(n), opts.data(),
           1.0, kTextScale, 2.0, 0.0, text_colours.data(), ctext.data(), nullptr, nullptr, nullptr,
           nullptr, colours.data(), styles.data(), widths.data(), nullptr, nullptr, nullptr,
           nullptr);
  return rows;
}

void drawFigure(const std::vector<PlotSeries>& series, const PlotParams& params) {
  const auto* most = series.front().result;
  for (const auto& s : series)
    if (s.result->pairs > most->pairs) most = s.result;
  const auto& gt = most->ground_truth;
  pladv(0);
  plschr(0, kTextScale);
  if (!params.title.empty()) {
    plvpor(0, 1, 0, 1);
    plwind(0, 1, 0, 1);
    plcol0(kInk);
    plschr(0, kTextScale * 1.2);
    plptex(0.5, 0.962, 1, 0, 0.5, plainText(params.title).c_str());
    plschr(0, kTextScale);
  }
  const PLINT rows = drawLegend(series);
  const PLFLT top = 0.88 - kLegendRow * rows;  // the panels start below the legend
  drawTrajectories(series, gt, planeAxes(params.plane, gt), top);
  double t0 = std::numeric_limits<double>::infinity(), t1 = -t0;
  for (const auto& s : series)
    t0 = std::min(t0, s.result->t.front()), t1 = std::max(t1, s.result->t.back());
  const PLFLT h = (top - kBottom - 2 * kPanelGap) / 3;
  drawTimePanel(series, t0, t1, top - h, top, "ATE [m]",
                "absolute trajectory error: position after alignment", false, 1e-3,
                [](const EvalResult& r) { return std::make_pair(r.t, r.error_aligned); });
  drawTimePanel(series, t0, t1, top - 2 * h - kPanelGap, top - h - kPanelGap, "RPE [m/s]",
                "relative pose error over " + fmt("%.2f", most->rpe_delta_used) + " s, translation",
                false, 1e-3,
                [](const EvalResult& r) { return std::make_pair(r.rpe_t, r.rpe_trans_error); });
  drawTimePanel(series, t0, t1, kBottom, kBottom + h, "RPE [°/s]",
                "relative pose error over " + fmt("%.2f", most->rpe_delta_used) + " s, rotation",
                true, 1e-2,
                [](const EvalResult& r) { return std::make_pair(r.rpe_t, r.rpe_rot_error); });
}

std::vector<char> readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

PlotPlane parsePlotPlane(const std::string& name) {
  if (name == "auto") return PlotPlane::Auto;
  if (name == "xy") return PlotPlane::XY;
  if (name == "xz") return PlotPlane::XZ;
  if (name == "yz") return PlotPlane::YZ;
  throw std::invalid_argument("plot plane '" + name + "': expected auto, xy, xz or yz");
}

void checkPlotPath(const std::string& path, const std::string& option) {
  if (formatOf(path) == Format::None)
    throw std::invalid_argument(option + " '" + path +
                                "': unknown plot format; the name must end in .png, .svg or .pdf");
  try {
    const OutputFile probe(path, "plot");  // creates and removes a file beside it
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(option + ": " + e.what());
  }
}

void plotEvaluations(const std::vector<PlotSeries>& series, const std::string& path,
                     const PlotParams& params) {
  checkPlotPath(path, "plot");
  if (series.empty()) throw std::invalid_argument("plot '" + path + "': no estimate to draw");
  for (const auto& s : series)
    if (!s.result || s.result->t.empty() || s.result->ground_truth.empty())
      throw std::invalid_argument("plot '" + path + "': '" + s.label + "' has no evaluation");
  const auto device = deviceFor(formatOf(path));
  if (!deviceAvailable(device))
    throw std::runtime_error("cannot write plot '" + path + "': PLplot's " + device +
                             " driver is missing (Debian package plplot-driver-cairo)");
  const TempFile tmp;
  plsdev(device);
  plsfnam(tmp.path().c_str());
  setColours();
  // [pixels] for PNG, [points] for SVG and PDF: the same figure at 72 dpi.
  plspage(0, 0, 1500, 860, 0, 0);
  plinit();
  drawFigure(series, params);
  plend();
  const auto bytes = readAll(tmp.path());
  if (bytes.empty())
    throw std::runtime_error("cannot write plot '" + path + "': PLplot drew nothing");
  writeOutputFile(path, "plot", bytes.data(), bytes.size());
}

void plotEvaluation(const EvalResult& r, const std::string& path, const std::string& title) {
  PlotParams params;
  params.title = title;
  plotEvaluations({{"estimate", &r}}, path, params);
}

}  // namespace hrgbd
