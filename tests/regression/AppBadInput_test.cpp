// Bad and unusual input, run as the user runs the apps: frame sizes, list and trajectory files
// as editors save them, image paths, rawlogs that are no rawlogs, depth images of the wrong
// format, intrinsics chosen without being asked, configuration files and options. Each case ends
// in a clear error naming the file, entry or key (or runs, where it is supported).
#include <zlib.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "AppRun.h"

namespace {

namespace fs = std::filesystem;
using hrgbd::test::expectFailure;
using hrgbd::test::expectRefused;
using hrgbd::test::runApp;
using hrgbd::test::slurp;

const std::string kOdometry = "hybrid-rgbd-odometry";

/** A textured colour image and a depth image (1 to 2 m, 16-bit at 5000 per metre). */
cv::Mat colourImage(cv::Size s) {
  cv::Mat bgr(s, CV_8UC3);
  cv::RNG(1).fill(bgr, cv::RNG::UNIFORM, 0, 256);
  return bgr;
}
cv::Mat depthImage(cv::Size s) {
  cv::Mat d(s, CV_16UC1);
  cv::RNG(2).fill(d, cv::RNG::UNIFORM, 5000, 10000);
  return d;
}

/** A TUM folder `dir` with one frame per size, colour rgb/<i>.png and depth depth/<i>.png. */
std::string writeTum(const fs::path& dir, const std::vector<cv::Size>& sizes) {
  fs::create_directories(dir / "rgb");
  fs::create_directories(dir / "depth");
  std::ofstream rgb(dir / "rgb.txt"), depth(dir / "depth.txt");
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const auto name = std::to_string(i) + ".png";
    EXPECT_TRUE(cv::imwrite((dir / "rgb" / name).string(), colourImage(sizes[i])));
    EXPECT_TRUE(cv::imwrite((dir / "depth" / name).string(), depthImage(sizes[i])));
    rgb << 1.0 + 0.1 * i << " rgb/" << name << "\n";
    depth << 1.0 + 0.1 * i << " depth/" << name << "\n";
  }
  return dir.string();
}

/** A valid PNG header (signature, IHDR with its CRC) declaring `w` x `h` 8-bit RGB pixels, and
 * no pixel data: what a "decompression bomb" shows the decoder first. */
std::string pngHeader(std::uint32_t w, std::uint32_t h) {
  std::string ihdr = "IHDR";
  for (std::uint32_t v : {w, h})
    for (int shift = 24; shift >= 0; shift -= 8) ihdr += char((v >> shift) & 0xff);
  ihdr += std::string("\x08\x02\x00\x00\x00", 5);
  const auto crc = crc32(0, reinterpret_cast<const Bytef*>(ihdr.data()), ihdr.size());
  std::string png = "\x89PNG\r\n\x1a\n";
  png += std::string("\x00\x00\x00\x0d", 4) + ihdr;
  for (int shift = 24; shift >= 0; shift -= 8) png += char((crc >> shift) & 0xff);
  return png;
}

/** Runs the odometry on `input` for at most `frames` frames, output in `dir`. */
hrgbd::test::Run odometry(const std::string& input, const fs::path& dir, int frames = 3,
                          const std::string& more = "") {
  return runApp(kOdometry, "-q -i " + input + " -n " + std::to_string(frames) + " -t " +
                               (dir / "t.txt").string() + " " + more);
}

// ---- 1. frame sizes ------------------------------------------------------------------------

TEST(AppBadInput, FrameSizesThePresetCannotServeAreRefusedNamingFileAndSizes) {
  // They ended in MRPT's scaleToResolution() assertion with a backtrace.
  const fs::path dir = hrgbd::test::tempDir("bad_sizes");
  for (const auto& [name, size] :
       std::vector<std::pair<std::string, cv::Size>>{{"hd", {1280, 720}}, {"one", {1, 1}}}) {
    const auto tum = writeTum(dir / name, {size, size});
    const auto text = std::to_string(size.width) + "x" + std::to_string(size.height);
    expectFailure(kOdometry, "-q -i " + tum + " -t " + (dir / "t.txt").string(),
                  {"rgb/0.png", text, "640x480", "intrinsics = explicit"});
  }
  EXPECT_FALSE(fs::exists(dir / "t.txt"));
}

