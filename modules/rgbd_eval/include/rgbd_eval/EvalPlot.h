#pragma once
/** \file EvalPlot.h
 * The evaluation figure, drawn with PLplot: one or more estimates against ground truth. Left,
 * the trajectories in a plane (equal axis scale, ticks in metres, grid, legend); right, over
 * time [s]: the aligned position error [m] (ATE), the RPE translation [m/s] and the RPE rotation
 * [deg/s]. The format follows the file's extension: .png, .svg or .pdf. PLplot draws it (a
 * library, no external program), through its cairo driver (Debian plplot-driver-cairo). */
#include <string>
#include <vector>

#include "rgbd_eval/Evaluate.h"

namespace hrgbd {

/** The plane the trajectories are drawn in; Auto: the two world axes along which the ground
 * truth spreads most (x-y, seen from above, for TUM's motion-capture frame). */
enum class PlotPlane { Auto, XY, XZ, YZ };

/** "auto", "xy", "xz" or "yz"; throws std::invalid_argument naming the value otherwise. */
PlotPlane parsePlotPlane(const std::string& name);

/** One estimate on the figure: its evaluation and its legend entry (e.g. the file stem). */
struct PlotSeries {
  std::string label;
  const EvalResult* result = nullptr;  //!< must outlive the call
};

/** Options of plotEvaluations(). */
struct PlotParams {
  PlotPlane plane = PlotPlane::Auto;
  std::string title;  //!< above the figure ("" = none)
};

/** Throws std::invalid_argument naming `path` and `option` ("--plot") unless `path` ends in
 * .png, .svg or .pdf (any case), or is an existing device or FIFO (written as PNG), and a file
 * can be created there (tried). Apps call it before the work whose result they plot. */
void checkPlotPath(const std::string& path, const std::string& option);

/** Draws every series into `path` (format by extension, checkPlotPath()), written in full or not
 * at all (OutputFile.h). The ground truth drawn is that of the series with the most pairs. Each
 * estimate is aligned to the ground truth on its own (EvalResult::estimate_aligned). Throws
 * std::invalid_argument for no series or a bad path, std::runtime_error naming the file if it
 * cannot be written or PLplot's cairo driver (Debian plplot-driver-cairo) is missing. */
void plotEvaluations(const std::vector<PlotSeries>& series, const std::string& path,
                     const PlotParams& params = {});

/** One estimate, labelled "estimate", plane Auto. */
void plotEvaluation(const EvalResult& r, const std::string& path, const std::string& title = "");

}  // namespace hrgbd
