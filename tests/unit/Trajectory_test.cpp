#include "rgbd_core/Trajectory.h"

#include <mrpt/math/TPoint3D.h>

#include <fstream>

#include "TestData.h"

using mrpt::poses::CPose3D;

TEST(Trajectory, TumRoundTripKeepsPoses) {
  const auto dir = hrgbd::test::tempDir("traj_rt");
  hrgbd::Trajectory t{{1305031453.359684, CPose3D(1.0, -2.0, 0.5, 0.3, -0.2, 0.1)},
                      {1305031453.391700, CPose3D(1.1, -2.1, 0.6, 0.35, -0.25, 0.12)}};
  hrgbd::saveTumTrajectory(dir + "/t.txt", t);
  const auto r = hrgbd::loadTumTrajectory(dir + "/t.txt");
  ASSERT_EQ(r.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(r[i].t, t[i].t, 1e-6);
    EXPECT_LT((r[i].pose.getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>() -
               t[i].pose.getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>())
                  .norm(),
              1e-5);
  }
}

TEST(Trajectory, MalformedLineIsReportedWithFileAndLine) {
  const auto dir = hrgbd::test::tempDir("traj_bad");
  std::ofstream(dir + "/t.txt") << "# header\n1 0 0 0 0 0 0 1\n2 0 0 zero 0 0 0 1\n";
  try {
    hrgbd::loadTumTrajectory(dir + "/t.txt");
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("line 3"), std::string::npos) << e.what();
  }
  std::ofstream(dir + "/q.txt") << "1 0 0 0 0 0 0 0\n";
  EXPECT_THROW(hrgbd::loadTumTrajectory(dir + "/q.txt"), std::runtime_error);
}

TEST(Trajectory, HugeAndSmallQuaternionsAreNormalised) {
  // Found by fuzz_tum_list: squaring 1e200 overflowed and MRPT's quaternion assertion threw.
  const auto dir = hrgbd::test::tempDir("traj_q");
  std::ofstream(dir + "/t.txt") << "1 0 0 0 0 0 1e200 1e200\n2 0 0 0 0 0 1e-5 0\n";
  const auto r = hrgbd::loadTumTrajectory(dir + "/t.txt");
  ASSERT_EQ(r.size(), 2u);
  EXPECT_NEAR(r[0].pose.yaw(), M_PI / 2, 1e-9);        // 90 deg about z
  EXPECT_NEAR(std::abs(r[1].pose.yaw()), M_PI, 1e-9);  // 180 deg about z
}

TEST(Trajectory, OpticalAndMrptConventionsAgree) {
  // A camera at (1,2,3) looking along world +x. In the optical convention its z axis is world +x;
  // in MRPT's convention its x axis is world +x. A point 2 m in front must land at (3,2,3).
  const auto mrpt_pose = CPose3D(1, 2, 3, 0, 0, 0);
  const auto optical = hrgbd::mrptToOptical(mrpt_pose);
  const auto in_front_optical = optical.composePoint(mrpt::math::TPoint3D(0, 0, 2));
  EXPECT_NEAR(in_front_optical.x, 3, 1e-12);
  EXPECT_NEAR(in_front_optical.y, 2, 1e-12);
  EXPECT_NEAR(in_front_optical.z, 3, 1e-12);
  // Optical x (right) is MRPT -y (left); optical y (down) is MRPT -z (up).
  const auto right = optical.composePoint(mrpt::math::TPoint3D(1, 0, 0)) - optical.translation();
  const auto down = optical.composePoint(mrpt::math::TPoint3D(0, 1, 0)) - optical.translation();
  EXPECT_NEAR(right.y, -1, 1e-12);
  EXPECT_NEAR(down.z, -1, 1e-12);
  // Round trip both ways.
  const auto back = hrgbd::opticalToMrpt(optical);
  EXPECT_NEAR((back.asVectorVal() - mrpt_pose.asVectorVal()).norm(), 0, 1e-12);
  // And it is the inverse of MRPT's own "cameras coincide" relativePoseIntensityWRTDepth.
  const CPose3D coincide(0, 0, 0, mrpt::DEG2RAD(-90.0), 0, mrpt::DEG2RAD(-90.0));
  const auto I = coincide + hrgbd::mrptFrameInOptical();
  EXPECT_NEAR(I.asVectorVal().norm(), 0, 1e-12);
}

