// The pose graph on MRPT's optimiser: a square closed by one loop returns to its corners, a wrong
// loop among correct ones is dropped, the chi-square is the weighted residual, and the graph is
// saved in MRPT's text format.
#include "rgbd_slam/PoseGraph.h"

#include <gtest/gtest.h>
#include <mrpt/core/bits_math.h>

#include <cstdio>
#include <filesystem>

namespace {

using hrgbd::PoseGraph;
using hrgbd::PoseGraphEdge;
using mrpt::poses::CPose3D;

// The corners of a 1 m square, turning 90 deg left at each, and 3D: a little height and tilt.
std::vector<CPose3D> square() {
  std::vector<CPose3D> out;
  for (int i = 0; i < 4; ++i)
    out.emplace_back(i == 1 || i == 2 ? 1.0 : 0.0, i >= 2 ? 1.0 : 0.0, 0.1 * i,
                     mrpt::DEG2RAD(90.0 * i), mrpt::DEG2RAD(2.0 * i), 0);
  return out;
}

const auto kInfo = hrgbd::edgeInformation(0.01, mrpt::DEG2RAD(0.5));

PoseGraphEdge edge(const std::vector<CPose3D>& truth, std::size_t from, std::size_t to, bool loop,
                   const CPose3D& error = CPose3D()) {
  return {from, to, ((-truth[from]) + truth[to]) + error, kInfo, loop};
}

const CPose3D kDrift(0.02, -0.02, 0.01, mrpt::DEG2RAD(1.0), 0, mrpt::DEG2RAD(-1.0));

// Nodes start on a chain that drifts 2 cm and 1 deg per corner; the odometry edges are exact, or
// drift the same (`biased`).
PoseGraph driftingSquare(const std::vector<CPose3D>& truth, bool biased = false) {
  PoseGraph g;
  CPose3D p = truth[0];
  for (std::size_t i = 0; i < truth.size(); ++i) {
    g.addNode(p);
    if (i + 1 < truth.size()) p = p + ((-truth[i]) + truth[i + 1]) + kDrift;
  }
  for (std::size_t i = 0; i + 1 < truth.size(); ++i)
    g.addEdge(edge(truth, i, i + 1, false, biased ? kDrift : CPose3D()));
  return g;
}

double maxError(const PoseGraph& g, const std::vector<CPose3D>& truth) {
  double worst = 0;
  for (std::size_t i = 0; i < truth.size(); ++i)
    worst = std::max(worst, ((-truth[i]) + g.pose(i)).norm());
  return worst;
}

TEST(PoseGraph, OneLoopReturnsTheSquareToItsCorners) {
  const auto truth = square();
  auto g = driftingSquare(truth);
  ASSERT_GT(maxError(g, truth), 0.04);  // where the nodes start
  g.addEdge(edge(truth, 0, 3, true));
  const auto r = g.optimize(22.46, 100);
  EXPECT_LT(maxError(g, truth), 0.001);
  EXPECT_TRUE(r.dropped.empty());
  EXPECT_EQ(g.activeLoops(), 1u);
  EXPECT_GT(r.iterations, 0u);
}

TEST(PoseGraph, LoopTakesOutMostOfTheOdometrysDrift) {
  const auto truth = square();
  auto chain = driftingSquare(truth, true);
  chain.optimize(22.46, 100);  // the chain alone cannot see its drift
  const double drift = ((-truth[3]) + chain.pose(3)).norm();
  ASSERT_GT(drift, 0.04);
  auto g = driftingSquare(truth, true);
  auto loop = edge(truth, 0, 3, true);
  loop.information = hrgbd::edgeInformation(0.001, mrpt::DEG2RAD(0.05));  // a precise loop
  g.addEdge(loop);
  const auto r = g.optimize(1e9, 100);  // this test is about the loop's effect: never dropped
  EXPECT_LT(((-truth[3]) + g.pose(3)).norm(), 0.1 * drift);
  EXPECT_TRUE(r.dropped.empty());
}

TEST(PoseGraph, AWindowMovesItsNodesOnlyAndHoldsTheRest) {
  // the drifting square with its loop, optimised with nodes 2 and 3 free: 0 and 1 stay exactly
  // where they were; 2 and 3 move onto the corners their edges to the held nodes give (corner 1
  // drifted, so they land 2 cm / 1 deg off it: the window takes its old nodes as they are)
  const auto truth = square();
  auto g = driftingSquare(truth);
  g.addEdge(edge(truth, 0, 3, true));
  const auto held = g.pose(1);
  const double before = ((-truth[3]) + g.pose(3)).norm();
  const auto r = g.optimize(22.46, 100, 2);
  EXPECT_GT(r.iterations, 0u);
  EXPECT_EQ(g.pose(0).asVectorVal(), truth[0].asVectorVal());
  EXPECT_EQ(g.pose(1).asVectorVal(), held.asVectorVal());
  EXPECT_LT(((-truth[3]) + g.pose(3)).norm(), 0.5 * before);
  // the whole graph from there: every corner
  g.optimize(22.46, 100);
  EXPECT_LT(maxError(g, truth), 0.001);
  // a window beyond the last node frees nothing
  EXPECT_EQ(g.optimize(22.46, 100, 4).iterations, 0u);
}

TEST(PoseGraph, WrongLoopAmongCorrectOnesIsDropped) {
  const auto truth = square();
  auto g = driftingSquare(truth);
  g.addEdge(edge(truth, 0, 3, true));
  g.addEdge(edge(truth, 0, 2, true));
  g.addEdge(edge(truth, 1, 3, true, CPose3D(0.4, 0.2, 0, mrpt::DEG2RAD(20), 0, 0)));  // wrong
  const auto r = g.optimize(22.46, 100);
  ASSERT_EQ(r.dropped.size(), 1u);
  EXPECT_EQ(r.dropped[0], 5u);  // the wrong loop, the sixth edge
  EXPECT_FALSE(g.active(5));
  EXPECT_EQ(g.activeLoops(), 2u);
  EXPECT_LT(maxError(g, truth), 0.001);
  EXPECT_LE(r.largest_loop_chi2, 22.46);
}

TEST(PoseGraph, ChiSquareIsTheWeightedResidual) {
  const auto truth = square();
  const auto exact = edge(truth, 0, 1, false);
  EXPECT_NEAR(hrgbd::edgeChi2(exact, truth[0], truth[1]), 0, 1e-9);
  // one sigma (1 cm) off along x of the edge's frame: chi-square 1
  const CPose3D off = truth[1] + CPose3D(0.01, 0, 0, 0, 0, 0);
  EXPECT_NEAR(hrgbd::edgeChi2(exact, truth[0], off), 1.0, 1e-6);
}

TEST(PoseGraph, SavesMrptTextFormat) {
  const auto truth = square();
  auto g = driftingSquare(truth);
  g.addEdge(edge(truth, 0, 3, true));
  const auto path = std::filesystem::temp_directory_path() / "hrgbd_posegraph_test.graph";
  g.save(path.string());
  mrpt::graphs::CNetworkOfPoses3DInf loaded;
  loaded.loadFromTextFile(path.string());
  EXPECT_EQ(loaded.nodes.size(), 4u);
  EXPECT_EQ(loaded.edges.size(), 4u);
  EXPECT_LT(((-loaded.nodes.at(2)) + g.pose(2)).norm(), 1e-4);
  std::filesystem::remove(path);
}

TEST(PoseGraph, EdgeBetweenMissingNodesThrows) {
  PoseGraph g;
  g.addNode(CPose3D());
  EXPECT_THROW(g.addEdge({0, 1, CPose3D(), kInfo, false}), std::invalid_argument);
  EXPECT_THROW(g.addEdge({0, 0, CPose3D(), kInfo, false}), std::invalid_argument);
}

}  // namespace
