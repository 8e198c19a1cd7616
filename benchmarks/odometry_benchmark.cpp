// Per-stage timings of the photometric path at 640x480 on one core. Frames: two consecutive
// real fr3/teddy frames when ../shared/data is present, else the bundled simulated desk.
// Run: build/benchmarks/odometry_benchmark --benchmark_repetitions=9
//        --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <filesystem>

#include "rgbd_io/RawlogSource.h"
#include "rgbd_io/TumSource.h"
#include "rgbd_odometry/DescriptorMatching.h"
#include "rgbd_odometry/RgbdOdometry.h"

namespace {

using namespace hrgbd;

struct Pair {
  mrpt::obs::CObservation3DRangeScan::Ptr obs[2];
  RgbdImage img[2];
  FeatureSet feat[2];
  Correspondences corr;
};

const Pair& pair() {
  static const Pair p = [] {
    Pair q;
    const auto teddy =
        std::string(HRGBD_SOURCE_DIR) + "/../shared/data/real/tum_fr3_teddy_200frames";
    std::unique_ptr<FrameSource> src;
    if (std::filesystem::is_directory(teddy))
      src = std::make_unique<TumSource>(teddy);
    else
      src = std::make_unique<RawlogSource>(std::string(HRGBD_SOURCE_DIR) +
                                           "/rawlogs/desk_near.rawlog");
    std::fprintf(stderr, "frames: %s\n", src->describe().c_str());
    for (int i = 0; i < 2; ++i) {
      q.obs[i] = src->next();
      q.img[i] = prepareRgbdImage(*q.obs[i]);
      q.feat[i] = extractOrbFeatures(q.img[i], OrbParams());
    }
    for (const auto& m :
         matchMutual(q.feat[1].descriptors, q.feat[0].descriptors, cv::NORM_HAMMING, 64).matches) {
      q.corr.source.push_back(q.feat[1].points[m.source]);
      q.corr.target.push_back(q.feat[0].points[m.target]);
    }
    return q;
  }();
  return p;
}

void BM_PrepareFrame(benchmark::State& s) {
  for (auto _ : s) benchmark::DoNotOptimize(prepareRgbdImage(*pair().obs[1]));
}
void BM_OrbFeatures(benchmark::State& s) {
  for (auto _ : s) benchmark::DoNotOptimize(extractOrbFeatures(pair().img[1], OrbParams()));
  s.counters["features"] = pair().feat[1].size();
}
void BM_MutualMatching(benchmark::State& s) {
  for (auto _ : s)
    benchmark::DoNotOptimize(
        matchMutual(pair().feat[1].descriptors, pair().feat[0].descriptors, cv::NORM_HAMMING, 64));
  s.counters["matches"] = pair().corr.size();
}
void BM_Msse(benchmark::State& s) {
  for (auto _ : s) benchmark::DoNotOptimize(estimateMsse(pair().corr, MsseParams()));
}
void BM_Ransac(benchmark::State& s) {  // the baseline estimator, same data, same process
  for (auto _ : s) benchmark::DoNotOptimize(estimateRansac(pair().corr, RansacParams()));
}
void BM_WholeFrame(benchmark::State& s) {
  OdometryParams p;
  p.method = "rgb_only";
  for (auto _ : s) {
    RgbdOdometry odo(p);
    odo.processObservation(*pair().obs[0]);
    benchmark::DoNotOptimize(odo.processObservation(*pair().obs[1]));
  }
  s.SetLabel("two frames: reference + one registration");
}

BENCHMARK(BM_PrepareFrame)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OrbFeatures)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MutualMatching)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Msse)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Ransac)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WholeFrame)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
