// config/paper.ini is the default configuration with exactly the paper's switches turned back:
// any other difference (a key added to config.ini and forgotten here) fails.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>

#include <set>

#include "rgbd_odometry/OdometryParams.h"

namespace {

using Keys = std::set<std::pair<std::string, std::string>>;

Keys differences(const mrpt::config::CConfigFile& a, const mrpt::config::CConfigFile& b) {
  Keys out;
  std::vector<std::string> sections, keys;
  for (const auto* f : {&a, &b}) {
    f->getAllSections(sections);
    for (const auto& s : sections) {
      f->getAllKeys(s, keys);
      for (const auto& k : keys)
        if (a.read_string(s, k, "<none>") != b.read_string(s, k, "<none>")) out.insert({s, k});
    }
  }
  return out;
}

}  // namespace

TEST(PaperPreset, DiffersFromTheDefaultsInThePapersSwitchesOnly) {
  const std::string dir = HRGBD_SOURCE_DIR;
  const mrpt::config::CConfigFile defaults(dir + "/config.ini"), paper(dir + "/config/paper.ini");
  const Keys expected{{"Odometry", "keyframe_max_translation"},
                      {"Odometry", "keyframe_after_failures"},
                      {"Odometry", "max_predicted_frames"},
                      {"Odometry", "min_photometric_inliers"},
                      {"Odometry", "geometric_fallback"},
                      {"Dense", "enabled"},
                      {"Playback", "input"},  // paths relative to the file
                      {"Benchmark", "sim_motions"},
                      {"Benchmark", "real_sequences"},
                      {"Benchmark", "cache_folder"},
                      {"Benchmark", "output_folder"},
                      {"Benchmark", "paper_config"},
                      {"Slam", "enabled"}};
  EXPECT_EQ(differences(defaults, paper), expected);

  hrgbd::OdometryParams p;
  p.loadFromConfigFile(paper, "Odometry");
  EXPECT_EQ(p.keyframe_max_translation, 0.0);
  EXPECT_EQ(p.keyframe_after_failures, 0);
  EXPECT_EQ(p.max_predicted_frames, 0);  // the paper's constant velocity over any run
  EXPECT_FALSE(p.dense.enabled);
  EXPECT_FALSE(p.geometric_fallback);
  EXPECT_EQ(p.geometric.refine_iterations, 0);
}
