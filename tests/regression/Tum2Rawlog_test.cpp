// tum2rawlog end to end on real TUM frames: the app's rawlog reads back through RawlogSource
// and MRPT's own unprojection with depths equal to the PNG values / 5000.
#include <mrpt/maps/CColouredPointsMap.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "TestData.h"
#include "rgbd_core/RgbdFrame.h"
#include "rgbd_io/RawlogSource.h"
#include "rgbd_io/TumLists.h"

TEST(Tum2Rawlog, RealFramesSurviveToTheMillimetre) {
  HRGBD_REQUIRE_SHARED_DATA(data);
  const std::string app = std::string(HRGBD_BINARY_DIR) + "/apps/tum2rawlog";
  ASSERT_TRUE(std::filesystem::exists(app)) << app;
  for (const std::string name : {"tum_fr1_desk_9frames", "tum_fr3_cabinet_58keyframes"}) {
    const auto folder = data + "/real/" + name;
    const auto out = hrgbd::test::tempDir("t2r_" + name) + "/seq.rawlog";
    const auto cmd = app + " " + folder + " " + out + " --images png > /dev/null";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    ASSERT_TRUE(std::filesystem::exists(hrgbd::groundTruthPathFor(out)));

    const auto depth_list = hrgbd::parseTumList(folder + "/depth.txt");
    hrgbd::RawlogSource src(out);
    EXPECT_FALSE(src.groundTruth().empty());
    size_t n = 0;
    while (auto obs = src.next()) {
      ASSERT_LT(n, depth_list.size());
      const cv::Mat png = cv::imread(folder + "/" + depth_list[n].file, cv::IMREAD_ANYDEPTH);
      const cv::Mat d = hrgbd::depthMetres(*obs);
      cv::Mat diff;
      cv::Mat png_m;
      png.convertTo(png_m, CV_32F, 1.0 / 5000);
      cv::absdiff(d, png_m, diff);
      double max_diff;
      cv::minMaxLoc(diff, nullptr, &max_diff);
      EXPECT_LT(max_diff, 1e-4) << name << " frame " << n;  // far below a millimetre

      // As a point cloud (MRPT's unprojection, x forward): the x of each point is its depth.
      mrpt::maps::CColouredPointsMap pts;
      obs->unprojectInto(pts);
      EXPECT_EQ(pts.size(), static_cast<size_t>(cv::countNonZero(png)));
      const auto& xs = pts.getPointsBufferRef_x();
      double sum_x = 0;
      for (float x : xs) sum_x += x;
      EXPECT_NEAR(sum_x / xs.size(), cv::mean(png_m, png > 0)[0], 1e-3) << name << " frame " << n;
      EXPECT_FALSE(hrgbd::colourBgr(*obs).empty());
      ++n;
    }
    EXPECT_EQ(n, depth_list.size()) << name;
  }
}
