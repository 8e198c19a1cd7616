#pragma once
/** \file Evaluate.h
 * Trajectory accuracy as the TUM RGB-D benchmark and the paper (section IV-A) measure it. */
#include <cstddef>
#include <string>
#include <vector>

#include "rgbd_core/Trajectory.h"

namespace hrgbd {

/** Parameters of evaluateTrajectory(). */
struct EvalParams {
  double max_time_difference = 0.02;  //!< [s] estimate/ground-truth association limit
  double rpe_delta = 1.0;             //!< [s] RPE interval (shortened to the span if longer)
};

/** Accuracy figures. Positions in metres, rates per second. */
struct EvalResult {
  std::size_t pairs = 0;          //!< associated (estimate, ground truth) poses
  double ate_rmse = 0;            //!< [m] ATE RMSE after rigid Horn alignment (TUM tool)
  double ate_mean_unaligned = 0;  //!< [m] paper eq. (10), both relative to their first pose
  double rpe_trans = 0;           //!< [m/s] RPE translation RMSE over rpe_delta_used
  double rpe_rot = 0;             //!< [deg/s] RPE rotation RMSE over rpe_delta_used
  double rpe_delta_used = 0;      //!< [s] interval actually used for RPE
  std::size_t rpe_pairs = 0;      //!< intervals that entered the RPE
  /** Error of the relative pose from the first associated pose to the last: the drift over the
   * whole run. On a camera path that returns to its start it is the loop-closure error. */
  double end_to_start_trans = 0;  //!< [m]
  double end_to_start_rot = 0;    //!< [deg]
  // Per associated pose, for plots: time, ground truth, aligned estimate, aligned error.
  std::vector<double> t;
  Trajectory ground_truth, estimate_aligned;
  std::vector<double> error_aligned;  //!< [m]
  // Per RPE interval, for plots: start time, translation and rotation error per second.
  std::vector<double> rpe_t;            //!< [s] time stamp at the interval's start
  std::vector<double> rpe_trans_error;  //!< [m/s]
  std::vector<double> rpe_rot_error;    //!< [deg/s]
};

/** Associates `estimate` with `ground_truth` by time stamp and computes the figures, all finite.
 * Throws std::invalid_argument for parameters that are not > 0, and std::runtime_error saying
 * why if fewer than 3 poses associate (the alignment needs 3), if the estimate has two poses at
 * one time stamp (the ground truth may: TUM's fr2/desk file does), if an associated position is
 * beyond kMaxTrajectoryCoordinate, or if a figure would not be finite. When no RPE interval is free
 * of gaps, rpe_pairs is 0 and the RPE figures are not given (toText(), toJson()). */
EvalResult evaluateTrajectory(const Trajectory& ground_truth, const Trajectory& estimate,
                              const EvalParams& params = {});

/** One JSON object with keys ate_rmse, ate_mean_unaligned, rpe_trans, rpe_rot, pairs,
 * rpe_delta, rpe_pairs, end_to_start_trans, end_to_start_rot; always valid JSON: rpe_trans and
 * rpe_rot are null when rpe_pairs is 0, and a figure that is not finite (none from
 * evaluateTrajectory()) is null, never inf or nan. */
std::string toJson(const EvalResult& r);

/** Human-readable summary, one figure per line ("RPE none: ..." when rpe_pairs is 0). */
std::string toText(const EvalResult& r);

/** Several estimates as a JSON array, one toJson() object each with a first key "estimate"
 * (names[k], e.g. the file), in order; ends with a newline. */
std::string toJsonArray(const std::vector<std::string>& names,
                        const std::vector<EvalResult>& results);

/** Several estimates as a text table, a header and one row per estimate (names[k]): pairs, ATE
 * RMSE, unaligned ATE mean [m], RPE translation [m/s] and rotation [deg/s] ("-" when none),
 * end-to-start error [m] and [deg]. */
std::string toTable(const std::vector<std::string>& names, const std::vector<EvalResult>& results);

/** A measured relative pose between two times (a loop closure): `relative` is the pose at
 * `t_to` in the frame of the pose at `t_from`. */
struct RelativeMeasurement {
  double t_from = 0, t_to = 0;  //!< [s]
  mrpt::poses::CPose3D relative;
};

/** How far measured relative poses are from the ground truth's. */
struct RelativeCheck {
  std::size_t checked = 0;         //!< measurements with ground truth at both ends
  double largest_translation = 0;  //!< [m]
  double largest_rotation = 0;     //!< [deg]
};

/** Compares each measurement with the ground truth's relative pose between the ground-truth
 * poses nearest its two times (within `max_time_difference` [s]; others are not checked). */
RelativeCheck checkRelativePoses(const Trajectory& ground_truth,
                                 const std::vector<RelativeMeasurement>& measured,
                                 double max_time_difference = 0.02);

/** The q-quantile (0..1, nearest rank) of `v`; 0 for an empty vector. */
double percentile(std::vector<double> v, double q);

}  // namespace hrgbd
