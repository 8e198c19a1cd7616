// OniWriter's own contract (what it writes is checked by playing it: OniFileSource_test).
#include "rgbd_io/OniWriter.h"

#include <filesystem>

#include "TestData.h"

using hrgbd::OniStreamSpec;
using hrgbd::OniWriter;

TEST(OniWriter, RefusesFramesThatDoNotFitTheirStream) {
  const auto dir = hrgbd::test::scratchDir("oni_writer_refuses");
  OniWriter w(dir + "/a.oni", OniStreamSpec{64, 48}, OniStreamSpec{64, 48});
  EXPECT_THROW(w.writeDepth(0, 1, cv::Mat(48, 64, CV_32FC1, cv::Scalar(1))), std::invalid_argument);
  EXPECT_THROW(w.writeDepth(0, 1, cv::Mat(24, 32, CV_16UC1, cv::Scalar(1))), std::invalid_argument);
  EXPECT_THROW(w.writeColour(0, 1, cv::Mat(48, 64, CV_8UC1, cv::Scalar(1))), std::invalid_argument);
  w.writeDepth(0, 1, cv::Mat(48, 64, CV_16UC1, cv::Scalar(1)));
  // Frame indices increase (gaps allowed).
  EXPECT_THROW(w.writeDepth(1, 1, cv::Mat(48, 64, CV_16UC1, cv::Scalar(1))), std::invalid_argument);
  w.writeDepth(2, 3, cv::Mat(48, 64, CV_16UC1, cv::Scalar(1)));
}

TEST(OniWriter, TheRecordingAppearsOnlyWhenClosed) {
  const auto dir = hrgbd::test::scratchDir("oni_writer_close");
  const auto path = dir + "/b.oni";
  {
    OniWriter w(path, OniStreamSpec{64, 48}, OniStreamSpec{0, 0});
    w.writeDepth(0, 1, cv::Mat(48, 64, CV_16UC1, cv::Scalar(1)));
  }  // not closed: a failed run leaves nothing that looks like a recording
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_TRUE(std::filesystem::is_empty(dir));  // nor a temporary file
  OniWriter w(path, OniStreamSpec{64, 48}, OniStreamSpec{0, 0});
  w.writeDepth(0, 1, cv::Mat(48, 64, CV_16UC1, cv::Scalar(1)));
  w.close();
  // Header (24 bytes), node records, one frame of 64 x 48 x 2 bytes, seek table, end record.
  EXPECT_GT(std::filesystem::file_size(path), 24u + 64u * 48u * 2u);
  EXPECT_THROW(OniWriter(dir + "/missing/c.oni", OniStreamSpec{}, OniStreamSpec{}),
               std::runtime_error);
}