TEST(AppBadInput, AnySizeRunsWithExplicitIntrinsicsAndFourThreeIsScaled) {
  const fs::path dir = hrgbd::test::tempDir("good_sizes");
  const auto hd = writeTum(dir / "hd", {{1280, 720}, {1280, 720}});
  std::ofstream(dir / "hd.ini") << "[TumSource]\nintrinsics = explicit\nfx = 910\nfy = 910\n"
                                   "cx = 640\ncy = 360\n";
  auto r = odometry(hd, dir, 2, "-c " + (dir / "hd.ini").string());
  EXPECT_EQ(r.code, 0) << r.err;
  // A 1x1 frame is no error either, only unregistered (ORB's pyramid threw an assertion).
  const auto one = writeTum(dir / "one", {{1, 1}, {1, 1}});
  std::ofstream(dir / "one.ini") << "[TumSource]\nintrinsics = explicit\nfx = 1\nfy = 1\n"
                                    "cx = 0\ncy = 0\n";
  r = odometry(one, dir, 2, "-c " + (dir / "one.ini").string());
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("frames: 2, registered: 1"), std::string::npos) << r.out;
  r = odometry(writeTum(dir / "small", {{320, 240}, {320, 240}}), dir, 2);
  EXPECT_EQ(r.code, 0) << r.err;
  // A principal point off the image ran, every frame "ok" on a wrong camera.
  std::ofstream(dir / "off.ini") << "[TumSource]\nintrinsics = explicit\ncx = 5000\n";
  expectFailure(
      kOdometry,
      "-q -i " + hd + " -t " + (dir / "t.txt").string() + " -c " + (dir / "off.ini").string(),
      {"[TumSource] cx = 5000 lies outside the 1280x720 image", "rgb/0.png"});
}

TEST(AppBadInput, ASizeChangeInTheSequenceNamesTheFrame) {
  const fs::path dir = hrgbd::test::tempDir("size_change");
  const auto tum = writeTum(dir / "tum", {{640, 480}, {640, 480}, {320, 240}});
  expectFailure(kOdometry, "-q -i " + tum + " -t " + (dir / "t.txt").string(),
                {"rgb/2.png", "frame 2", "320x240", "rgb/0.png", "640x480"});
}

TEST(AppBadInput, AnImageDeclaringHugeDimensionsIsRefusedBeforeDecoding) {
  const fs::path dir = hrgbd::test::tempDir("png_bomb");
  const auto tum = writeTum(dir / "tum", {{640, 480}, {640, 480}});
  std::ofstream(dir / "tum" / "rgb" / "1.png", std::ios::binary) << pngHeader(60000, 60000);
  expectFailure(kOdometry, "-q -i " + tum + " -t " + (dir / "t.txt").string(),
                {"rgb/1.png", "60000x60000"});
}

