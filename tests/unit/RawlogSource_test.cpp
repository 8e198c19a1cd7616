#include "rgbd_io/RawlogSource.h"

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <initializer_list>

#include "TestData.h"
#include "rgbd_core/Intrinsics.h"
#include "rgbd_core/RgbdFrame.h"
#include "rgbd_io/RawlogWriter.h"

namespace {

mrpt::obs::CObservation3DRangeScan::Ptr frame(double t, uint16_t value) {
  cv::Mat depth(480, 640, CV_16UC1, cv::Scalar(value));
  cv::Mat bgr(480, 640, CV_8UC3, cv::Scalar(value % 255, 50, 100));
  return hrgbd::makeRgbdObservation(bgr, depth, 1.0 / 5000, hrgbd::intrinsicsPreset("fr1"), t);
}

// Writes: frame, odometry, frame, SensoryFrame{frame, odometry}, frame.
void writeMixedRawlog(const std::string& path, hrgbd::ImageStorage images) {
  hrgbd::RawlogWriter w(path, images);
  w.write(*frame(1.0, 5000));
  w.write(mrpt::obs::CObservationOdometry());
  w.write(*frame(2.0, 6000));
  mrpt::obs::CSensoryFrame sf;
  sf.insert(frame(3.0, 7000));
  sf.insert(mrpt::obs::CObservationOdometry::Create());
  w.write(sf);
  w.write(*frame(4.0, 8000));
  w.close();
}

std::vector<double> readAll(hrgbd::RawlogSource& src) {
  std::vector<double> depths;
  while (auto obs = src.next()) depths.push_back(hrgbd::depthMetres(*obs).at<float>(10, 10));
  return depths;
}

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

/** Expects `src` to read its first frame and to refuse its second with a message holding
 * each of `parts`. */
void expectSecondFrameRefused(hrgbd::RawlogSource& src, std::initializer_list<const char*> parts) {
  if (!src.next()) {
    ADD_FAILURE() << "no first frame";
    return;
  }
  std::string msg;
  try {
    src.next();
    ADD_FAILURE() << "the second frame was read";
  } catch (const std::runtime_error& e) {
    msg = e.what();
  }
  for (const auto* part : parts)
    EXPECT_NE(msg.find(part), std::string::npos) << part << ": " << msg;
}

}  // namespace

TEST(RawlogSource, MixedFormatsAreReadAndOtherTypesCounted) {
  const auto dir = hrgbd::test::tempDir("rawlog_mixed");
  for (auto images : {hrgbd::ImageStorage::Inline, hrgbd::ImageStorage::ExternalPng}) {
    const auto path = dir + "/mixed.rawlog";
    writeMixedRawlog(path, images);
    hrgbd::RawlogSource src(path);
    const auto d = readAll(src);
    ASSERT_EQ(d.size(), 4u);
    EXPECT_NEAR(d[0], 1.0, 1e-6);
    EXPECT_NEAR(d[3], 1.6, 1e-6);
    EXPECT_EQ(src.stats().skipped_objects, 2u);
    EXPECT_EQ(src.stats().frames, 4u);
  }
}

TEST(RawlogSource, MissingExternalImageIsNamed) {
  const auto dir = hrgbd::test::tempDir("rawlog_noimg");
  writeMixedRawlog(dir + "/m.rawlog", hrgbd::ImageStorage::ExternalPng);
  std::filesystem::remove_all(dir + "/m_Images");
  hrgbd::RawlogSource src(dir + "/m.rawlog");
  try {
    src.next();
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("RGBD_000000.png"), std::string::npos) << e.what();
  }
}

