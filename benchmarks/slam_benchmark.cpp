// The SLAM mode's costs beside the tracking: optimising a keyframe graph the size of fr1/rpy's
// (108 keyframes, ~250 loops) and of a longer run, verifying one loop candidate (the tracking's
// registration between two keyframes of the bundled desk sequence, five frames apart), and the
// appearance search: a keyframe's ORB descriptors into words (bundled vocabulary) and its score
// against N older keyframes.
#include <benchmark/benchmark.h>
#include <mrpt/core/bits_math.h>

#include <random>

#include "rgbd_io/RawlogSource.h"
#include "rgbd_odometry/OdometryParams.h"
#include "rgbd_odometry/OrbFeatures.h"
#include "rgbd_odometry/Registration.h"
#include "rgbd_slam/PoseGraph.h"
#include "rgbd_slam/Vocabulary.h"

namespace {

using mrpt::poses::CPose3D;

// A wandering chain of `nodes` keyframes with noisy edges and `loops` loop edges between nodes 3
// to 20 apart.
hrgbd::PoseGraph randomGraph(int nodes, int loops) {
  std::mt19937 rng(1);
  std::normal_distribution<double> n(0, 1);
  std::vector<CPose3D> truth{CPose3D()};
  for (int i = 1; i < nodes; ++i)
    truth.push_back(truth.back() +
                    CPose3D(0.03, 0.01 * n(rng), 0.01 * n(rng), mrpt::DEG2RAD(2.0 * n(rng)), 0, 0));
  auto noisy = [&](const CPose3D& p) {
    return p + CPose3D(0.003 * n(rng), 0.003 * n(rng), 0.003 * n(rng), 0.002 * n(rng),
                       0.002 * n(rng), 0.002 * n(rng));
  };
  const auto info = hrgbd::edgeInformation(0.003, 0.002);
  hrgbd::PoseGraph g;
  CPose3D p;
  for (int i = 0; i < nodes; ++i) {
    g.addNode(p);
    if (i + 1 < nodes) {
      const auto rel = noisy((-truth[i]) + truth[i + 1]);
      p = p + rel;
    }
  }
  for (int i = 0; i + 1 < nodes; ++i)
    g.addEdge({std::size_t(i), std::size_t(i + 1), noisy((-truth[i]) + truth[i + 1]), info, false});
  std::uniform_int_distribution<int> gap(3, 20);
  for (int k = 0; k < loops; ++k) {
    const int to = 20 + k % (nodes - 20), from = to - gap(rng);
    g.addEdge({std::size_t(from), std::size_t(to), noisy((-truth[from]) + truth[to]), info, true});
  }
  return g;
}

void BM_PoseGraphOptimize(benchmark::State& state) {
  const auto g0 = randomGraph(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  for (auto _ : state) {
    auto g = g0;
    const auto r = g.optimize(22.46, 100);
    benchmark::DoNotOptimize(r.iterations);
  }
}
BENCHMARK(BM_PoseGraphOptimize)->Args({108, 250})->Args({500, 1000})->Unit(benchmark::kMillisecond);

void BM_LoopVerification(benchmark::State& state) {
  hrgbd::RawlogSource src(std::string(HRGBD_SOURCE_DIR) + "/rawlogs/desk_near.rawlog");
  std::vector<hrgbd::Frame> frames;
  const hrgbd::OdometryParams params;
  auto reg = hrgbd::makeRegistration(params);
  while (auto obs = src.next()) {
    hrgbd::Frame f;
    f.image = hrgbd::prepareRgbdImage(*obs);
    reg->prepare(f);
    frames.push_back(std::move(f));
  }
  for (auto _ : state) {
    hrgbd::Frame cur = frames[10];
    const auto r = reg->align(cur, frames[5]);
    benchmark::DoNotOptimize(r.T);
  }
}
BENCHMARK(BM_LoopVerification)->Unit(benchmark::kMillisecond);

// ORB descriptors of the bundled rawlog's frames (as the tracker extracts them).
std::vector<cv::Mat> orbOfBundledFrames() {
  hrgbd::RawlogSource src(std::string(HRGBD_SOURCE_DIR) + "/rawlogs/desk_near.rawlog");
  const hrgbd::OdometryParams params;
  std::vector<cv::Mat> out;
  while (auto obs = src.next())
    out.push_back(hrgbd::extractOrbFeatures(hrgbd::prepareRgbdImage(*obs), params.orb).descriptors);
  return out;
}

void BM_BowTransform(benchmark::State& state) {
  const auto v = hrgbd::Vocabulary::load(hrgbd::bundledVocabulary());
  const auto orb = orbOfBundledFrames();
  for (auto _ : state) benchmark::DoNotOptimize(v.transform(orb[0]));
  state.SetLabel(std::to_string(orb[0].rows) + " descriptors, " + std::to_string(v.size()) +
                 " words");
}
BENCHMARK(BM_BowTransform)->Unit(benchmark::kMillisecond);

void BM_AppearanceScores(benchmark::State& state) {
  const auto v = hrgbd::Vocabulary::load(hrgbd::bundledVocabulary());
  const auto orb = orbOfBundledFrames();
  std::vector<hrgbd::BowVector> keyframes;
  for (int i = 0; i < state.range(0); ++i)
    keyframes.push_back(v.transform(orb[static_cast<std::size_t>(i) % orb.size()]));
  for (auto _ : state) {
    double best = 0;
    for (const auto& k : keyframes) best = std::max(best, hrgbd::bowScore(keyframes[0], k));
    benchmark::DoNotOptimize(best);
  }
}
BENCHMARK(BM_AppearanceScores)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
