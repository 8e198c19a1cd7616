#include <sstream>

#include "rgbd_bench/Benchmark.h"
#include "rgbd_core/Config.h"
#include "rgbd_odometry/OdometryParams.h"
#include "rgbd_sim/Scene.h"

namespace hrgbd {
namespace {

std::vector<std::string> splitList(const std::string& s) {
  std::vector<std::string> out;
  std::istringstream in(s);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

std::string joinList(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& w : v) s += (s.empty() ? "" : " ") + w;
  return s;
}

}  // namespace

void BenchmarkParams::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                         const std::string& s) {
  rejectUnknownKeys(c, s,
                    {"methods", "sim_scenes", "sim_far", "sim_motions", "sim_frames", "sim_seed",
                     "real_sequences", "max_frames", "cache_folder", "output_folder"});
  auto list = [&](const char* key, std::vector<std::string>& v) {
    if (c.keyExists(s, key)) v = splitList(c.read_string(s, key, ""));
  };
  list("methods", methods);
  list("sim_scenes", sim_scenes);
  list("sim_motions", sim_motions);
  list("real_sequences", real_sequences);
  MRPT_LOAD_CONFIG_VAR_CS(sim_far, bool);
  MRPT_LOAD_CONFIG_VAR_CS(sim_frames, int);
  MRPT_LOAD_CONFIG_VAR_CS(sim_seed, int);
  MRPT_LOAD_CONFIG_VAR_CS(max_frames, int);
  MRPT_LOAD_CONFIG_VAR_CS(cache_folder, string);
  MRPT_LOAD_CONFIG_VAR_CS(output_folder, string);
  for (const auto& m : methods) parseMethod(m);  // throws naming the bad method
  const auto& types = sim::sceneTypes();
  for (const auto& t : sim_scenes)
    if (std::find(types.begin(), types.end(), t) == types.end())
      throw ConfigError("[" + s + "] sim_scenes: unknown scene type '" + t + "'");
  requireValid(sim_frames >= 3, s, "sim_frames", sim_frames, "must be >= 3 (ATE needs 3 poses)");
  requireValid(max_frames >= 0, s, "max_frames", max_frames, "must be >= 0 (0 = all)");
  if (methods.empty()) throw ConfigError("[" + s + "] methods: the list is empty");
}

void BenchmarkParams::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                       const std::string& s) const {
  c.write(s, "methods", joinList(methods));
  c.write(s, "sim_scenes", joinList(sim_scenes));
  MRPT_SAVE_CONFIG_VAR_COMMENT(sim_far, "also far (~2 m) texture, structure, structure_texture");
  c.write(s, "sim_motions", joinList(sim_motions));
  MRPT_SAVE_CONFIG_VAR_COMMENT(sim_frames, "[count] frames per simulated sequence");
  MRPT_SAVE_CONFIG_VAR_COMMENT(sim_seed, "simulator noise seed");
  c.write(s, "real_sequences", joinList(real_sequences));
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_frames, "[count] per run, 0 = all");
  MRPT_SAVE_CONFIG_VAR_COMMENT(cache_folder, "rendered simulated sequences");
  MRPT_SAVE_CONFIG_VAR_COMMENT(output_folder, "results.md, results.csv, trajectories");
}

}  // namespace hrgbd
