#include "rgbd_io/Config.h"

#include <mrpt/config/CConfigFileMemory.h>

#include "TestData.h"
#include "rgbd_io/TumSource.h"

using hrgbd::ConfigError;

namespace {
std::string messageOf(const std::string& ini) {
  mrpt::config::CConfigFileMemory cfg(ini);
  hrgbd::TumSourceParams p;
  try {
    p.loadFromConfigFile(cfg, "TumSource");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(Config, UnknownKeyIsRejectedNamingSectionAndKey) {
  const auto msg = messageOf("[TumSource]\ndepth_factor = 5000\ndepth_factr = 1000\n");
  EXPECT_NE(msg.find("[TumSource]"), std::string::npos) << msg;
  EXPECT_NE(msg.find("depth_factr"), std::string::npos) << msg;
}

TEST(Config, OutOfRangeValueIsRejectedNamingKey) {
  const auto msg = messageOf("[TumSource]\ndepth_factor = -3\n");
  EXPECT_NE(msg.find("depth_factor"), std::string::npos) << msg;
  EXPECT_NE(messageOf("[TumSource]\nintrinsics = fr9\n").find("intrinsics"), std::string::npos);
}

TEST(Config, ValidSectionLoadsValues) {
  mrpt::config::CConfigFileMemory cfg(
      "[TumSource]\nmax_time_difference = 0.01\nintrinsics = explicit\nfx = 500\n");
  hrgbd::TumSourceParams p;
  p.loadFromConfigFile(cfg, "TumSource");
  EXPECT_DOUBLE_EQ(p.max_time_difference, 0.01);
  EXPECT_EQ(p.intrinsics, "explicit");
  EXPECT_DOUBLE_EQ(p.fx, 500);
  EXPECT_DOUBLE_EQ(p.depth_factor, 5000);  // default kept
}

TEST(Config, MissingFileIsAnError) {
  EXPECT_THROW(hrgbd::loadIniFile("/nonexistent/config.ini"), ConfigError);
}
