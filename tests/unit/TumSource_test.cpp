#include "rgbd_io/TumSource.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "TestData.h"
#include "rgbd_core/RgbdFrame.h"

TEST(TumSource, RealFr1DeskFramesMatchPngOver5000) {
  HRGBD_REQUIRE_SHARED_DATA(data);
  const auto folder = data + "/real/tum_fr1_desk_9frames";
  hrgbd::TumSource src(folder);
  EXPECT_EQ(src.size(), 9u);
  EXPECT_DOUBLE_EQ(src.camera().fx(), 517.3);  // "auto" recognised fr1 from the folder name
  EXPECT_GT(src.groundTruth().size(), 1000u);
  const auto depth_files = hrgbd::parseTumList(folder + "/depth.txt");
  int n = 0;
  while (auto obs = src.next()) {
    const cv::Mat png = cv::imread(folder + "/" + depth_files[n].file, cv::IMREAD_ANYDEPTH);
    const cv::Mat d = hrgbd::depthMetres(*obs);
    ASSERT_EQ(png.size(), d.size());
    double max_err = 0;
    for (int r = 0; r < png.rows; ++r)
      for (int c = 0; c < png.cols; ++c)
        max_err = std::max(max_err, std::abs(d.at<float>(r, c) - png.at<uint16_t>(r, c) / 5000.0));
    EXPECT_LT(max_err, 1e-5) << "frame " << n;
    EXPECT_FALSE(hrgbd::colourBgr(*obs).empty());
    ++n;
  }
  EXPECT_EQ(n, 9);
  EXPECT_EQ(src.next(), nullptr);  // stays at the end
}

TEST(TumSource, BrokenTimestampsNameTheFileAndLine) {
  HRGBD_REQUIRE_SHARED_DATA(data);
  try {
    hrgbd::TumSource src(data + "/real/realsense_handheld_30frames");
    FAIL() << "the RealSense lists are not in time order; expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("rgb.txt' line"), std::string::npos) << e.what();
  }
}

TEST(TumSource, MissingFolderOrListsAreClearErrors) {
  EXPECT_THROW(hrgbd::TumSource("/nonexistent/folder"), std::runtime_error);
  const auto dir = hrgbd::test::tempDir("tum_nolists");
  try {
    hrgbd::TumSource src(dir);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("rgb.txt"), std::string::npos) << e.what();
  }
}

TEST(TumSource, MissingImageIsAnErrorNamingIt) {
  const auto dir = hrgbd::test::tempDir("tum_missing_image");
  std::ofstream(dir + "/rgb.txt") << "1.0 rgb/1.png\n";
  std::ofstream(dir + "/depth.txt") << "1.0 depth/1.png\n";
  hrgbd::TumSource src(dir);
  try {
    src.next();
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("rgb/1.png"), std::string::npos) << e.what();
  }
}

TEST(TumSource, TheFr1AndFr2CamerasHaveTheirRollingShutter) {
  const auto dir = hrgbd::test::tempDir("tum_rolling_shutter");
  std::ofstream(dir + "/rgb.txt") << "1.0 rgb/1.png\n";
  std::ofstream(dir + "/depth.txt") << "1.0 depth/1.png\n";
  hrgbd::TumSourceParams p;
  p.intrinsics = "ros_default";
  EXPECT_EQ(hrgbd::TumSource(dir, p).rollingShutterMs(), 0);
  p.intrinsics = "explicit";
  EXPECT_EQ(hrgbd::TumSource(dir, p).rollingShutterMs(), 0);
  for (const char* camera : {"fr1", "fr2"}) {
    p.intrinsics = camera;
    EXPECT_EQ(hrgbd::TumSource(dir, p).rollingShutterMs(), 30) << camera;
  }
  p.intrinsics = "fr3";  // measured no consistent gain on fr3: not undone
  EXPECT_EQ(hrgbd::TumSource(dir, p).rollingShutterMs(), 0);
  p.intrinsics = "fr1";
  p.rolling_shutter_ms = 12;
  EXPECT_EQ(hrgbd::TumSource(dir, p).rollingShutterMs(), 12);
}

namespace {
/** A folder of one 64x48 frame (flat grey, depth 1 m) with `calibration` as its calibration.txt. */
std::string folderWithCalibration(const std::string& name, const std::string& calibration) {
  const auto dir = hrgbd::test::tempDir(name);
  std::filesystem::create_directories(dir + "/rgb");
  std::filesystem::create_directories(dir + "/depth");
  cv::imwrite(dir + "/rgb/1.png", cv::Mat(48, 64, CV_8UC3, cv::Scalar(90, 100, 110)));
  cv::imwrite(dir + "/depth/1.png", cv::Mat(48, 64, CV_16UC1, cv::Scalar(5000)));
  std::ofstream(dir + "/rgb.txt") << "1.0 rgb/1.png\n";
  std::ofstream(dir + "/depth.txt") << "1.0 depth/1.png\n";
  std::ofstream(dir + "/calibration.txt") << calibration;
  return dir;
}

}  // namespace

