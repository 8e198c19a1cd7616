// Per-stage timings at 640x480 on one core. Photometric path: two consecutive real fr3/teddy
// frames when ../shared/data is present, else the bundled simulated desk. Geometric path: the
// bundled plain zig-zag (rawlogs/structure_near), where the hybrid method takes it.
// Run: build/benchmarks/odometry_benchmark --benchmark_repetitions=9
//        --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <mrpt/core/bits_math.h>

#include <filesystem>

#include "rgbd_baselines/RansacEstimator.h"
#include "rgbd_io/RawlogSource.h"
#include "rgbd_io/TumSource.h"
#include "rgbd_odometry/DescriptorMatching.h"
#include "rgbd_odometry/GeometricFeatures.h"
#include "rgbd_odometry/Is3dSampling.h"
#include "rgbd_odometry/PlaneIcp.h"
#include "rgbd_odometry/RgbdOdometry.h"
#include "rgbd_odometry/ShotDescriptor.h"

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
// the same frame with fr1's lens distortion: its undistortion (two remaps) is the difference
void BM_PrepareFrameWithLensDistortion(benchmark::State& s) {
  static const auto obs = [] {
    auto o = mrpt::obs::CObservation3DRangeScan::Create(*pair().obs[1]);
    o->cameraParamsIntensity.dist = {0.2624, -0.9531, -0.0054, 0.0026, 1.1633};
    return o;
  }();
  for (auto _ : s) benchmark::DoNotOptimize(prepareRgbdImage(*obs));
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
// A fresh odometry on frame 0 (the reference), then the registration of frame 1.
void twoFrames(benchmark::State& s, const char* method,
               const mrpt::obs::CObservation3DRangeScan::Ptr (&obs)[2], bool dense = true) {
  OdometryParams p;
  p.method = parseMethod(method);
  p.dense.enabled = dense;
  for (auto _ : s) {
    RgbdOdometry odo(p);
    odo.processObservation(*obs[0]);
    benchmark::DoNotOptimize(odo.processObservation(*obs[1]));
  }
  s.SetLabel("two frames: reference + one registration");
}
void BM_WholeFrame(benchmark::State& s) { twoFrames(s, "rgb_only", pair().obs); }
// The same without the dense refinement (the paper's photometric path): the refinement's share.
void BM_WholeFrameSparseOnly(benchmark::State& s) { twoFrames(s, "rgb_only", pair().obs, false); }
void BM_DensePyramid(benchmark::State& s) {
  for (auto _ : s) benchmark::DoNotOptimize(buildDensePyramid(pair().img[1], DenseParams()));
}
// What a tracked frame costs: its derivatives are made only if it becomes a reference.
void BM_DensePyramidWithoutDerivatives(benchmark::State& s) {
  for (auto _ : s) benchmark::DoNotOptimize(buildDensePyramid(pair().img[1], DenseParams(), false));
}
// The refinement of the sparse MSSE estimate (one start).
void BM_DenseRefine(benchmark::State& s) {
  const DenseParams p;
  const auto cur = buildDensePyramid(pair().img[1], p), ref = buildDensePyramid(pair().img[0], p);
  const auto start = estimateMsse(pair().corr, MsseParams()).T;
  DenseResult d;
  for (auto _ : s) benchmark::DoNotOptimize(d = refineDense(cur, ref, {start}, p));
  s.counters["iterations"] = d.iterations;
}
// The sparse estimate and a prediction 1.5 cm / 1.5 deg off it (beyond the 1 cm / 1 deg within
// which the tracker gives no second start) that the refinement brings to the same motion: the
// second start is dropped once a level brings it next to the first, so this costs less than twice
// BM_DenseRefine.
void BM_DenseRefineTwoStartsThatMeet(benchmark::State& s) {
  const DenseParams p;
  const auto cur = buildDensePyramid(pair().img[1], p), ref = buildDensePyramid(pair().img[0], p);
  const auto start = estimateMsse(pair().corr, MsseParams()).T;
  Eigen::Isometry3d prediction = start;
  prediction.translate(Eigen::Vector3d(0.015, 0, 0));
  prediction.rotate(Eigen::AngleAxisd(mrpt::DEG2RAD(1.5), Eigen::Vector3d::UnitY()));
  DenseResult d;
  for (auto _ : s) benchmark::DoNotOptimize(d = refineDense(cur, ref, {start, prediction}, p));
  s.counters["iterations"] = d.iterations;
}
// The same with both frames' rolling shutter undone (30 ms readout at 0.3 m/s, 1 rad/s).
void BM_DenseRefineRollingShutter(benchmark::State& s) {
  const DenseParams p;
  const auto cur = buildDensePyramid(pair().img[1], p), ref = buildDensePyramid(pair().img[0], p);
  ReadoutMotion readout;
  readout << 0.009, 0, 0, 0, 0.03, 0;
  const auto start = estimateMsse(pair().corr, MsseParams()).T;
  DenseResult d;
  for (auto _ : s)
    benchmark::DoNotOptimize(d = refineDense(cur, ref, {start}, p, readout, readout));
  s.counters["iterations"] = d.iterations;
}

// Geometric path (paper III-C to III-G) on two frames of the plain zig-zag.
struct GeometricPair {
  mrpt::obs::CObservation3DRangeScan::Ptr obs[2];
  RgbdImage img[2];
  GeometricFeatures feat[2];
  Correspondences corr;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
};

const GeometricPair& geometricPair() {
  static const GeometricPair p = [] {
    GeometricPair q;
    RawlogSource src(std::string(HRGBD_SOURCE_DIR) + "/rawlogs/structure_near.rawlog");
    for (int i = 0; i < 2; ++i) {
      q.obs[i] = src.next();
      q.img[i] = prepareRgbdImage(*q.obs[i]);
      q.feat[i] = extractGeometricFeatures(q.img[i], GeometricParams());
    }
    const auto& f = q.feat;
    for (const auto& m :
         matchMutual(f[1].features.descriptors, f[0].features.descriptors, cv::NORM_L2, 1.0)
             .matches) {
      q.corr.source.push_back(f[1].features.points[m.source]);
      q.corr.target.push_back(f[0].features.points[m.target]);
    }
    MsseParams msse;
    msse.k_fraction = OdometryParams().geometric_k_fraction;
    q.T = estimateMsse(q.corr, msse).T;
    return q;
  }();
  return p;
}

void BM_Downsample(benchmark::State& s) {
  DownsampledCloud c;
  for (auto _ : s) benchmark::DoNotOptimize(c = downsampleDepth(geometricPair().img[1], {}));
  s.counters["points"] = c.points.size();
}
void BM_Normals(benchmark::State& s) {
  const auto& g = geometricPair().feat[1];
  for (auto _ : s) {
    const PointKdTree tree(g.cloud);
    benchmark::DoNotOptimize(estimateNormals(g.cloud, tree, 3.0 * g.radius));
  }
  s.SetLabel("KD-tree + plane fits");
}
void BM_Is3d(benchmark::State& s) {
  for (auto _ : s) benchmark::DoNotOptimize(sampleIs3d(geometricPair().feat[1].normals, {}));
  s.counters["is3d"] = geometricPair().feat[1].features.size();
}
void BM_Shot(benchmark::State& s) {
  const auto& g = geometricPair().feat[1];
  const auto keys = sampleIs3d(g.normals, {}).indices;
  const PointKdTree tree(g.cloud);
  for (auto _ : s)
    benchmark::DoNotOptimize(computeShot(g.cloud, g.normals, tree, keys, 5.0 * g.radius, 10));
}
void BM_ShotMatching(benchmark::State& s) {
  const auto& f = geometricPair().feat;
  for (auto _ : s)
    benchmark::DoNotOptimize(
        matchMutual(f[1].features.descriptors, f[0].features.descriptors, cv::NORM_L2, 1.0));
  s.counters["matches"] = geometricPair().corr.size();
}
void BM_GeometricMsse(benchmark::State& s) {
  MsseParams msse;
  msse.k_fraction = OdometryParams().geometric_k_fraction;
  for (auto _ : s) benchmark::DoNotOptimize(estimateMsse(geometricPair().corr, msse));
}
void BM_PlaneIcp(benchmark::State& s) {
  const auto& f = geometricPair().feat;
  for (auto _ : s) {
    const PointKdTree tree(f[0].cloud);
    benchmark::DoNotOptimize(refinePointToPlane(f[1].cloud, f[0].cloud, f[0].normals, tree,
                                                geometricPair().T, 10, 0.05));
  }
}
void BM_GeometricFrame(benchmark::State& s) { twoFrames(s, "depth_only", geometricPair().obs); }

BENCHMARK(BM_PrepareFrame)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PrepareFrameWithLensDistortion)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OrbFeatures)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MutualMatching)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Msse)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Ransac)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WholeFrame)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WholeFrameSparseOnly)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DensePyramid)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DensePyramidWithoutDerivatives)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DenseRefine)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DenseRefineTwoStartsThatMeet)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DenseRefineRollingShutter)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Downsample)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Normals)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Is3d)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Shot)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ShotMatching)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GeometricMsse)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlaneIcp)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GeometricFrame)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
