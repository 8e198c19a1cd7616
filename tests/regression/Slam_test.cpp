// The SLAM mode on a simulated revisit (the camera pans away and comes back): loops are found,
// each agrees with the exact ground truth, and the outputs carry the optimised poses. Without
// loops, the SLAM mode gives the odometry's trajectory.
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/graphs/CNetworkOfPoses.h>
#include <mrpt/math/CQuaternion.h>
#include <mrpt/poses/CPose3DQuat.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "TestData.h"
#include "rgbd_app/FrameLoop.h"
#include "rgbd_app/Playback.h"
#include "rgbd_app/makeOdometry.h"
#include "rgbd_core/RgbdFrame.h"
#include "rgbd_io/RawlogSource.h"
#include "rgbd_io/openFrameSource.h"
#include "rgbd_sim/Simulator.h"

namespace {

// 50 frames at 30 Hz: the camera orbits 25 deg around a point 1.2 m ahead and back, so the second
// half sees again what the first saw.
std::string revisit(const std::string& dir) {
  const std::string motion = dir + "/pan_motion.txt";
  std::ofstream out(motion);
  const int n = 50;
  // TUM world (z up): the camera looks 30 deg down at a point 1.2 m away and orbits it about the
  // vertical; mrpt's camera convention turns the body frame (x forward) into the optical frame
  const mrpt::poses::CPose3D optical(0, 0, 0, mrpt::DEG2RAD(-90.0), 0, mrpt::DEG2RAD(-90.0));
  const double r = 1.2, pitch = mrpt::DEG2RAD(30.0);
  for (int i = 0; i <= n; ++i) {  // one sample beyond the last frame: the file covers them all
    const double a = mrpt::DEG2RAD(25.0) * std::sin(M_PI * i / n);
    const mrpt::poses::CPose3D body(-r * std::cos(pitch) * std::cos(a),
                                    -r * std::cos(pitch) * std::sin(a), r * std::sin(pitch), a,
                                    pitch, 0);
    const mrpt::poses::CPose3DQuat q(body + optical);
    out << std::fixed << std::setprecision(6) << 1000.0 + i / 30.0 << " " << q.x() << " " << q.y()
        << " " << q.z() << " " << q.quat().x() << " " << q.quat().y() << " " << q.quat().z() << " "
        << q.quat().r() << "\n";
  }
  out.close();
  hrgbd::sim::SimParams p;
  p.scene = "desk";
  p.frames = n;
  p.motion = motion;
  hrgbd::sim::SimOutputs o;
  o.tum_folder = dir + "/revisit";
  hrgbd::sim::simulate(p, o);
  return o.tum_folder;
}

struct Runs {
  std::string dir, folder;
};

const Runs& runs() {
  static const Runs r = [] {
    Runs x;
    x.dir = hrgbd::test::tempDir("slam");
    x.folder = revisit(x.dir);
    return x;
  }();
  return r;
}

// A run named `name` on the revisit; with `ini`, the configuration is that text (written to
// <name>.ini) instead of the project's config.ini.
hrgbd::PlaybackOptions options(const std::string& name, bool slam, const std::string& ini = "") {
  hrgbd::PlaybackOptions o;
  o.config = std::string(HRGBD_SOURCE_DIR) + "/config.ini";
  if (!ini.empty()) {
    o.config = runs().dir + "/" + name + ".ini";
    std::ofstream(o.config) << ini;
  }
  o.input = runs().folder;
  o.trajectory = runs().dir + "/" + name + ".txt";
  o.progress = false;
  o.ini_outputs = false;
  o.slam = slam;
  o.no_slam = !slam;  // [Slam] enabled is true by default, also without config.ini
  return o;
}

}  // namespace

