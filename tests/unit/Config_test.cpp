#include "rgbd_core/Config.h"

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
// One field of each kind, loaded the MRPT way (which reads "abc" as 0 without a word).
struct Kinds : public mrpt::config::CLoadableOptions {
  int count = 3;
  double size = 0.02;
  bool flag = true;
  std::string name = "hybrid";
  void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override {
    MRPT_LOAD_CONFIG_VAR_CS(count, int);
    MRPT_LOAD_CONFIG_VAR_CS(size, double);
    MRPT_LOAD_CONFIG_VAR_CS(flag, bool);
    MRPT_LOAD_CONFIG_VAR_CS(name, string);
  }
  void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override {
    MRPT_SAVE_CONFIG_VAR(count, c, s);
    MRPT_SAVE_CONFIG_VAR(size, c, s);
    MRPT_SAVE_CONFIG_VAR(flag, c, s);
    MRPT_SAVE_CONFIG_VAR(name, c, s);
  }
};

std::string strictMessageOf(const std::string& line) {
  mrpt::config::CConfigFileMemory cfg("[K]\n" + line + "\n");
  Kinds k;
  try {
    hrgbd::loadStrict(k, cfg, "K");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(Config, LoadStrictRejectsValuesMrptWouldMisread) {
  for (const auto* line : {"size = abc", "size = 1,5", "size =", "size = nan", "size = 1e400",
                           "count = 2.7", "count = 99999999999", "count = x", "flag = maybe"}) {
    const auto msg = strictMessageOf(line);
    const std::string key = std::string(line).substr(0, std::string(line).find(' '));
    EXPECT_NE(msg.find("[K] " + key), std::string::npos) << line << " -> '" << msg << "'";
  }
}

TEST(Config, LoadStrictAcceptsWellFormedValues) {
  mrpt::config::CConfigFileMemory cfg(
      "[K]\ncount = -4\nsize = 2.5e-3\nflag = no\nname = 1,5 anything\n");
  Kinds k;
  hrgbd::loadStrict(k, cfg, "K");
  EXPECT_EQ(k.count, -4);
  EXPECT_DOUBLE_EQ(k.size, 2.5e-3);
  EXPECT_FALSE(k.flag);
  EXPECT_EQ(k.name, "1,5 anything");
}

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
