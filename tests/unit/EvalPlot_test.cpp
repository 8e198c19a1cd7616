#include "rgbd_eval/EvalPlot.h"

#include <gtest/gtest.h>
#include <mrpt/img/CImage.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <sstream>

#include "TestData.h"

using mrpt::poses::CPose3D;
namespace fs = std::filesystem;

namespace {
// A loop of 201 poses over 20 s in the x-y plane; `wobble` [m] bends it along z and y.
hrgbd::Trajectory loop(double wobble) {
  hrgbd::Trajectory t;
  for (int i = 0; i <= 200; ++i) {
    const double s = 0.1 * i;
    t.push_back({100.0 + s, CPose3D(std::cos(0.3 * s) + wobble * std::sin(2 * s), std::sin(0.3 * s),
                                    0.05 * s + wobble * std::cos(3 * s), 0.3 * s, 0, 0)});
  }
  return t;
}

std::string slurp(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

/** Pixels of colour `rgb` (within 20 per channel) in a PNG. */
int countColour(const std::string& png, const cv::Vec3b& rgb) {
  mrpt::img::CImage img;
  EXPECT_TRUE(img.loadFromFile(png)) << png;
  const cv::Mat m = img.asCvMatRef();
  int n = 0;
  for (int r = 0; r < m.rows; ++r)
    for (int c = 0; c < m.cols; ++c) {
      const auto px = m.at<cv::Vec3b>(r, c);  // BGR
      n += std::abs(px[2] - rgb[0]) < 20 && std::abs(px[1] - rgb[1]) < 20 &&
           std::abs(px[0] - rgb[2]) < 20;
    }
  return n;
}

const cv::Vec3b kFirstColour(31, 119, 180), kSecondColour(255, 127, 14);  // Tableau 10
}  // namespace

TEST(EvalPlot, WritesPngSvgAndPdfByExtension) {
  const auto dir = hrgbd::test::tempDir("evalplot_formats");
  const auto r = hrgbd::evaluateTrajectory(loop(0), loop(0.02));
  const std::pair<std::string, std::string> files[] = {
      {"f.png", "\x89PNG\r\n\x1a\n"}, {"f.SVG", "<?xml"}, {"f.pdf", "%PDF-"}};
  for (const auto& [name, header] : files) {
    const auto path = dir + "/" + name;
    hrgbd::plotEvaluation(r, path, "a title");
    const auto bytes = slurp(path);
    EXPECT_GT(bytes.size(), 10000u) << name;
    EXPECT_EQ(bytes.rfind(header, 0), 0u) << name;
  }
  EXPECT_NE(slurp(dir + "/f.SVG").find("<svg"), std::string::npos);
  // Only the figures: no temporary file is left beside them.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 3);
}

TEST(EvalPlot, BadPathsAreErrorsNamingThePath) {
  const auto dir = hrgbd::test::tempDir("evalplot_bad");
  const auto r = hrgbd::evaluateTrajectory(loop(0), loop(0.02));
  for (const std::string& bad :
       {dir + "/p.jpg", dir + "/p", dir + "/p.png.txt", dir + "/missing/p.png", dir}) {
    try {
      hrgbd::checkPlotPath(bad, "--plot");
      ADD_FAILURE() << "accepted " << bad;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("'" + bad), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind("--plot", 0), 0u) << e.what();
    }
    EXPECT_THROW(hrgbd::plotEvaluation(r, bad), std::invalid_argument) << bad;
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 0);
  EXPECT_NO_THROW(hrgbd::checkPlotPath(dir + "/ok.Pdf", "--plot"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 0)
      << "the check leaves nothing behind";
  // A device takes a PNG; /dev/full refuses it when written, named.
  EXPECT_NO_THROW(hrgbd::checkPlotPath("/dev/null", "--plot"));
  try {
    hrgbd::plotEvaluation(r, "/dev/full");
    ADD_FAILURE() << "/dev/full took the plot";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write plot '/dev/full'"), std::string::npos);
  }
  EXPECT_THROW(hrgbd::plotEvaluations({}, dir + "/none.png"), std::invalid_argument);
  EXPECT_THROW(hrgbd::parsePlotPlane("xx"), std::invalid_argument);
  EXPECT_EQ(hrgbd::parsePlotPlane("yz"), hrgbd::PlotPlane::YZ);
}

TEST(EvalPlot, EveryEstimateIsDrawnInItsOwnColour) {
  const auto dir = hrgbd::test::tempDir("evalplot_series");
  const auto a = hrgbd::evaluateTrajectory(loop(0), loop(0.01));
  const auto b = hrgbd::evaluateTrajectory(loop(0), loop(0.05));
  hrgbd::PlotParams p;
  p.plane = hrgbd::PlotPlane::XZ;
  hrgbd::plotEvaluations({{"a", &a}}, dir + "/one.png", p);
  hrgbd::plotEvaluations({{"a", &a}, {"b#1", &b}}, dir + "/two.png", p);
  EXPECT_GT(countColour(dir + "/one.png", kFirstColour), 2000);
  EXPECT_LT(countColour(dir + "/one.png", kSecondColour), 50);
  EXPECT_GT(countColour(dir + "/two.png", kFirstColour), 800);  // partly under the second
  EXPECT_GT(countColour(dir + "/two.png", kSecondColour), 2000);
}
