// The SLAM mode's costs beside the tracking: optimising a keyframe graph the size of fr1/rpy's
// (108 keyframes, ~250 loops) and of a longer run, and verifying one loop candidate (the tracking's
// registration between two keyframes of the bundled desk sequence, five frames apart).
#include <benchmark/benchmark.h>
#include <mrpt/core/bits_math.h>

#include <random>

#include "rgbd_io/RawlogSource.h"
#include "rgbd_odometry/OdometryParams.h"
#include "rgbd_odometry/Registration.h"
#include "rgbd_slam/PoseGraph.h"

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

}  // namespace

BENCHMARK_MAIN();
