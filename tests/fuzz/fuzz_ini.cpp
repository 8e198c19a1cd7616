// Fuzz target: INI loading, as the apps do it. The input is written to a file and loaded as
// `--print-config` (every [Playback], [Odometry] (+ [ORB] [Geometric] [MSSE] [RANSAC] [ICP]),
// [TumSource] and [Map] key) and as rgbd-benchmark's [Benchmark] section. A configuration either
// loads or is refused with hrgbd::ConfigError, whose message names the section and key; any
// other exception or a crash is a bug.
#include "FuzzUtil.h"
#include "rgbd_app/Playback.h"
#include "rgbd_bench/Benchmark.h"
#include "rgbd_core/Config.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  static const auto path = hrgbd::fuzz::tempPath("config.ini");
  hrgbd::fuzz::writeFile(path, data, size);
  try {
    hrgbd::effectiveConfig(path);
  } catch (const hrgbd::ConfigError&) {
  }
  try {
    const auto cfg = hrgbd::loadChecked(path);
    hrgbd::BenchmarkParams bench;
    bench.loadFromConfigFile(*cfg, "Benchmark");
  } catch (const hrgbd::ConfigError&) {
  }
  return 0;
}
