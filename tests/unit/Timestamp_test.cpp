// Frame time stamps read and written exactly, or refused with the reason (Timestamp.h).
#include "rgbd_core/Timestamp.h"

#include <cstdint>
#include <cstdlib>

#include "TestData.h"

namespace {

/** The reason parseFrameTime() refuses `text` ("" if it does not). */
std::string refusal(const std::string& text) {
  try {
    hrgbd::parseFrameTime(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Timestamp, TextIsReadAndWrittenExactly) {
  // A double near 1.7e9 s has a step of 238 ns: these would change through one.
  for (const auto& [in, out] : std::vector<std::pair<std::string, std::string>>{
           {"1700000000.1234567", "1700000000.123456700"},
           {"1305031453.359684", "1305031453.359684000"},
           {"1700000000.1234568", "1700000000.123456800"},
           {"0", "0.000000000"},
           {"0.0000001", "0.000000100"},
           {"1.5e3", "1500.000000000"},
           {"+12.50000000000", "12.500000000"},
           {"99999999999.9999999", "99999999999.999999900"}})
    EXPECT_EQ(hrgbd::formatFrameTime(hrgbd::parseFrameTime(in)), out) << in;
  EXPECT_LT(hrgbd::parseFrameTime("1700000000.1234567"),
            hrgbd::parseFrameTime("1700000000.1234568"));
  EXPECT_DOUBLE_EQ(hrgbd::frameSeconds(hrgbd::parseFrameTime("1305031453.359684")),
                   1305031453.359684);
  // The same as MRPT's own conversion, where that is right.
  const auto t = hrgbd::parseFrameTime("1305031453.359684");
  EXPECT_EQ(hrgbd::frameSeconds(t), mrpt::Clock::toDouble(t));
}

TEST(Timestamp, StampsMrptsClockCannotHoldAreRefusedWithTheReason) {
  EXPECT_NE(refusal("-1").find("negative"), std::string::npos);
  EXPECT_NE(refusal("-0.5").find("negative"), std::string::npos);
  for (const char* big : {"1e308", "1700000000123456789", "1700000000123456", "100000000000"})
    EXPECT_NE(refusal(big).find("not below 1e11 s"), std::string::npos) << big;
  for (const char* fine : {"0.00000001", "1.00000002", "1700000000.12345678", "1e-300"})
    EXPECT_NE(refusal(fine).find("finer than 100 ns"), std::string::npos) << fine;
  for (const char* junk : {"", "abc", "nan", "inf", "1.2.3", "1e", "0x10", "1,5", "--1"})
    EXPECT_NE(refusal(junk).find("is not a time stamp"), std::string::npos) << junk;
  EXPECT_THROW(hrgbd::checkFrameTime(mrpt::Clock::time_point()), std::invalid_argument);
  EXPECT_THROW(hrgbd::checkFrameTime(mrpt::Clock::fromDouble(-1)), std::invalid_argument);
  EXPECT_NO_THROW(hrgbd::checkFrameTime(hrgbd::parseFrameTime("0")));
  const auto most = mrpt::Clock::time_point(mrpt::Clock::duration(INT64_MIN));
  EXPECT_EQ(hrgbd::formatFrameTime(most), "-933981677285.477580800");  // 2^63 ticks before 1601
  EXPECT_THROW(hrgbd::checkFrameTime(most), std::invalid_argument);
  EXPECT_THROW(hrgbd::frameTimeFromSeconds(-1), std::invalid_argument);
  EXPECT_THROW(hrgbd::frameTimeFromSeconds(1e308), std::invalid_argument);
  EXPECT_EQ(hrgbd::formatFrameTime(hrgbd::frameTimeFromSeconds(1000.5)), "1000.500000000");
}

TEST(Timestamp, SecondsAreWrittenInTheShortestTextThatReadsBackExactly) {
  for (double t :
       {2.5, -1.0, 1e308, 1e-10, 1305031453.3596, 1305031453.359684, 1.0 / 3, 1311868229.576})
    EXPECT_EQ(std::strtod(hrgbd::formatSeconds(t).c_str(), nullptr), t) << t;
  EXPECT_EQ(hrgbd::formatSeconds(1305031453.3596), "1305031453.3596");
  EXPECT_EQ(hrgbd::formatSeconds(2.5), "2.5");
}