TEST(TumSource, TheFoldersCalibrationTxtGivesTheCameraUnlessTheIniSetsOne) {
  // in a folder whose name would pick fr1: the file wins over the name
  const auto dir = folderWithCalibration("tum_fr1_calibrated", "# fx fy cx cy\n50 51 31.5 23.25\n");
  hrgbd::TumSource src(dir);
  EXPECT_NE(src.describe().find("intrinsics calibration.txt (the folder's own: fx 50, fy 51, "
                                "cx 31.5, cy 23.25"),
            std::string::npos)
      << src.describe();
  EXPECT_EQ(src.rollingShutterMs(), 0);  // not a Freiburg Kinect
  bool listed = false;
  for (const auto& in : src.inputs()) listed |= in.path == dir + "/calibration.txt";
  EXPECT_TRUE(listed) << "an output could overwrite calibration.txt";
  const auto obs = src.next();
  ASSERT_TRUE(obs);
  const auto& cam = obs->cameraParamsIntensity;
  EXPECT_EQ(cam.fx(), 50);
  EXPECT_EQ(cam.fy(), 51);
  EXPECT_EQ(cam.cx(), 31.5);
  EXPECT_EQ(cam.cy(), 23.25);
  EXPECT_EQ(cam.ncols, 64u);
  EXPECT_EQ(cam.nrows, 48u);

  hrgbd::TumSourceParams p;
  p.intrinsics = "fr3";
  hrgbd::TumSource fr3(dir, p);
  EXPECT_DOUBLE_EQ(fr3.camera().fx(), 535.4);
  EXPECT_NE(fr3.describe().find("the folder's calibration.txt is not read"), std::string::npos)
      << fr3.describe();
  listed = false;  // still an input that no output may overwrite
  for (const auto& in : fr3.inputs()) listed |= in.path == dir + "/calibration.txt";
  EXPECT_TRUE(listed);
}

TEST(TumSource, AMalformedCalibrationTxtIsRefusedNamingItsLine) {
  const std::pair<const char*, const char*> cases[] = {
      {"50 51 31.5\n", "line 1: expected 'fx fy cx cy'"},
      {"50 51 31.5 23.5 0 0 0\n", "line 1: expected 'fx fy cx cy'"},
      {"fx fy cx cy\n", "line 1: expected 'fx fy cx cy'"},
      {"# camera\n\n-50 51 31.5 23.5\n", "line 3: the focal lengths fx, fy must be positive"},
      {"50 51 31.5 23.5\n50 51 31.5 23.5\n", "line 2: a second line of values (line 1"},
      {"# nothing\n", "holds no 'fx fy cx cy' line"},
      {"50 51 1e999 23.5\n", "line 1: expected"},
  };
  for (const auto& [text, expected] : cases) {
    const auto dir = folderWithCalibration("tum_bad_calibration", text);
    const auto what = hrgbd::test::errorOf([&] { hrgbd::TumSource src(dir); });
    EXPECT_NE(what.find("calibration.txt' "), std::string::npos) << text << " -> " << what;
    EXPECT_NE(what.find(expected), std::string::npos) << text << " -> " << what;
  }
  // values no camera of these 64x48 images has: refused when the first frame says their size
  const std::pair<const char*, const char*> impossible[] = {
      {"525 525 319.5 239.5\n", "calibration.txt': cx = 319.5 lies outside the 64x48 image"},
      {"1e300 50 31.5 23.5\n", "calibration.txt': fx = 1e+300 is no focal length for the 64x48"},
      {"50 1e-300 31.5 23.5\n", "calibration.txt': fy = 1e-300 is no focal length"},
  };
  for (const auto& [text, expected] : impossible) {
    hrgbd::TumSource src(folderWithCalibration("tum_bad_calibration", text));
    const auto what = hrgbd::test::errorOf([&] { src.next(); });
    EXPECT_NE(what.find(expected), std::string::npos) << text << " -> " << what;
  }
  // a broken link is no missing file (that would guess the camera from the path)
  const auto dir = folderWithCalibration("tum_bad_calibration", "");
  std::filesystem::remove(dir + "/calibration.txt");
  std::filesystem::create_symlink(dir + "/nowhere.txt", dir + "/calibration.txt");
  const auto what = hrgbd::test::errorOf([&] { hrgbd::TumSource src(dir); });
  EXPECT_NE(what.find("calibration.txt' is a broken symbolic link"), std::string::npos) << what;
}

TEST(TumSource, IntrinsicsForTwiceTheImageSizeAreSaidOnce) {
  // the values of a 32x24 camera for 64x48 images: the principal point a quarter off the centre
  const auto dir = folderWithCalibration("tum_half_calibration", "26.25 26.25 15.75 11.75\n");
  std::ostringstream err;
  auto* old = std::cerr.rdbuf(err.rdbuf());
  {
    hrgbd::TumSource src(dir);
    EXPECT_TRUE(src.next());
    EXPECT_TRUE(src.next() == nullptr);
    hrgbd::TumSource again(dir);  // once per folder, as a benchmark opens it per method
    EXPECT_TRUE(again.next());
  }
  std::cerr.rdbuf(old);
  const auto text = err.str();
  EXPECT_NE(text.find("calibration.txt': the principal point (15.75, 11.75) lies more than a "
                      "sixth of the 64x48 image"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("intrinsics for another image size?"), std::string::npos) << text;
  EXPECT_EQ(text.find("warning", 1), std::string::npos) << "said twice: " << text;
  // centred values give no warning
  std::ostringstream quiet;
  old = std::cerr.rdbuf(quiet.rdbuf());
  EXPECT_TRUE(hrgbd::TumSource(folderWithCalibration("tum_centred", "50 50 31.5 23.5\n")).next());
  std::cerr.rdbuf(old);
  EXPECT_EQ(quiet.str(), "");
}