TEST(AppBadInput, ATruncatedJpegIsRefusedNamingTheFile) {
  // OpenCV and MRPT decode it with a libjpeg warning and grey rows: it was registered as "ok".
  const fs::path dir = hrgbd::test::tempDir("jpeg_truncated");
  const auto tum = writeTum(dir / "tum", {{640, 480}, {640, 480}});
  std::vector<unsigned char> jpeg;
  ASSERT_TRUE(cv::imencode(".jpg", colourImage({640, 480}), jpeg));
  const auto whole = std::string(jpeg.begin(), jpeg.end());
  std::ofstream(dir / "tum" / "rgb" / "1.jpg", std::ios::binary) << whole.substr(0, 8000);
  std::ofstream(dir / "tum" / "rgb.txt") << "1.0 rgb/0.png\n1.1 rgb/1.jpg\n";
  expectFailure(kOdometry, "-q -i " + tum + " -t " + (dir / "t.txt").string(),
                {"colour image '" + tum + "/rgb/1.jpg' is a truncated JPEG file"});
  // The same file whole runs, also with bytes after its end (padding, appended data).
  std::ofstream(dir / "tum" / "rgb" / "1.jpg", std::ios::binary) << whole << std::string(2048, 0);
  EXPECT_EQ(odometry(tum, dir, 2).code, 0);
  // A rawlog's external image.
  const auto rawlog = dir / "desk_near.rawlog";
  for (const auto* name : {"desk_near.rawlog", "desk_near_Images"})
    fs::copy(std::string(HRGBD_SOURCE_DIR) + "/rawlogs/" + name, dir / name,
             fs::copy_options::recursive);
  const auto image = dir / "desk_near_Images" / "RGBD_SIM_000002.jpg";
  const auto bytes = slurp(image);
  std::ofstream(image, std::ios::binary | std::ios::trunc) << bytes.substr(0, bytes.size() / 2);
  expectFailure(kOdometry, "-q -i " + rawlog.string() + " -t " + (dir / "t.txt").string(),
                {"entry 2: external image", "RGBD_SIM_000002.jpg' is a truncated JPEG file"});
}

// ---- 2, 3. lists as editors save them, absolute image paths ---------------------------------

TEST(AppBadInput, ByteOrderMarksAndAbsoluteImagePathsAreAccepted) {
  const fs::path dir = hrgbd::test::tempDir("bom_absolute");
  const auto sim = runApp("rgbd-simulate", "--scene wall -n 3 --tum " + (dir / "tum").string());
  ASSERT_EQ(sim.code, 0) << sim.err;
  for (const auto* list : {"rgb.txt", "depth.txt", "groundtruth.txt"}) {
    auto text = slurp(dir / "tum" / list);
    if (std::string(list) == "rgb.txt") {  // absolute paths for the colour images
      for (std::size_t at = 0; (at = text.find(" rgb/", at)) != std::string::npos; ++at)
        text.replace(at + 1, 0, (dir / "tum").string() + "/");
    }
    std::ofstream(dir / "tum" / list, std::ios::binary) << "\xEF\xBB\xBF" << text;
  }
  const auto r = odometry((dir / "tum").string(), dir, 3);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("ATE"), std::string::npos) << r.out;  // the ground truth was read
  EXPECT_EQ(slurp(dir / "t.txt").empty(), false);
}

// ---- 4, 5. rawlogs ---------------------------------------------------------------------------

TEST(AppBadInput, ARawlogWithoutItsImageFolderSaysSo) {
  const fs::path dir = hrgbd::test::tempDir("rawlog_no_images");
  fs::copy_file(std::string(HRGBD_SOURCE_DIR) + "/rawlogs/desk_near.rawlog", dir / "desk.rawlog");
  expectFailure(kOdometry, "-q -i " + (dir / "desk.rawlog").string(),
                {"rawlog '" + (dir / "desk.rawlog").string() +
                 "' references external images in "
                 "folder '" +
                 (dir / "desk_Images").string() + "', which does not exist"});
}

TEST(AppBadInput, AnUndecodableExternalImageIsAFlaggedFrameWithAOneLineDetail) {
  // The CSV's detail held MRPT's whole exception text, call stack backtrace included.
  const fs::path dir = hrgbd::test::tempDir("rawlog_undecodable");
  for (const auto* name : {"desk_near.rawlog", "desk_near_Images"})
    fs::copy(std::string(HRGBD_SOURCE_DIR) + "/rawlogs/" + name, dir / name,
             fs::copy_options::recursive);
  std::ofstream(dir / "desk_near_Images" / "RGBD_SIM_000002.jpg", std::ios::binary)
      << std::string(300, '\x5a');
  const auto r = odometry((dir / "desk_near.rawlog").string(), dir, 4,
                          "--no-slam --csv " + (dir / "c.csv").string());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto csv = slurp(dir / "c.csv");
  const auto flagged = csv.find(",bad_input,");
  ASSERT_NE(flagged, std::string::npos) << csv;
  const auto line = csv.substr(flagged, csv.find('\n', flagged) - flagged);
  EXPECT_NE(line.find("RGBD_SIM_000002.jpg"), std::string::npos) << line;
  EXPECT_EQ(csv.find("backtrace"), std::string::npos) << csv;
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5) << csv;  // header and 4 frames
}

