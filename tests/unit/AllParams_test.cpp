// Every params struct of the project through its real INI sections: each malformed value of
// each key, with and without a trailing comment, is an error naming the section and key; saved
// values load back unchanged; one file may hold every known section.
#include <mrpt/config/CConfigFileMemory.h>

#include <algorithm>
#include <fstream>
#include <functional>
#include <sstream>

#include "../../modules/rgbd_app/src/PlaybackSection.h"  // [Playback] (private to rgbd_app)
#include "TestData.h"
#include "rgbd_app/AppConfig.h"
#include "rgbd_app/Playback.h"
#include "rgbd_baselines/Baselines.h"
#include "rgbd_bench/Benchmark.h"
#include "rgbd_core/Config.h"
#include "rgbd_io/TumSource.h"
#include "rgbd_map/ColouredMap.h"
#include "rgbd_odometry/OdometryParams.h"
#include "rgbd_sim/Simulator.h"
#include "rgbd_slam/SlamParams.h"

using hrgbd::ConfigError;
using mrpt::config::CConfigFileMemory;

namespace {

enum class Kind { Integer, Real, Bool, Enum, Choice, Text, List };

// The declared type of each key of a section (merged structs included).
struct Probe {
  std::vector<std::pair<std::string, Kind>> keys;
  template <class T, class... Checks>
  void operator()(const T&, const char* key, const char*, const Checks&...) {
    constexpr bool choice = (std::is_same_v<Checks, hrgbd::OneOf> || ...);
    Kind k = Kind::Text;
    if constexpr (std::is_same_v<T, int>) k = Kind::Integer;
    if constexpr (std::is_same_v<T, double>) k = Kind::Real;
    if constexpr (std::is_same_v<T, bool>) k = Kind::Bool;
    if constexpr (std::is_enum_v<T>) k = Kind::Enum;
    if constexpr (std::is_same_v<T, std::string>) k = choice ? Kind::Choice : Kind::Text;
    if constexpr (std::is_same_v<T, std::vector<std::string>>) k = Kind::List;
    keys.emplace_back(key, k);
  }
  template <class P>
  void section(const P&, const std::string&) {}
  template <class P>
  void merge(const P& sub) {
    P::declare(sub, *this);
  }
};

// One real section: its keys, and how the app loads it (through the struct that owns it).
struct SectionCase {
  std::string section;
  std::vector<std::pair<std::string, Kind>> keys;
  std::function<void(const mrpt::config::CConfigFileBase&)> load;
  std::function<std::string()> defaults;  // the owner's saved defaults
};

template <class Top, class Sub>
SectionCase caseOf(const std::string& top_section, const std::string& section, const Sub& sub) {
  Probe probe;
  Sub::declare(sub, probe);
  return {section, probe.keys,
          [top_section](const mrpt::config::CConfigFileBase& c) {
            Top t;
            t.loadFromConfigFile(c, top_section);
          },
          [top_section] {
            CConfigFileMemory out;
            Top().saveToConfigFile(out, top_section);
            return out.getContent();
          }};
}

std::vector<SectionCase> allSections() {
  using namespace hrgbd;
  const OdometryParams odo;
  const BaselineParams baselines;
  const std::string bs = BaselineParams::kSection;
  return {caseOf<PlaybackSection>("Playback", "Playback", PlaybackSection()),
          caseOf<OdometryParams>("Odometry", "Odometry", odo),
          caseOf<OdometryParams>("Odometry", "ORB", odo.orb),
          caseOf<OdometryParams>("Odometry", "Geometric", odo.geometric),
          caseOf<OdometryParams>("Odometry", "MSSE", odo.msse),
          caseOf<OdometryParams>("Odometry", "Dense", odo.dense),
          caseOf<BaselineParams>(bs, "RANSAC", baselines.ransac),
          caseOf<BaselineParams>(bs, "ICP", baselines.icp),
          caseOf<MapParams>("Map", "Map", MapParams()),
          caseOf<SlamParams>("Slam", "Slam", SlamParams()),
          caseOf<TumSourceParams>("TumSource", "TumSource", TumSourceParams()),
          caseOf<sim::SimParams>("Simulator", "Simulator", sim::SimParams()),
          caseOf<BenchmarkParams>("Benchmark", "Benchmark", BenchmarkParams())};
}

std::vector<std::string> badValues(Kind k) {
  switch (k) {
    case Kind::Integer:
      return {"1,5", "2.7", "abc", "", "99999999999", "-99999999999", "nan", "1e3x"};
    case Kind::Real:
      return {"1,5", "abc", "", "nan", "inf", "-inf", "1e400", "0.5.1"};
    case Kind::Bool:
      return {"maybe", "2", "", "truee"};
    case Kind::Enum:
      return {"abc", "", "0", "hold hybrid"};
    case Kind::Choice:
      return {"abc", ""};
    case Kind::Text:
    case Kind::List:
      return {};  // any text is well-formed; the comment cases below apply to them
  }
  return {};
}

// The message of loading `ini` through the section's owner ("" = loaded).
std::string messageOf(const SectionCase& c, const std::string& ini) {
  try {
    c.load(CConfigFileMemory(ini));
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(AllParams, EveryMalformedValueIsAnErrorNamingSectionAndKey) {
  int checked = 0;
  for (const auto& c : allSections()) {
    for (const auto& [key, kind] : c.keys) {
      for (const auto& bad : badValues(kind))
        for (const std::string comment : {"", "  // a comment", "\t# a comment"}) {
          const auto line = key + " = " + bad + comment;
          const auto msg = messageOf(c, "[" + c.section + "]\n" + line + "\n");
          EXPECT_NE(msg.find("[" + c.section + "] " + key), std::string::npos)
              << "[" << c.section << "] " << line << " -> '" << msg << "'";
          ++checked;
        }
    }
  }
  EXPECT_GT(checked, 1000);
}

TEST(AllParams, DefaultValueLoadsWithSlashCommentButNotWithHashComment) {
  for (const auto& c : allSections()) {
    const CConfigFileMemory defaults(c.defaults());
    for (const auto& [key, kind] : c.keys) {
      const auto value = defaults.read_string(c.section, key, "");
      const auto head = "[" + c.section + "]\n" + key + " = " + value;
      if (!value.empty()) {
        EXPECT_EQ(messageOf(c, head + "  // a comment\n"), "") << head;
      }
      const auto msg = messageOf(c, head + " # a comment\n");
      EXPECT_NE(msg.find("[" + c.section + "] " + key), std::string::npos) << head << " -> " << msg;
    }
  }
}

TEST(AllParams, UnknownKeyIsRejectedInEverySection) {
  for (const auto& c : allSections()) {
    const auto msg = messageOf(c, "[" + c.section + "]\nno_such_key = 1\n");
    EXPECT_NE(msg.find("[" + c.section + "] unknown key 'no_such_key'"), std::string::npos) << msg;
  }
}

TEST(AllParams, EverySavedSectionIsKnownAndEveryKnownSectionIsSaved) {
  const auto& known = hrgbd::knownConfigSections();
  std::vector<std::string> saved;
  for (const auto& c : allSections()) {
    saved.push_back(c.section);
    std::vector<std::string> sections;
    CConfigFileMemory(c.defaults()).getAllSections(sections);
    for (const auto& s : sections)
      EXPECT_NE(std::find(known.begin(), known.end(), s), known.end()) << s;
  }
  for (const auto& s : known)  // [OpenNI2] holds MRPT's own COpenNI2Sensor keys
    if (s != "OpenNI2") {
      EXPECT_NE(std::find(saved.begin(), saved.end(), s), saved.end()) << s;
    }
}

// Saves `a`, loads the text into a fresh struct and saves that: both texts must be equal, and
// the loaded struct must save what `a` saved (so every field went through).
template <class P>
void expectRoundTrip(const P& a, const std::string& section) {
  CConfigFileMemory out;
  a.saveToConfigFile(out, section);
  P b;
  b.loadFromConfigFile(CConfigFileMemory(out.getContent()), section);
  CConfigFileMemory again;
  b.saveToConfigFile(again, section);
  EXPECT_EQ(out.getContent(), again.getContent()) << section;
  CConfigFileMemory defaults;
  P().saveToConfigFile(defaults, section);
  EXPECT_NE(out.getContent(), defaults.getContent()) << section << ": nothing changed";
}

TEST(AllParams, SavedValuesLoadBackUnchanged) {
  using namespace hrgbd;
  OdometryParams odo;
  odo.method = Method::Open3dHybrid, odo.on_failure = FailurePolicy::Hold;
  odo.geometric_fallback = false, odo.max_step_translation = 0.25;
  odo.orb.n_features = 500, odo.geometric.is3d_T = 3.5, odo.msse.k_fraction = 0.2;
  expectRoundTrip(odo, "Odometry");
  BaselineParams baselines;
  baselines.ransac.inlier_threshold = 0.05, baselines.icp.max_iterations = 7;
  expectRoundTrip(baselines, BaselineParams::kSection);
  MapParams map;
  map.voxel_size = 0.05, map.pixel_stride = 4;
  expectRoundTrip(map, "Map");
  TumSourceParams tum;
  tum.intrinsics = "explicit", tum.fx = 520.5, tum.cy = 240.25;
  expectRoundTrip(tum, "TumSource");
  sim::SimParams simp;
  simp.scene = "object", simp.far = true, simp.sensor.correlation_window = 5;
  simp.sensor.auto_exposure = 0;
  expectRoundTrip(simp, "Simulator");
  BenchmarkParams bench;
  bench.methods = {"ransac", "hybrid"}, bench.sim_scenes = {}, bench.max_frames = 9;
  bench.real_sequences = {"a/b", "c.rawlog"};
  expectRoundTrip(bench, "Benchmark");
  PlaybackSection pb;
  pb.input = "openni2", pb.trajectory = "", pb.outputs.map_ply = "m.ply";
  expectRoundTrip(pb, "Playback");
}

TEST(AllParams, OneFileHoldsEverySectionAndThePlaybackAcceptsIt) {
  const auto dir = hrgbd::test::tempDir("all_params");
  const auto ini = dir + "/all.ini";
  {
    std::ofstream f(ini);
    std::vector<std::string> written;  // [Odometry] saves its stage sections once for all
    for (const auto& c : allSections())
      if (std::find(written.begin(), written.end(), c.defaults()) == written.end())
        f << written.emplace_back(c.defaults()) << "\n";
    f << "[OpenNI2]\nsensorLabel = KINECT\n";
  }
  EXPECT_NO_THROW(hrgbd::loadChecked(ini));
  EXPECT_NE(hrgbd::effectiveConfig(ini).find("[Odometry]"), std::string::npos);
  const auto cfg = hrgbd::loadIniFile(ini);
  hrgbd::sim::SimParams simp;
  EXPECT_NO_THROW(simp.loadFromConfigFile(*cfg, "Simulator"));
  hrgbd::PlaybackOptions o;
  o.config = ini;
  o.input = std::string(HRGBD_SOURCE_DIR) + "/rawlogs/desk_near.rawlog";
  o.trajectory = dir + "/t.txt";
  o.max_frames = 2;
  o.progress = false;
  o.ini_outputs = false;
  std::ostringstream log;
  EXPECT_EQ(hrgbd::runPlayback(o, log).frames, 2u);
}

TEST(AllParams, EffectiveConfigIsAFixedPoint) {
  const auto dir = hrgbd::test::tempDir("all_params_fixed");
  const auto text = hrgbd::effectiveConfig(std::string(HRGBD_SOURCE_DIR) + "/config.ini");
  std::ofstream(dir + "/e.ini") << text;
  EXPECT_EQ(hrgbd::effectiveConfig(dir + "/e.ini"), text);
}