TEST(Slam, SimulatedRevisitClosesCorrectLoops) {
  auto o = options("slam", true);
  o.graph = runs().dir + "/slam.graph";
  o.output_rawlog = runs().dir + "/slam.rawlog";
  o.map_scene = runs().dir + "/slam.3Dscene";
  std::ostringstream log;
  const auto s = hrgbd::runPlayback(o, log);
  ASSERT_TRUE(s.slam);
  ASSERT_TRUE(s.evaluated) << log.str();
  EXPECT_GE(s.slam_stats.loops_accepted, 3u) << log.str();
  // every loop that holds registered the right place: within 3 cm and 2 deg of the exact ground
  // truth (measured: 1.6 cm, 0.9 deg; a false loop is decimetres off)
  ASSERT_GE(s.loop_check.checked, 3u) << log.str();
  EXPECT_LT(s.loop_check.largest_translation, 0.03) << log.str();
  EXPECT_LT(s.loop_check.largest_rotation, 2.0) << log.str();
  EXPECT_LT(s.eval.ate_rmse, 0.01) << log.str();
  // a kept keyframe holds its features and its pyramids' grey and depth, packed (2 + 2 bytes a
  // pixel of 320x240, 160x120 and 80x60: 0.41 MB), not the gradients, normals and textured cells
  // (2.9 MB with them, 0.81 MB unpacked)
  ASSERT_GT(s.slam_stats.keyframes, s.slam_stats.culled);
  const double kept = static_cast<double>(s.slam_stats.kept_bytes) /
                      static_cast<double>(s.slam_stats.keyframes - s.slam_stats.culled);
  EXPECT_GT(kept, 0.4e6);
  EXPECT_LT(kept, 0.6e6);

  // the graph, in MRPT's format, has a node per keyframe and the loop edges
  mrpt::graphs::CNetworkOfPoses3DInf g;
  g.loadFromTextFile(o.graph);
  EXPECT_EQ(g.nodes.size(), s.slam_stats.keyframes);
  EXPECT_EQ(g.edges.size(), g.nodes.size() - 1 + s.loops.size());
  // the rawlog carries the optimised poses
  hrgbd::RawlogSource back(o.output_rawlog);
  std::size_t n = 0;
  while (auto obs = back.next()) {
    ASSERT_LT(n, s.results.size());
    EXPECT_LT(
        (hrgbd::mrptWorldToOptical(obs->sensorPose).asVectorVal() - s.results[n].pose.asVectorVal())
            .norm(),
        1e-6)
        << "frame " << n;
    ++n;
  }
  EXPECT_EQ(n, s.frames);
}

TEST(Slam, ANodePerNodeSpacingEveryKeyframeSearchedOptimisedWhenTheGraphDisagrees) {
  // the default: a node per 0.2 m of view, every keyframe of the tracker searched for loops, the
  // graph optimised only when it disagrees with a loop, nodes that a loop ties to a kept node
  // within 0.1 m culled; against every keyframe a node, optimised after every loop: fewer nodes
  // and optimisations, the loops as right, the trajectory as good
  std::ostringstream log;
  const auto all = hrgbd::runPlayback(
      options("all_nodes", true, "[Slam]\nnode_spacing = 0\noptimize_min_chi2 = 0\n"), log);
  const auto spaced = hrgbd::runPlayback(options("spaced", true), log);
  for (const auto* s : {&all, &spaced}) {
    const auto& st = s->slam_stats;
    const auto keyframes = static_cast<std::size_t>(std::count_if(
        s->results.begin(), s->results.end(), [](const auto& r) { return r.keyframe; }));
    EXPECT_EQ(st.tracker_keyframes, keyframes);
    EXPECT_EQ(st.work.size() + st.searches_skipped, keyframes) << log.str();
    std::size_t nodes = 0, with_loops = 0, optimised = 0;
    for (const auto& w : st.work) {
      nodes += w.node;
      with_loops += w.accepted > 0;
      optimised += w.optimized;
    }
    EXPECT_EQ(nodes, st.keyframes);
    EXPECT_GE(st.loops_accepted, 3u) << log.str();
    ASSERT_GE(s->loop_check.checked, 3u) << log.str();
    EXPECT_LT(s->loop_check.largest_translation, 0.03) << log.str();
    EXPECT_LT(s->eval.ate_rmse, 0.01) << log.str();
    if (s == &all) {
      EXPECT_EQ(st.keyframes, keyframes);
      EXPECT_EQ(optimised, with_loops);
      EXPECT_EQ(st.culled, 0u);  // node_spacing 0: nothing is near enough to be culled
    } else {
      EXPECT_LT(st.keyframes, keyframes * 3 / 4) << log.str();
      EXPECT_LT(optimised, with_loops) << log.str();
      // the way back sees the way out again: some of its nodes are culled, poses only
      EXPECT_GT(st.culled, 0u) << log.str();
      EXPECT_LT(st.culled, st.keyframes / 2) << log.str();
    }
  }
}