TEST(AppBadInput, AGzipFileOfGarbageIsNotARawlog) {
  // It was reported as "no RGB-D frames".
  const fs::path dir = hrgbd::test::tempDir("rawlog_garbage");
  std::string garbage = "\x1f\x8b\x08\x00\x00\x00\x00\x00\x00\x03";
  for (int i = 0; i < 500; ++i) garbage += char(i * 37 + 11);
  std::ofstream(dir / "garbage.rawlog", std::ios::binary) << garbage;
  // A valid gzip stream of text, and plain text.
  const auto text = std::string(200, 'x');
  gzFile gz = gzopen((dir / "text.rawlog.gz").c_str(), "wb");
  ASSERT_NE(gz, nullptr);
  gzwrite(gz, text.data(), unsigned(text.size()));
  gzclose(gz);
  std::ofstream(dir / "text.rawlog") << "this is not a rawlog\n";
  for (const auto* name : {"garbage.rawlog", "text.rawlog.gz", "text.rawlog"})
    expectFailure(kOdometry, "-q -i " + (dir / name).string(),
                  {"rawlog '" + (dir / name).string() + "' could not be decoded"});
}

// ---- 6. depth formats ------------------------------------------------------------------------

TEST(AppBadInput, DepthThatIsNotSingleChannel16BitIsRefusedNamingTheFile) {
  // A 3-channel 16-bit PNG was converted to grey (depths ~0.11x) and its frames were "ok".
  const fs::path dir = hrgbd::test::tempDir("depth_formats");
  const cv::Size s(640, 480);
  cv::Mat d3(s, CV_16UC3), d8(s, CV_8UC1), df(s, CV_32FC1);
  cv::RNG(3).fill(d3, cv::RNG::UNIFORM, 5000, 10000);
  d8.setTo(100);
  df.setTo(1.5);
  const std::vector<std::tuple<std::string, cv::Mat, std::string>> cases{
      {"colour", d3, "3-channel 16-bit"},
      {"eight", d8, "1-channel 8-bit"},
      {"float", df, "32-bit floating point"}};
  for (const auto& [name, img, what] : cases) {
    const auto tum = writeTum(dir / name, {s, s});
    const auto file = std::string(name == "float" ? "depth/1.tiff" : "depth/1.png");
    ASSERT_TRUE(cv::imwrite((dir / name / file).string(), img));
    std::ofstream(dir / name / "depth.txt") << "1.0 depth/0.png\n1.1 " << file << "\n";
    expectFailure(kOdometry, "-q -i " + tum + " -t " + (dir / "t.txt").string(),
                  {file, what, "single-channel 16-bit"});
  }
}

// ---- 8. intrinsics chosen without being asked ------------------------------------------------

TEST(AppBadInput, IntrinsicsGuessedFromNothingAreAWarningAndByNameAreSaid) {
  HRGBD_REQUIRE_SHARED_DATA(data);
  const fs::path dir = hrgbd::test::tempDir("intrinsics_name");
  const fs::path real = data + "/real/tum_fr1_desk_9frames";
  // The same frames under a name that says no camera.
  const auto copy = dir / "desk9";
  fs::create_directories(copy);
  for (const auto* f : {"rgb.txt", "depth.txt", "rgb", "depth"})
    fs::copy(real / f, copy / f, fs::copy_options::recursive);
  auto r = odometry(copy.string(), dir, 2);
  EXPECT_EQ(r.code, 0) << r.err;
  const auto warning = r.err.find("warning: TUM folder '" + copy.string() + "'");
  EXPECT_NE(warning, std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("warning:", warning + 1), std::string::npos) << "said once: " << r.err;
  for (const auto* part : {"ros_default", "[TumSource] intrinsics", "fx = fy = 525",
                           "calibration.txt as 'fx fy cx cy'"})
    EXPECT_NE(r.err.find(part), std::string::npos) << part << "\n" << r.err;
  r = odometry(real.string(), dir, 2);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.find("warning:"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("intrinsics fr1 (chosen by the folder's path"), std::string::npos) << r.out;
}

