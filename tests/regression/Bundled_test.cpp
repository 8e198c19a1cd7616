// The default job (config.ini on rawlogs/desk_near.rawlog) with bounds from measurement, and the
// INI checks the README promises.
#include <mrpt/config/CConfigFileMemory.h>

#include <fstream>
#include <sstream>

#include "TestData.h"
#include "rgbd_app/Playback.h"
#include "rgbd_io/Config.h"

TEST(Bundled, DefaultJobTracksTheSimulatedDesk) {
  const auto dir = hrgbd::test::tempDir("bundled");
  hrgbd::PlaybackOptions o;
  o.config = std::string(HRGBD_SOURCE_DIR) + "/config.ini";
  o.trajectory = dir + "/traj.txt";
  o.csv = dir + "/frames.csv";
  o.progress = false;
  std::ostringstream log;
  const auto s = hrgbd::runPlayback(o, log);
  EXPECT_EQ(s.frames, 20u);
  EXPECT_EQ(s.registered, 20u);
  ASSERT_TRUE(s.evaluated) << log.str();
  // Measured 0.0013 m aligned, 0.0018 m unaligned over 0.63 s.
  EXPECT_LT(std::stod(s.eval_json.substr(s.eval_json.find("ate_rmse") + 11)), 0.005);
  std::ifstream csv(o.csv);
  std::string line;
  int rows = 0;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, 21);  // header + one row per frame
}

TEST(Bundled, UnknownSectionsAndKeysAreRejected) {
  const auto dir = hrgbd::test::tempDir("bundled_ini");
  for (const std::string ini :
       {"[Odometry]\nmetod = hybrid\n", "[Odometri]\nmethod = hybrid\n", "[MSSE]\nT = -1\n"}) {
    std::ofstream(dir + "/c.ini") << ini;
    hrgbd::PlaybackOptions o;
    o.config = dir + "/c.ini";
    o.input = std::string(HRGBD_SOURCE_DIR) + "/rawlogs/desk_near.rawlog";
    o.trajectory = dir + "/t.txt";
    o.progress = false;
    std::ostringstream log;
    EXPECT_THROW(hrgbd::runPlayback(o, log), hrgbd::ConfigError) << ini;
  }
}