TEST(Slam, WithoutLoopsItIsTheOdometry) {
  // the SLAM mode with its loop search off (by position and by appearance): a chain of keyframes,
  // frames following them
  const std::string ini = "[Slam]\nloop_max_candidates = 0\nloop_appearance_candidates = 0\n";
  std::ostringstream log;
  const auto odometry = hrgbd::runPlayback(options("odometry", false, ini), log);
  const auto slam = hrgbd::runPlayback(options("no_loops", true, ini), log);
  ASSERT_EQ(slam.results.size(), odometry.results.size());
  EXPECT_EQ(slam.slam_stats.loops_accepted, 0u);
  EXPECT_GT(slam.slam_stats.keyframes, 3u);
  for (std::size_t i = 0; i < slam.results.size(); ++i)
    EXPECT_LT((slam.results[i].pose.asVectorVal() - odometry.results[i].pose.asVectorVal()).norm(),
              1e-4)  // OpenCV's threaded sums vary the tracking itself by ~1e-5 between runs
        << "frame " << i;
}

TEST(Slam, AppearanceFindsLoopsWhereThePositionSearchDoesNot) {
  // a search window of 1 mm: no keyframe is near enough by position, as after a long drift; the
  // bundled vocabulary finds the revisited views, and their loops are right
  std::ostringstream log;
  const auto s =
      hrgbd::runPlayback(options("appearance", true, "[Slam]\nloop_search_radius = 0.001\n"), log);
  EXPECT_GE(s.slam_stats.appearance_loops, 2u) << log.str();
  EXPECT_EQ(s.slam_stats.appearance_loops, s.slam_stats.loops_accepted) << log.str();
  ASSERT_GE(s.loop_check.checked, 2u) << log.str();
  EXPECT_LT(s.loop_check.largest_translation, 0.03) << log.str();
  EXPECT_LT(s.loop_check.largest_rotation, 2.0) << log.str();
  // without a vocabulary, nothing
  const auto none = hrgbd::runPlayback(
      options("no_vocabulary", true, "[Slam]\nloop_search_radius = 0.001\nvocabulary =\n"), log);
  EXPECT_EQ(none.slam_stats.loops_accepted, 0u);
  EXPECT_EQ(none.slam_stats.candidates, 0u);
}

TEST(Slam, ABoundedBacklogKeepsEveryKeyframesLoopSearch) {
  // the first 25 frames, every one a keyframe: the loop search falls behind the tracking (the
  // backlog reached 9 keyframes without a bound). With one keyframe at most waiting, the tracking
  // waits for it instead of piling keyframes up, and every keyframe is still searched (measured:
  // the same 57 loops and ATE with and without the bound)
  auto o = options("backlog", true,
                   "[Odometry]\nkeyframe_max_translation = 0.001\n[Slam]\nmax_backlog = "
                   "1\nnode_spacing = 0\n");
  o.max_frames = 25;
  std::ostringstream log;
  const auto s = hrgbd::runPlayback(o, log);
  EXPECT_EQ(s.slam_stats.largest_backlog, 1u) << log.str();
  // (the tracking's waits are not asserted: they depend on the two threads' speeds; measured 16)
  // every keyframe of the tracking is a node of the graph
  const auto keyframes =
      std::count_if(s.results.begin(), s.results.end(), [](const auto& r) { return r.keyframe; });
  EXPECT_GT(keyframes, 20);
  EXPECT_EQ(s.slam_stats.keyframes, static_cast<std::size_t>(keyframes));
  EXPECT_GE(s.slam_stats.loops_accepted, 3u) << log.str();
  ASSERT_GE(s.loop_check.checked, 3u) << log.str();
  EXPECT_LT(s.loop_check.largest_translation, 0.03) << log.str();
  EXPECT_LT(s.eval.ate_rmse, 0.01) << log.str();
  // a kept keyframe holds its features and its pyramids' grey and depth, packed (2 + 2 bytes a
  // pixel of 320x240, 160x120 and 80x60: 0.41 MB), not the gradients, normals and textured cells
  // (2.9 MB with them, 0.81 MB unpacked)
  ASSERT_GT(s.slam_stats.keyframes, s.slam_stats.culled);
  const double kept = static_cast<double>(s.slam_stats.kept_bytes) /
                      static_cast<double>(s.slam_stats.keyframes - s.slam_stats.culled);
  EXPECT_GT(kept, 0.4e6);
  EXPECT_LT(kept, 0.6e6);
}