TEST(RawlogSource, TruncatedGzipAndPlainFilesAreErrorsNotEndOfData) {
  const auto dir = hrgbd::test::tempDir("rawlog_trunc");
  writeMixedRawlog(dir + "/full.rawlog", hrgbd::ImageStorage::Inline);
  // A plain (uncompressed) copy: CFileGZInputStream reads both.
  std::string plain;
  {
    mrpt::io::CFileGZInputStream in(dir + "/full.rawlog");
    char buf[65536];
    for (size_t n; (n = in.Read(buf, sizeof(buf))) > 0;) plain.append(buf, n);
  }
  const auto gz = readBytes(dir + "/full.rawlog");
  for (const auto& [name, bytes] : {std::pair{"gz", gz}, std::pair{"plain", plain}}) {
    const auto path = dir + "/cut_" + name + ".rawlog";
    std::ofstream(path, std::ios::binary) << bytes.substr(0, bytes.size() * 6 / 10);
    hrgbd::RawlogSource src(path);
    size_t frames = 0;
    try {
      while (src.next()) ++frames;
      FAIL() << name << ": a truncated file must not look like a clean end";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
    EXPECT_GE(frames, 1u) << name << ": frames before the cut are delivered";
  }
  // The plain copy itself reads completely.
  std::ofstream(dir + "/plain.rawlog", std::ios::binary) << plain;
  hrgbd::RawlogSource src(dir + "/plain.rawlog");
  EXPECT_EQ(readAll(src).size(), 4u);
}

TEST(RawlogSource, MissingFileIsAnError) {
  EXPECT_THROW(hrgbd::RawlogSource("/nonexistent.rawlog"), std::runtime_error);
}

TEST(RawlogSource, MrptSampleOpenNI2Frame) {
  const std::string path = "/usr/share/mrpt/datasets/tests_rgbd.rawlog";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " absent (package mrpt-common)";
  hrgbd::RawlogSource src(path);
  auto obs = src.next();
  ASSERT_NE(obs, nullptr);
  EXPECT_TRUE(obs->hasRangeImage);
  const cv::Mat d = hrgbd::depthMetres(*obs);
  double mean = cv::mean(d, d > 0)[0];
  EXPECT_GT(mean, 0.3);  // a real indoor scene, metres
  EXPECT_LT(mean, 10.0);
}

TEST(RawlogSource, CorruptBytesAreAnErrorNamingTheFile) {
  // The middle of a plain rawlog overwritten with garbage: an exception naming the file, after
  // the frames before the damage, never a crash or a silent end.
  const auto dir = hrgbd::test::tempDir("rawlog_corrupt");
  writeMixedRawlog(dir + "/full.rawlog", hrgbd::ImageStorage::Inline);
  std::string plain;
  {
    mrpt::io::CFileGZInputStream in(dir + "/full.rawlog");
    char buf[65536];
    for (size_t n; (n = in.Read(buf, sizeof(buf))) > 0;) plain.append(buf, n);
  }
  for (std::size_t i = plain.size() / 2; i < plain.size() / 2 + 64; ++i) plain[i] = char(0xA5);
  const auto path = dir + "/corrupt.rawlog";
  std::ofstream(path, std::ios::binary) << plain;
  hrgbd::RawlogSource src(path);
  try {
    while (src.next()) {
    }
    FAIL() << "corrupt data must not look like a clean end";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

TEST(RawlogSource, RawlogWithoutRgbdFramesCountsWhatItSkipped) {
  const auto dir = hrgbd::test::tempDir("rawlog_no3d");
  {
    hrgbd::RawlogWriter w(dir + "/odo.rawlog");
    for (int i = 0; i < 3; ++i) w.write(mrpt::obs::CObservationOdometry());
    w.close();
  }
  hrgbd::RawlogSource src(dir + "/odo.rawlog");
  EXPECT_EQ(src.next(), nullptr);
  EXPECT_EQ(src.stats().skipped_objects, 3u);
}

TEST(RawlogSource, FramesWithoutAUsableTimeStampAreAnErrorNamingTheEntry) {
  // Unset (MRPT's 1601), before 1970 (MRPT's toDouble wraps it to 1.8e12 s), beyond 1e11 s.
  // Any 64-bit count, as a corrupt rawlog may hold, is handled without overflow.
  for (const auto& stamp : {mrpt::Clock::time_point(), mrpt::Clock::fromDouble(-1),
                            mrpt::Clock::time_point(mrpt::Clock::duration(INT64_MAX)),
                            mrpt::Clock::time_point(mrpt::Clock::duration(INT64_MIN))}) {
    const auto dir = hrgbd::test::tempDir("rawlog_stamp");
    {
      hrgbd::RawlogWriter w(dir + "/s.rawlog");
      w.write(*frame(1.0, 5000));
      auto bad = frame(2.0, 5000);
      bad->timestamp = stamp;
      w.write(*bad);
      w.close();
    }
    hrgbd::RawlogSource src(dir + "/s.rawlog");
    expectSecondFrameRefused(src, {"s.rawlog' entry 1: "});
  }
}

TEST(RawlogWriter, TheRawlogAppearsOnlyWhenClosedAndWriteFailuresAreErrors) {
  const auto dir = hrgbd::test::tempDir("rawlog_writer");
  {
    hrgbd::RawlogWriter w(dir + "/a.rawlog");
    w.write(*frame(1.0, 5000));
  }  // not closed: as when the run fails half-way
  EXPECT_FALSE(std::filesystem::exists(dir + "/a.rawlog"));
  try {
    hrgbd::RawlogWriter w("/dev/full");
    w.write(*frame(1.0, 5000));
    w.close();
    FAIL() << "writing /dev/full must fail";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write rawlog '/dev/full'"), std::string::npos)
        << e.what();
  }
}

TEST(RawlogSource, ASizeChangeWithinTheRawlogNamesTheEntry) {
  const auto dir = hrgbd::test::tempDir("rawlog_size_change");
  const auto path = dir + "/sizes.rawlog";
  {
    hrgbd::RawlogWriter w(path, hrgbd::ImageStorage::Inline);
    w.write(*frame(1.0, 5000));
    cv::Mat depth(240, 320, CV_16UC1, cv::Scalar(5000)), bgr(240, 320, CV_8UC3);
    auto cam = hrgbd::intrinsicsPreset("fr1");
    cam.scaleToResolution(320, 240);
    w.write(*hrgbd::makeRgbdObservation(bgr, depth, 1.0 / 5000, cam, 2.0));
    w.close();
  }
  hrgbd::RawlogSource src(path);
  expectSecondFrameRefused(src,
                           {"entry 1", "320x240", "entry 0", "640x480"});  // after a 640x480 one
}

TEST(RawlogSource, FramesOutOfTimeOrderNameBothEntries) {
  // They were read as they came: the trajectory went back in time and its evaluation blamed it.
  for (const double second : {1.0, 0.5}) {  // the same stamp again, an earlier one
    const auto dir = hrgbd::test::tempDir("rawlog_order");
    {
      hrgbd::RawlogWriter w(dir + "/o.rawlog");
      w.write(*frame(1.0, 5000));
      w.write(mrpt::obs::CObservationOdometry());  // not a frame: entry 1
      w.write(*frame(second, 5000));
      w.close();
    }
    hrgbd::RawlogSource src(dir + "/o.rawlog");
    SCOPED_TRACE(second);
    expectSecondFrameRefused(src, {"o.rawlog' entry 2", "not after the previous frame's",
                                   "entry 0)", "strictly increasing time order"});
  }
}

TEST(RawlogSource, FramesOfASecondCameraAreRefusedNamingBoth) {
  // Two cameras' frames (in one SensoryFrame, one time stamp) were read as one sequence, and
  // refused as out of time order.
  const auto dir = hrgbd::test::tempDir("rawlog_two_cameras");
  {
    hrgbd::RawlogWriter w(dir + "/two.rawlog");
    mrpt::obs::CSensoryFrame sf;
    for (const auto* label : {"LEFT", "RIGHT"}) {
      auto f = frame(1.0, 5000);
      f->sensorLabel = label;
      sf.insert(f);
    }
    w.write(sf);
    w.close();
  }
  hrgbd::RawlogSource src(dir + "/two.rawlog");
  expectSecondFrameRefused(src,
                           {"two.rawlog' entry 0", "camera 'RIGHT' after frames of camera 'LEFT'",
                            "rawlog-edit --keep-label LEFT"});
}
