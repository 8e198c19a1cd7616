#include "rgbd_core/Config.h"

#include <mrpt/config/CConfigFileMemory.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <thread>

#include "TestData.h"
#include "rgbd_core/Params.h"
#include "rgbd_io/TumSource.h"

using hrgbd::ConfigError;

namespace {

enum class Colour { Red, Green };

}  // namespace

MRPT_ENUM_TYPE_BEGIN(Colour)
MRPT_FILL_ENUM_CUSTOM_NAME(Colour::Red, "red");
MRPT_FILL_ENUM_CUSTOM_NAME(Colour::Green, "green");
MRPT_ENUM_TYPE_END()

namespace {

// One field of each declarable type, in section [K].
struct Kinds : public hrgbd::Params<Kinds> {
  int count = 3;
  double size = 0.02;
  bool flag = true;
  std::string name = "hybrid";
  Colour colour = Colour::Red;
  std::vector<std::string> words{"a", "b"};
  template <class P, class V>
  static void declare(P& p, V& v) {
    HRGBD_PARAM(count, "[count] things", hrgbd::Range::closed(-10, 10));
    HRGBD_PARAM(size, "[m] a length", hrgbd::Range::above(0));
    HRGBD_PARAM(flag, "a switch");
    HRGBD_PARAM(name, "any text");
    HRGBD_PARAM(colour, "a colour");
    HRGBD_PARAM(words, "a list", hrgbd::OneOf{{"a", "b", "c"}});
  }
};

// A programming error: one key declared twice.
struct Twice : public hrgbd::Params<Twice> {
  int a = 1, b = 2;
  template <class P, class V>
  static void declare(P& p, V& v) {
    HRGBD_PARAM(a, "");
    v(p.b, "a", "");
  }
};

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

std::string kindsMessageOf(const std::string& line) {
  mrpt::config::CConfigFileMemory cfg("[K]\n" + line + "\n");
  Kinds k;
  try {
    k.loadFromConfigFile(cfg, "K");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// MRPT's own reading, which the strict check guards against: "//" after a blank starts a comment,
// '#' after a value does not, and read_int/read_bool take a prefix or give 0/false.
TEST(Config, MrptReadsCommentsAsAssumed) {
  mrpt::config::CConfigFileMemory cfg(
      "[K]\na = 1,5  // c\nb = 2.7 # c\nc = maybe // c\nd =   // c\ne = x//y\n");
  EXPECT_EQ(cfg.read_string("K", "a", ""), "1,5");
  EXPECT_EQ(cfg.read_int("K", "a", -1), 1);
  EXPECT_EQ(cfg.read_string("K", "b", ""), "2.7 # c");
  EXPECT_EQ(cfg.read_int("K", "b", -1), 2);
  EXPECT_FALSE(cfg.read_bool("K", "c", true));
  EXPECT_EQ(cfg.read_string("K", "d", ""), "// c");
  EXPECT_EQ(cfg.read_string("K", "e", ""), "x//y");
}

TEST(Config, MalformedValuesAreRejectedNamingSectionAndKey) {
  for (const std::string line :
       {"size = abc",  "size = 1,5",    "size =",       "size = nan",   "size = inf",
        "size = -inf", "size = 1e400",  "count = 2.7",  "count = 1,5",  "count = 99999999999",
        "count = x",   "count =",       "count = 0x10", "flag = maybe", "flag = 2",
        "flag =",      "colour = blue", "colour = 1",   "colour =",     "colour = red green",
        "words = a d"}) {
    for (const std::string comment : {"", "  // a comment", " # a comment"}) {
      const auto msg = kindsMessageOf(line + comment);
      const auto key = line.substr(0, line.find(' '));
      EXPECT_NE(msg.find("[K] " + key), std::string::npos)
          << line + comment << " -> '" << msg << "'";
    }
  }
}

TEST(Config, HashAfterAValueIsRejectedEvenForText) {
  for (const std::string line : {"count = 4 # c", "name = x.rawlog # c", "name = x ; c",
                                 "words = a b # c", "name =  // c"}) {
    const auto msg = kindsMessageOf(line);
    EXPECT_NE(msg.find("[K] " + line.substr(0, line.find(' '))), std::string::npos) << line;
  }
}

TEST(Config, WellFormedValuesLoadWithTrailingComments) {
  mrpt::config::CConfigFileMemory cfg(
      "[K]\ncount = -4 // c\nsize = 2.5e-3\t// c\nflag = no // c\nname = 1,5 anything // c\n"
      "colour = green // c\nwords = c a // c\n");
  Kinds k;
  k.loadFromConfigFile(cfg, "K");
  EXPECT_EQ(k.count, -4);
  EXPECT_DOUBLE_EQ(k.size, 2.5e-3);
  EXPECT_FALSE(k.flag);
  EXPECT_EQ(k.name, "1,5 anything");
  EXPECT_EQ(k.colour, Colour::Green);
  EXPECT_EQ(k.words, (std::vector<std::string>{"c", "a"}));
}

TEST(Config, RangeIsCheckedNamingSectionKeyAndBound) {
  auto msg = kindsMessageOf("count = 11");
  EXPECT_NE(msg.find("[K] count = 11: must be in [-10, 10]"), std::string::npos) << msg;
  msg = kindsMessageOf("size = 0");
  EXPECT_NE(msg.find("[K] size = 0: must be > 0"), std::string::npos) << msg;
  // beyond the "unbounded" end (1e300): not "must be > 0", which it is
  msg = kindsMessageOf("size = 1e308");
  EXPECT_NE(msg.find("[K] size = 1e+308: must be in (0, 1e+300]"), std::string::npos) << msg;
  EXPECT_EQ(kindsMessageOf("count = 10"), "");
  Kinds k;
  k.count = -11;  // set in code: validate() applies the same checks
  EXPECT_THROW(k.validate("K"), ConfigError);
}

TEST(Config, SavedValuesLoadBackUnchanged) {
  Kinds a;
  a.count = 7, a.size = 0.125, a.flag = false, a.name = "", a.colour = Colour::Green;
  a.words = {"c"};
  mrpt::config::CConfigFileMemory out;
  a.saveToConfigFile(out, "K");
  Kinds b;
  b.loadFromConfigFile(mrpt::config::CConfigFileMemory(out.getContent()), "K");
  EXPECT_EQ(b.count, 7);
  EXPECT_DOUBLE_EQ(b.size, 0.125);
  EXPECT_FALSE(b.flag);
  EXPECT_EQ(b.name, "");  // saved bare: a comment after an empty value would be read as it
  EXPECT_EQ(b.colour, Colour::Green);
  EXPECT_EQ(b.words, a.words);
  EXPECT_NE(out.getContent().find("red|green: a colour"), std::string::npos);
  EXPECT_NE(out.getContent().find("a|b|c: a list"), std::string::npos);
}

TEST(Config, KeyDeclaredTwiceIsAProgrammingError) {
  Twice t;
  EXPECT_THROW(t.loadFromConfigFile(mrpt::config::CConfigFileMemory(), "T"), std::logic_error);
  EXPECT_EQ(Kinds().keyNames(),
            (std::vector<std::string>{"count", "size", "flag", "name", "colour", "words"}));
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
  EXPECT_NE(messageOf("[TumSource]\nfy = 0 // c\n").find("[TumSource] fy"), std::string::npos);
}

TEST(Config, ValidSectionLoadsValues) {
  mrpt::config::CConfigFileMemory cfg(
      "[TumSource]\nmax_time_difference = 0.01 // s\nintrinsics = explicit // c\nfx = 500\n");
  hrgbd::TumSourceParams p;
  p.loadFromConfigFile(cfg, "TumSource");
  EXPECT_DOUBLE_EQ(p.max_time_difference, 0.01);
  EXPECT_EQ(p.intrinsics, "explicit");
  EXPECT_DOUBLE_EQ(p.fx, 500);
  EXPECT_DOUBLE_EQ(p.depth_factor, 5000);  // default kept
}

TEST(Config, UnknownSectionIsRejectedAndSimulatorIsKnown) {
  EXPECT_NO_THROW(hrgbd::rejectUnknownSections(
      mrpt::config::CConfigFileMemory("[Simulator]\nframes = 3\n[Odometry]\n")));
  try {
    hrgbd::rejectUnknownSections(mrpt::config::CConfigFileMemory("[Odometri]\n"));
    FAIL() << "unknown section accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("[Odometri]"), std::string::npos) << e.what();
  }
}

TEST(Config, MissingFileIsAnError) {
  EXPECT_THROW(hrgbd::loadIniFile("/nonexistent/config.ini"), ConfigError);
}

TEST(Config, AFolderGivenAsTheConfigFileIsNamed) {
  // It was "basic_string::_M_create": an ifstream opens a folder and reads garbage sizes.
  const auto dir = hrgbd::test::tempDir("config_folder");
  try {
    hrgbd::loadIniFile(dir);
    FAIL() << "a folder loaded as a config file";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("'" + dir + "' is a folder"), std::string::npos)
        << e.what();
  }
}

namespace {
// loadIniFile()'s message on a file holding `text`, "" if it loads.
std::string messageOfFile(const std::string& text) {
  const auto dir = hrgbd::test::tempDir("config_lines");
  std::ofstream(dir + "/c.ini") << text;
  try {
    hrgbd::loadIniFile(dir + "/c.ini");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(Config, RepeatedSectionsAndKeysAreRejectedNamingLineAndKey) {
  auto msg = messageOfFile("[ORB]\nn_features = 500\nfast_threshold = 20\nn_features = 800\n");
  EXPECT_NE(msg.find("line 4"), std::string::npos) << msg;
  EXPECT_NE(msg.find("[ORB] n_features"), std::string::npos) << msg;
  EXPECT_NE(msg.find("first on line 2"), std::string::npos) << msg;
  msg = messageOfFile("[ORB]\nn_features = 500\n\n[Map]\nvoxel_size = 0.02\n[ORB]\nn_levels = 8\n");
  EXPECT_NE(msg.find("line 6"), std::string::npos) << msg;
  EXPECT_NE(msg.find("section [ORB]"), std::string::npos) << msg;
  // The same key in two sections, and commented-out repeats, are fine.
  EXPECT_EQ(messageOfFile("[ORB]\nmax_depth = 4\n# max_depth = 5\n[Map]\nmax_depth = 4\n"), "");
  // The project's own files repeat nothing.
  for (const auto* f : {"/config.ini", "/config/paper.ini"})
    EXPECT_NO_THROW(hrgbd::loadIniFile(std::string(HRGBD_SOURCE_DIR) + f)) << f;
}

TEST(Config, LinesMrptWouldSkipAreRejectedNamingTheLine) {
  auto msg = messageOfFile("n_features = 500\n[ORB]\nfast_threshold = 5\n");
  EXPECT_NE(msg.find("line 1"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'n_features' comes before any [section]"), std::string::npos) << msg;
  msg = messageOfFile("[ORB]\nfast_threshold 5\n");
  EXPECT_NE(msg.find("line 2"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'fast_threshold 5' is neither"), std::string::npos) << msg;
  msg = messageOfFile("[ORB\nn_features = 500\n");
  EXPECT_NE(msg.find("line 1"), std::string::npos) << msg;
  EXPECT_NE(msg.find("without closing it"), std::string::npos) << msg;
  msg = messageOfFile("[ORB]\n = 5\n");
  EXPECT_NE(msg.find("line 2: '= 5' gives a value without a key"), std::string::npos) << msg;
  // Comments of every kind, blank lines, MRPT's continued lines and @define'd variables stay
  // allowed; a line number after a continued line is still the file's.
  EXPECT_EQ(messageOfFile("; a\n# b\n// c\n\n  \t\n[ORB]\nn_features = 500 // d\n"), "");
  EXPECT_EQ(messageOfFile("[ORB]\nn_features = \\\n  500\nn_levels = 8\n"), "");
  EXPECT_EQ(messageOfFile("@define KV n_levels = 8\n[ORB]\n${KV}\n"), "");
  msg = messageOfFile("[ORB]\nn_features = \\\n  500\nfast_threshold 5\n");
  EXPECT_NE(msg.find("line 4: 'fast_threshold 5'"), std::string::npos) << msg;
}

TEST(Config, IncludeLinesAreRefusedNamingTheLine) {
  // MRPT's INI preprocessor knows @define only: "@include" was skipped without a word.
  const auto msg = messageOfFile("[ORB]\nn_features = 500\n@include other.ini\n");
  EXPECT_NE(msg.find("line 3: '@include other.ini'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("no @include"), std::string::npos) << msg;
  EXPECT_EQ(messageOfFile("@define N 500\n[ORB]\nn_features = ${N}\n"), "");
}

TEST(Config, AnIniFileFromAPipeIsReadOnceAndADeviceIsRefused) {
  const auto dir = hrgbd::test::tempDir("config_pipe");
  const auto fifo = dir + "/c.ini";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // The writer opens, writes once and closes: a second open (CConfigFile's) waited for ever.
  std::thread writer([&] { std::ofstream(fifo) << "[ORB]\nn_features = 321\n"; });
  const auto cfg = hrgbd::loadIniFile(fifo);
  writer.join();
  EXPECT_EQ(cfg->read_int("ORB", "n_features", 0), 321);
  if (!std::filesystem::exists("/dev/zero")) GTEST_SKIP() << "no /dev/zero on this system";
  try {
    hrgbd::loadIniFile("/dev/zero");  // was read until memory ran out: std::bad_alloc
    FAIL() << "/dev/zero read as an INI file";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("config file '/dev/zero' is a character device"),
              std::string::npos)
        << e.what();
  }
}
