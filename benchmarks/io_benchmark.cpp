// Reading frames: the bundled desk sequence (20 frames, 640x480) from its rawlog and from the
// same frames written as an OpenNI recording, played through OpenNI2's file driver.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "rgbd_core/RgbdFrame.h"
#include "rgbd_io/OniFileSource.h"
#include "rgbd_io/OniWriter.h"
#include "rgbd_io/RawlogSource.h"

namespace {

const std::string kRawlog = std::string(HRGBD_SOURCE_DIR) + "/rawlogs/desk_near.rawlog";

/** A private temporary folder, removed by main(). */
std::filesystem::path tempFolder() {
  return std::filesystem::temp_directory_path() /
         ("hrgbd_io_benchmark_" + std::to_string(::getpid()));
}

/** The rawlog's frames as a recording in the temporary folder (written once). */
const std::string& recording() {
  static const std::string path = [] {
    std::filesystem::create_directories(tempFolder());
    const auto oni = (tempFolder() / "desk.oni").string();
    hrgbd::RawlogSource src(kRawlog);
    std::unique_ptr<hrgbd::OniWriter> w;
    std::uint32_t i = 0;
    double t0 = 0;
    while (auto obs = src.next()) {
      const auto& c = obs->cameraParamsIntensity;
      if (!w) {
        hrgbd::OniStreamSpec s{static_cast<int>(c.ncols), static_cast<int>(c.nrows),
                               2 * std::atan(0.5 * c.ncols / c.fx()),
                               2 * std::atan(0.5 * c.nrows / c.fy())};
        w = std::make_unique<hrgbd::OniWriter>(oni, s, s);
        t0 = hrgbd::timestampSeconds(*obs);
      }
      cv::Mat mm;
      hrgbd::depthMetres(*obs).convertTo(mm, CV_16UC1, 1000.0);
      const auto us = static_cast<std::uint64_t>((hrgbd::timestampSeconds(*obs) - t0) * 1e6);
      w->writeDepth(us, ++i, mm);
      w->writeColour(us, i, hrgbd::colourBgr(*obs));
    }
    w->close();
    return oni;
  }();
  return path;
}

template <class Source>
void readAll(benchmark::State& s, const std::string& path) {
  std::size_t frames = 0;
  for (auto _ : s) {
    Source src(path);
    while (auto obs = src.next()) {
      benchmark::DoNotOptimize(obs);
      ++frames;
    }
  }
  s.counters["frames/s"] =
      benchmark::Counter(static_cast<double>(frames), benchmark::Counter::kIsRate);
}

void BM_ReadRawlog(benchmark::State& s) { readAll<hrgbd::RawlogSource>(s, kRawlog); }
void BM_ReadOni(benchmark::State& s) { readAll<hrgbd::OniFileSource>(s, recording()); }

}  // namespace

BENCHMARK(BM_ReadRawlog)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ReadOni)->Unit(benchmark::kMillisecond)->UseRealTime();  // a player thread

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::filesystem::remove_all(tempFolder());
}
