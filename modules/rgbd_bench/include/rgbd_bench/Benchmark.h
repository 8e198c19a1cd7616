#pragma once
/** \file Benchmark.h
 * Sequences x methods, as the paper's Tables I-III: every method of RgbdOdometry (ours, the
 * paper's baselines and the peers of OpenCV contrib and Open3D) runs through the same playback on
 * the same frames; the report gives ATE (unaligned mean, the paper's metric, and aligned RMSE),
 * RPE, time per frame, path shares and failures as markdown. `rgbd-benchmark` is a thin main. */
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

#include "rgbd_app/Playback.h"
#include "rgbd_core/Params.h"
#include "rgbd_odometry/OdometryParams.h"
#include "rgbd_sim/Scene.h"

namespace hrgbd {

/** The benchmark's method names: every [Odometry] method, and variants: `hybrid_slam` and
 * `hybrid_odometry` (the SLAM mode on / off, whatever [Slam] says), `hybrid_paper`,
 * `rgb_only_paper` and `depth_only_paper` (the configuration `paper_config`, the paper's pipeline
 * as published), and `hybrid_realtime` (the configuration as it is, played as a sensor at the
 * recorded rate: late frames dropped, PlaybackOptions::realtime). */
std::vector<std::string> benchmarkMethods();

/** INI section [Benchmark]. Lists are separated by spaces; paths are relative to the INI. */
struct BenchmarkParams : public Params<BenchmarkParams> {
  std::vector<std::string> methods{"hybrid",       "rgb_only",     "depth_only", "ransac",
                                   "ransac_icp",   "opencv_rgbd",  "opencv_icp", "opencv_rgbd_icp",
                                   "open3d_color", "open3d_hybrid"};
  /** Simulated suite: these scene types (rgbd_sim::sceneTypes()), each near (~1 m) ... */
  std::vector<std::string> sim_scenes{"texture", "structure", "structure_texture", "desk", "wall"};
  /** ... and also far (~2 m) for texture, structure and structure_texture, as in Table I. */
  bool sim_far = true;
  /** "sweep", "loop" (rgbd_sim::SimParams::motion) and/or TUM ground-truth files whose real
   * hand-held motion is replayed. */
  std::vector<std::string> sim_motions{"sweep"};
  int sim_frames = 30;  //!< [count] frames per simulated sequence (30 Hz)
  int sim_seed = 1;     //!< simulator noise seed
  /** Real sequences: TUM folders or rawlogs with ground truth. Missing ones are reported and
   * skipped (../shared/data is not on every machine). */
  std::vector<std::string> real_sequences;
  int max_frames = 0;                             //!< [count] per run, 0 = all
  std::string cache_folder = "benchmark_cache";   //!< rendered simulated sequences (reused)
  std::string output_folder = "benchmark";        //!< results.md, results.csv, trajectories
  std::string paper_config = "config/paper.ini";  //!< the configuration of `hybrid_paper`

  template <class P, class V>
  static void declare(P& p, V& v) {
    HRGBD_PARAM(methods,
                "any [Odometry] method, hybrid_slam|odometry|paper|realtime, "
                "rgb_only_paper, depth_only_paper",
                OneOf{benchmarkMethods()}, NonEmpty{});
    HRGBD_PARAM(sim_scenes, "scene types, each near (~1 m)", OneOf{sim::sceneTypes()});
    HRGBD_PARAM(sim_far, "also far (~2 m) texture, structure, structure_texture");
    HRGBD_PARAM(sim_motions, "sweep, loop and/or TUM trajectory files to replay");
    HRGBD_PARAM(sim_frames, "[count] frames per simulated sequence (ATE needs 3 poses)",
                Range::atLeast(3));
    HRGBD_PARAM(sim_seed, "simulator noise seed");
    HRGBD_PARAM(real_sequences, "TUM folders or rawlogs with ground truth");
    HRGBD_PARAM(max_frames, "[count] per run, 0 = all", Range::atLeast(0));
    HRGBD_PARAM(cache_folder, "rendered simulated sequences");
    HRGBD_PARAM(output_folder, "results.md, results.csv, trajectories");
    HRGBD_PARAM(paper_config, "configuration of the method hybrid_paper");
  }
};

/** One sequence of the suite. */
struct BenchSequence {
  std::string name;         //!< e.g. "sim/structure_near/sweep", "real/tum_fr1_desk_9frames"
  std::string input;        //!< rawlog or TUM folder
  std::string scene_type;   //!< simulated scene type ("" for real sequences)
  std::string skip_reason;  //!< not empty: the sequence is listed but not run
};

/** One sequence x method run. */
struct BenchRun {
  std::string sequence, method;
  PlaybackSummary summary;
  std::string error;  //!< the run threw: what it said
};

/** The figure of one real sequence: every method's estimate against its ground truth. */
struct BenchFigure {
  std::string sequence;
  std::string file;   //!< relative to [Benchmark] output_folder, e.g. "plots/real_x.png"
  std::string error;  //!< not empty: no figure, and why
};

struct BenchmarkReport {
  std::vector<BenchSequence> sequences;
  std::vector<std::string> methods;
  std::vector<BenchRun> runs;
  std::vector<BenchFigure> figures;  //!< one per real sequence that ran
  std::string config_file, machine, date;
  double seconds = 0;  //!< wall time of the whole benchmark
  /** Not empty: an interrupt stopped the benchmark; what ran ("interrupted (SIGINT) after 7 of
   * 252 runs"). The report then holds the runs finished, and no figures. */
  std::string partial;
};

/** Renders missing simulated sequences into the cache and resolves the real ones; `extra` are
 * further sequences (TUM folders or rawlogs) from the command line. */
std::vector<BenchSequence> prepareSequences(const BenchmarkParams& params,
                                            const std::vector<std::string>& extra,
                                            std::ostream& log);

/** The quick preset (`rgbd-benchmark --quick`), as [Benchmark] keys over the file's: `hybrid`
 * and `opencv_rgbd` on every scene near only, swept, and every real sequence, at most 60 frames
 * a run, into `benchmark_quick` (the full results stay as they are). */
std::map<std::string, std::string> quickBenchmark();

/** Loads [Benchmark] from `config_file` (paths relative to it), prepares the sequences and runs
 * every method on each with runPlayback(), on one thread. Runs that throw are recorded. Each real
 * sequence gets a figure of all methods against its ground truth (plotEvaluations()) in
 * <output_folder>/plots/; one that cannot be drawn is recorded in the report. `log` gets a line
 * per run as it ends ("run 7 of 252: ...; 12 min left"). `progress`: each run shows its progress
 * on stderr (rgbd_core/Progress.h), labelled "run <n>/<count> <sequence> <method>".
 * `overrides`: [Benchmark] keys set over the file's (the command line's), checked alike.
 * Results: <output_folder>/results.md and results.csv. An interrupt (Ctrl-C, SIGTERM:
 * rgbd_core/Interrupt.h) stops the benchmark at the next frame; the runs finished so far are
 * then written to results_partial.md and results_partial.csv, marked partial, and the Interrupted
 * propagates. A benchmark that finishes removes the partial results of an earlier one. */
BenchmarkReport runBenchmark(const std::string& config_file, const std::vector<std::string>& extra,
                             std::ostream& log, bool progress = true,
                             const std::map<std::string, std::string>& overrides = {});

/** The report as markdown: one table per metric, timing, paths, failures, targets, figures. */
std::string toMarkdown(const BenchmarkReport& report);

/** One CSV row per run with every figure. */
std::string toCsv(const BenchmarkReport& report);

}  // namespace hrgbd
