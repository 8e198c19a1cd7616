#pragma once
/** \file ReportParts.h (private to rgbd_bench)
 * The report's shared helpers (Report.cpp) and its time figures: the timing, stage and real-time
 * tables and the speed and real-time target lines (ReportTiming.cpp). */
#include <functional>
#include <optional>
#include <string>

#include "rgbd_bench/Benchmark.h"

namespace hrgbd::report {

using Value = std::function<std::optional<double>(const BenchRun&)>;

const BenchRun* findRun(const BenchmarkReport& r, const std::string& seq, const std::string& m);
/** `field` of a run's evaluation; none when the run failed, was not evaluated, or (RPE) had no
 * interval */
std::optional<double> evaluated(const BenchRun& r, double EvalResult::*field);
/** "-" for none or a non-finite value */
std::string fmt(std::optional<double> v, int precision);
bool isSimulated(const BenchSequence& s);

/** Time per frame over all frames, with each typed path's share and median. */
std::string timingTable(const BenchmarkReport& r);
/** Mean time of each stage over all frames. */
std::string stageTable(const BenchmarkReport& r);
/** hybrid_realtime against hybrid, per sequence. */
std::string realtimeTable(const BenchmarkReport& r);
/** The speed, frame-kind and real-time target lines. */
std::string timeTargets(const BenchmarkReport& r);

}  // namespace hrgbd::report
