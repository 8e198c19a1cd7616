// The playback's MRPT outputs: rawlog with poses, simplemap, coloured map (PLY) and its memory.
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3DPDF.h>

#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>

#include "TestData.h"
#include "rgbd_app/Playback.h"
#include "rgbd_core/RgbdFrame.h"
#include "rgbd_io/RawlogSource.h"
#include "rgbd_map/ColouredMap.h"

namespace {
const std::string kDesk = std::string(HRGBD_SOURCE_DIR) + "/rawlogs/desk_near.rawlog";

double poseDistance(const mrpt::poses::CPose3D& a, const mrpt::poses::CPose3D& b) {
  return (a.asVectorVal() - b.asVectorVal()).norm();
}
}  // namespace

TEST(MapOutputs, RawlogWithPosesRoundTrip) {
  const auto dir = hrgbd::test::tempDir("map_outputs");
  hrgbd::PlaybackOptions o;
  o.config = std::string(HRGBD_SOURCE_DIR) + "/config.ini";
  o.input = kDesk;
  o.trajectory = dir + "/traj.txt";
  o.progress = false;
  o.ini_outputs = false;
  o.output_rawlog = dir + "/out.rawlog";
  o.simplemap = dir + "/out.simplemap";
  o.map_ply = dir + "/map.ply";
  std::ostringstream log;
  const auto s = hrgbd::runPlayback(o, log);
  ASSERT_EQ(s.frames, 20u);

  // Read back with the project's reader: same frames, same time stamps, same poses.
  hrgbd::RawlogSource back(o.output_rawlog);
  std::size_t n = 0;
  while (auto obs = back.next()) {
    ASSERT_LT(n, s.results.size());
    EXPECT_NEAR(hrgbd::timestampSeconds(*obs), s.results[n].t, 1e-6);
    EXPECT_LT(poseDistance(hrgbd::mrptWorldToOptical(obs->sensorPose), s.results[n].pose), 1e-9)
        << "frame " << n;
    EXPECT_TRUE(obs->hasIntensityImage && obs->hasRangeImage) << "frame " << n;
    ++n;
  }
  EXPECT_EQ(n, s.frames);
  // The poses moved: the round trip is not comparing identities.
  EXPECT_GT(s.results.back().pose.norm(), 0.01);

  // MRPT's own rawlog-edit lists the same poses (when mrpt-apps is installed).
  if (std::system("command -v rawlog-edit > /dev/null") == 0) {
    const auto list = dir + "/poses.txt";
    ASSERT_EQ(std::system(("rawlog-edit -q --list-poses -i " + o.output_rawlog +
                           " --text-file-output " + list + " > /dev/null 2>&1")
                              .c_str()),
              0);
    std::ifstream in(list);
    std::string line;
    std::size_t lines = 0;
    while (std::getline(in, line))
      if (!line.empty() && line[0] != '%') ++lines;
    EXPECT_EQ(lines, s.frames);
  }

  // The simplemap holds every frame at its MRPT world pose.
  mrpt::maps::CSimpleMap sm;
  ASSERT_TRUE(sm.loadFromFile(o.simplemap));
  ASSERT_EQ(sm.size(), s.frames);
  const auto& [pdf, sf] = sm.get(s.frames - 1);
  EXPECT_LT(poseDistance(hrgbd::mrptWorldToOptical(pdf->getMeanVal()), s.results.back().pose),
            1e-6);
  EXPECT_EQ(sf->size(), 1u);
  // observations2map inserts the stored point cloud, so it must be there.
  const auto scan = sf->getObservationByClass<mrpt::obs::CObservation3DRangeScan>();
  ASSERT_TRUE(scan);
  EXPECT_TRUE(scan->hasPoints3D);
  EXPECT_GT(scan->points3D_x.size(), 10000u);

  // The PLY holds the map, with colour.
  std::ifstream ply(o.map_ply, std::ios::binary);
  std::string header, line;
  while (std::getline(ply, line) && line != "end_header") header += line + "\n";
  EXPECT_NE(header.find("element vertex " + std::to_string(s.map_points)), std::string::npos);
  EXPECT_NE(header.find("property uchar red"), std::string::npos);
  EXPECT_GT(s.map_points, 5000u);
}

TEST(MapOutputs, MapMemoryStaysBoundedOnALongRun) {
  // 2,000 insertions of the simulated desk frames at their true poses with 1 cm / 0.5 deg of
  // pose noise each time, as a long run revisiting the same place: the voxel decimation must
  // keep the map at the size of the volume seen.
  std::vector<mrpt::obs::CObservation3DRangeScan::Ptr> frames;
  hrgbd::RawlogSource src(kDesk);
  while (auto obs = src.next()) frames.push_back(obs);
  const auto gt = src.groundTruth();
  ASSERT_EQ(gt.size(), frames.size());
  hrgbd::ColouredMap map;
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0, 1);
  std::size_t after_200 = 0, after_1000 = 0;
  for (int i = 0; i < 2000; ++i) {
    const auto k = static_cast<std::size_t>(i) % frames.size();
    const mrpt::poses::CPose3D jitter(0.01 * noise(rng), 0.01 * noise(rng), 0.01 * noise(rng),
                                      0.0087 * noise(rng), 0.0087 * noise(rng),
                                      0.0087 * noise(rng));
    map.insert(*frames[k], (-gt[0].pose) + gt[k].pose + jitter);
    if (i == 199) after_200 = map.size();
    if (i == 999) after_1000 = map.size();
  }
  std::printf("map points after 200, 1000, 2000 insertions: %zu, %zu, %zu\n", after_200, after_1000,
              map.size());
  EXPECT_GT(after_200, 5000u);
  // Unbounded storage would grow by 1,000 frames' points (about 19,000 each) in the second
  // half; the map grows by a few percent, from the tails of the pose noise only.
  EXPECT_LT(map.size(), after_1000 * 11 / 10);
}