TEST(Trajectory, TimeStampsAreWrittenExactly) {
  // Any finite stamp of a ground truth reads back as itself, not rounded to 9 decimals.
  const auto dir = hrgbd::test::tempDir("traj_stamps");
  const hrgbd::Trajectory t{{-1.0, CPose3D()},
                            {1e-10, CPose3D()},
                            {2.0000000001, CPose3D()},
                            {1305031453.3596, CPose3D()},
                            {1e308, CPose3D()}};
  hrgbd::saveTumTrajectory(dir + "/t.txt", t);
  const auto r = hrgbd::loadTumTrajectory(dir + "/t.txt");
  ASSERT_EQ(r.size(), t.size());
  for (std::size_t i = 0; i < t.size(); ++i) EXPECT_EQ(r[i].t, t[i].t) << i;
  std::ifstream in(dir + "/t.txt");
  std::string header, line;
  std::getline(in, header);
  for (int i = 0; i < 4; ++i) std::getline(in, line);
  EXPECT_EQ(line.rfind("1305031453.3596 ", 0), 0u) << line;  // as TUM writes it
  EXPECT_THROW(hrgbd::saveTumTrajectory("/dev/full", t), std::runtime_error);
}

TEST(Trajectory, RepeatedTimeStampsAreAnErrorWhenAsked) {
  const auto dir = hrgbd::test::tempDir("traj_repeat");
  std::ofstream(dir + "/t.txt") << "# h\n1 0 0 0 0 0 0 1\n2 0 0 0 0 0 0 1\n1.0 1 0 0 0 0 0 1\n";
  EXPECT_EQ(hrgbd::loadTumTrajectory(dir + "/t.txt").size(), 3u);
  try {
    hrgbd::loadTumTrajectory(dir + "/t.txt", true);
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("t.txt' line 4: time stamp 1 was already given on line 2"),
              std::string::npos)
        << e.what();
  }
}

TEST(Trajectory, AByteOrderMarkAtTheStartIsSkippedAndAFolderIsNamed) {
  const auto dir = hrgbd::test::tempDir("traj_bom");
  std::ofstream(dir + "/t.txt") << "\xEF\xBB\xBF"
                                   "1 0 0 0 0 0 0 1\n2 1 0 0 0 0 0 1\n";
  const auto t = hrgbd::loadTumTrajectory(dir + "/t.txt");
  ASSERT_EQ(t.size(), 2u);
  EXPECT_DOUBLE_EQ(t[0].t, 1.0);
  EXPECT_DOUBLE_EQ(t[1].pose.x(), 1.0);
  try {
    hrgbd::loadTumTrajectory(dir);
    FAIL() << "a folder read as an empty trajectory";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("is a folder"), std::string::npos) << e.what();
  }
}

TEST(Trajectory, AKittiPoseFileIsNamedAsSuch) {
  // 12 numbers a line (a 3x4 matrix): its first 8 were read as 't tx ty tz qx qy qz qw', and
  // rgbd-eval said "duplicate time stamps".
  const auto dir = hrgbd::test::tempDir("traj_kitti");
  std::ofstream(dir + "/k.txt") << "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 0.5 0 1 0 0 0 0 1 0.1\n";
  try {
    hrgbd::loadTumTrajectory(dir + "/k.txt", true);
    FAIL() << "a KITTI file read as TUM";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("k.txt' line 1: 12 columns: KITTI format"),
              std::string::npos)
        << e.what();
  }
  std::ofstream(dir + "/n.txt") << "1 0 0 0 0 0 0 1 7\n";
  EXPECT_THROW(hrgbd::loadTumTrajectory(dir + "/n.txt"), std::runtime_error);  // 9 columns
}