TEST(Slam, LiveTheTrackingNeverWaitsForTheLoopSearch) {
  // the same keyframe flood with the back end live (as behind a sensor), but read as fast as
  // the tracking goes, so that no timing decides what is tracked: where the offline run waited
  // (16 times measured), a keyframe that finds the backlog full joins the graph unsearched
  mrpt::config::CConfigFileMemory cfg;
  cfg.write("Odometry", "keyframe_max_translation", "0.001");
  cfg.write("Slam", "max_backlog", "1");
  cfg.write("Slam", "node_spacing", "0");
  hrgbd::OdometryParams odometry;
  odometry.loadFromConfigFile(cfg, "Odometry");
  const auto slam = hrgbd::loadSlamParams(cfg, HRGBD_SOURCE_DIR, odometry.method, true, false);
  auto source = hrgbd::openFrameSource(runs().folder, cfg);
  hrgbd::FrameLoop loop(*source, hrgbd::makeOdometry(odometry, cfg), {}, 25);
  loop.setSlam(std::make_unique<hrgbd::KeyframeSlam>(slam, odometry, true));
  loop.run();
  std::ostringstream log;
  loop.finish(log);
  const auto s = loop.slam()->stats();
  EXPECT_EQ(s.backlog_waits, 0u) << log.str();
  EXPECT_EQ(s.waited_ms, 0.0);
  // every frame a keyframe, each a node; the first is always searched (nothing waits before it)
  EXPECT_GT(s.keyframes, 20u) << log.str();
  EXPECT_LT(s.searches_skipped, s.keyframes) << log.str();
}

TEST(Slam, AKeyframeTakenAfterFailuresIsANodeThatLoopsPlace) {
  // steps over 1.5 cm from the keyframe are flagged, and after two flagged frames in a row the
  // tracker takes a flagged frame as its keyframe, at a predicted pose: such keyframes are nodes
  // too, joined to the one before by a weak edge, and the loops place them
  const std::string ini = "[Odometry]\nmax_step_translation = 0.015\nkeyframe_after_failures = 2\n";
  auto o = options("after_failures", true, ini);
  o.graph = runs().dir + "/after_failures.graph";
  std::ostringstream log;
  const auto s = hrgbd::runPlayback(o, log);
  ASSERT_TRUE(s.evaluated) << log.str();
  const auto keyframes =
      std::count_if(s.results.begin(), s.results.end(), [](const auto& r) { return r.keyframe; });
  const auto flagged_keyframes =
      std::count_if(s.results.begin(), s.results.end(),
                    [](const auto& r) { return r.keyframe && !r.registered(); });
  EXPECT_GE(flagged_keyframes, 2) << log.str();
  // every flagged keyframe is a node, whatever node_spacing (0.2 m here)
  const auto nodes =
      std::count_if(s.results.begin(), s.results.end(), [](const auto& r) { return r.node; });
  for (const auto& r : s.results) {
    if (r.keyframe && !r.registered()) {
      EXPECT_TRUE(r.node);
    }
  }
  EXPECT_EQ(s.slam_stats.keyframes, static_cast<std::size_t>(nodes));
  EXPECT_EQ(s.slam_stats.tracker_keyframes, static_cast<std::size_t>(keyframes));
  mrpt::graphs::CNetworkOfPoses3DInf g;
  g.loadFromTextFile(o.graph);
  EXPECT_EQ(g.nodes.size(), s.slam_stats.keyframes);
  EXPECT_EQ(g.edges.size(), g.nodes.size() - 1 + s.loops.size());
  // the edge into a flagged keyframe is the weak one (0.5 m: information 4 on translation, less
  // the little the keyframes chained before it add), into a registered one the chained fits'
  // (1 cm each on 100 inliers)
  std::size_t node = 0;
  for (const auto& r : s.results) {
    if (!r.node) continue;
    if (node > 0) {
      const auto edge = g.edges.find({node - 1, node});
      ASSERT_NE(edge, g.edges.end()) << "node " << node;
      if (r.registered())
        EXPECT_GT(edge->second.cov_inv(0, 0), 100.0) << "node " << node;
      else
        EXPECT_NEAR(edge->second.cov_inv(0, 0), 4.0, 0.05) << "node " << node;
    }
    ++node;
  }
  EXPECT_GE(s.slam_stats.loops_accepted, 1u) << log.str();
  for (const auto& r : s.results)
    for (double v : r.pose.asVectorVal()) ASSERT_TRUE(std::isfinite(v));
  // 11 of 50 frames registered; the odometry chains the predictions (ATE 0.12 m), the loops
  // place the keyframes (measured 0.010 m)
  const auto odometry = hrgbd::runPlayback(options("after_failures_odometry", false, ini), log);
  EXPECT_FALSE(odometry.slam);
  EXPECT_GT(odometry.eval.ate_rmse, 0.05) << log.str();
  EXPECT_LT(s.eval.ate_rmse, 0.02) << log.str();
}
