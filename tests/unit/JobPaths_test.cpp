// No output may overwrite an input or another output (JobPaths.h).
#include "rgbd_core/JobPaths.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "TestData.h"
#include "rgbd_core/Config.h"

namespace fs = std::filesystem;

namespace {

/** The message of the exception E that checkJobPaths() throws ("" if none). */
template <class E>
std::string conflict(const std::vector<hrgbd::JobPath>& in,
                     const std::vector<hrgbd::JobPath>& out) {
  try {
    hrgbd::checkJobPaths(in, out);
  } catch (const E& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(JobPaths, AnOutputNamingAnInputIsRefusedHoweverItIsSpelled) {
  const auto dir = hrgbd::test::tempDir("job_paths");
  fs::create_directories(dir + "/seq/rgb");
  std::ofstream(dir + "/seq/groundtruth.txt") << "1 0 0 0 0 0 0 1\n";
  fs::create_symlink(dir + "/seq", dir + "/link");
  fs::create_hard_link(dir + "/seq/groundtruth.txt", dir + "/hard.txt");
  const std::vector<hrgbd::JobPath> in{{dir + "/seq/groundtruth.txt", "the ground truth"}};
  for (const auto& spelling :
       {dir + "/seq/groundtruth.txt", dir + "/seq/rgb/../groundtruth.txt",
        dir + "/link/groundtruth.txt", dir + "/hard.txt", dir + "/./seq//groundtruth.txt"}) {
    const auto e = conflict<hrgbd::UsageError>(in, {{spelling, "--trajectory", false, true}});
    EXPECT_NE(e.find("--trajectory '" + spelling + "' would overwrite the ground truth '" + dir +
                     "/seq/groundtruth.txt'"),
              std::string::npos)
        << e;
  }
  // Relative to the working directory.
  const auto cwd = fs::current_path();
  fs::current_path(dir);
  EXPECT_NE(conflict<hrgbd::UsageError>(in, {{"seq/groundtruth.txt", "--csv", false, true}}), "");
  fs::current_path(cwd);
  // A different file is fine, also one that does not exist yet.
  EXPECT_NO_THROW(hrgbd::checkJobPaths(in, {{dir + "/seq/trajectory.txt", "--trajectory"},
                                            {dir + "/new/t.txt", "--csv"},
                                            {"", "--plot"}}));
}

TEST(JobPaths, FromAConfigurationFileItIsAConfigError) {
  const auto dir = hrgbd::test::tempDir("job_paths_ini");
  const auto e = conflict<hrgbd::ConfigError>({{dir + "/cfg.ini", "the configuration file"}},
                                              {{dir + "/cfg.ini", "[Playback] trajectory"}});
  EXPECT_NE(e.find("[Playback] trajectory '" + dir +
                   "/cfg.ini' would overwrite the configuration "
                   "file"),
            std::string::npos)
      << e;
}

TEST(JobPaths, FoldersHoldWhatLiesInsideThem) {
  const auto dir = hrgbd::test::tempDir("job_paths_folders");
  fs::create_directories(dir + "/x_Images");
  const std::vector<hrgbd::JobPath> images{{dir + "/x_Images", "the input's image folder", true}};
  EXPECT_NE(conflict<hrgbd::UsageError>(images, {{dir + "/x_Images/a.png", "--csv", false, true}}),
            "");
  EXPECT_NE(conflict<hrgbd::UsageError>(images, {{dir + "/x_Images/", "--out images", true, true}}),
            "");
  EXPECT_NE(conflict<hrgbd::UsageError>({{dir + "/x_Images/a.png", "an image"}},
                                        {{dir, "--tum's rgb/", true, true}}),
            "");
  EXPECT_NO_THROW(hrgbd::checkJobPaths(images, {{dir + "/x_Images2/a.png", "--csv"}}));
}

TEST(JobPaths, TwoOutputsMayNotBeOneFileExceptADevice) {
  const auto dir = hrgbd::test::tempDir("job_paths_outputs");
  const auto e = conflict<hrgbd::UsageError>({}, {{dir + "/t.txt", "--trajectory", false, true},
                                                  {dir + "/./t.txt", "--csv", false, true}});
  EXPECT_NE(
      e.find("--trajectory '" + dir + "/t.txt' and --csv '" + dir + "/./t.txt' are the same file"),
      std::string::npos)
      << e;
  EXPECT_NO_THROW(hrgbd::checkJobPaths(
      {}, {{"/dev/null", "--trajectory", false, true}, {"/dev/null", "--csv", false, true}}));
  // A device as an input is still an input.
  EXPECT_NE(conflict<hrgbd::UsageError>({{"/dev/null", "the input"}},
                                        {{"/dev/null", "--csv", false, true}}),
            "");
}