// ---- 9, 10. configuration files and options --------------------------------------------------

TEST(AppBadInput, AFolderGivenAsAFileIsNamedByEveryApp) {
  const fs::path dir = hrgbd::test::tempDir("folder_as_file");
  const auto d = dir.string();
  expectFailure(kOdometry, "-c " + d + " -i x", {"config file '" + d + "' is a folder"});
  expectFailure("rgbd-benchmark", "-c " + d, {"'" + d + "' is a folder"});
  expectFailure("rgbd-simulate", "-c " + d + " -o " + d + "/x.rawlog", {"'" + d + "' is a folder"});
  expectFailure("rgbd-eval", d + " " + d, {"'" + d + "' is a folder"});
  expectFailure("tum2rawlog", d + " " + d + "/x.rawlog -c " + d, {"'" + d + "' is a folder"});
}

TEST(AppBadInput, IniValuesThatCannotBeServedAndRepeatedKeysNameTheKey) {
  const fs::path dir = hrgbd::test::tempDir("ini_values");
  const auto ini = (dir / "x.ini").string();
  std::ofstream(ini) << "[ORB]\nn_features = 2000000000\n";  // was "vector::reserve"
  expectFailure(kOdometry, "-c " + ini + " -i x", {"[ORB] n_features = 2e+09"});
  std::ofstream(ini) << "[MSSE]\nhypotheses = 2000000000\n";  // ran for hours
  expectFailure(kOdometry, "-c " + ini + " -i x", {"[MSSE] hypotheses"});
  std::ofstream(ini) << "[ORB]\nn_features = 500\n\n[ORB]\nn_features = 800\n";
  expectFailure(kOdometry, "-c " + ini + " -i x", {ini + "' line 4", "section [ORB]"});
  std::ofstream(ini) << "[Map]\nvoxel_size = 0.02\nvoxel_size = 0.05\n";
  expectFailure(kOdometry, "-c " + ini + " -i x", {ini + "' line 3", "[Map] voxel_size"});
  // rgbd-simulate reads [Simulator] only, but a section no app knows is refused there too.
  std::ofstream(ini) << "[Simulator]\nscene = wall\n[Foo]\nbar = 1\n";
  expectFailure("rgbd-simulate", "-c " + ini + " -n 2 -o " + (dir / "s.rawlog").string(),
                {"unknown INI section [Foo]"});
  // the SLAM mode's vocabulary: missing, a folder, damaged; relative to the INI file's folder
  const auto rawlog = std::string(HRGBD_SOURCE_DIR) + "/rawlogs/desk_near.rawlog";
  std::ofstream(ini) << "[Slam]\nvocabulary = missing.txt\n";
  expectFailure(kOdometry, "-c " + ini + " -i " + rawlog,
                {"[Slam] vocabulary = " + (dir / "missing.txt").string(), "cannot open"});
  std::ofstream(ini) << "[Slam]\nvocabulary = .\n";
  expectFailure(kOdometry, "-c " + ini + " -i " + rawlog, {"[Slam] vocabulary", "is a folder"});
  std::ofstream((dir / "v.txt").string()) << "HRGBD_ORB_VOCABULARY 1 5\n00 1\n";
  std::ofstream(ini) << "[Slam]\nvocabulary = v.txt\n";
  expectFailure(kOdometry, "-c " + ini + " -i " + rawlog, {"v.txt, line 2"});
}

}  // namespace
