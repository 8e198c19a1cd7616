#include "rgbd_eval/Evaluate.h"

#include <mrpt/core/bits_math.h>
#include <mrpt/math/TPoint3D.h>
#include <mrpt/poses/CPose3DQuat.h>
#include <mrpt/tfest/se3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>

#include "rgbd_core/TimeAssociation.h"
#include "rgbd_core/Timestamp.h"

namespace hrgbd {
namespace {

double rotationAngleDeg(const mrpt::poses::CPose3D& p) {
  const auto R = p.getRotationMatrix();
  const double c = std::clamp((R(0, 0) + R(1, 1) + R(2, 2) - 1.0) / 2.0, -1.0, 1.0);
  return mrpt::RAD2DEG(std::acos(c));
}

/** The error of `measured`, a relative pose from `a` to `b`, against the truth's relative pose
 * from `qa` to `qb`: (Q_a^-1 Q_b)^-1 M. */
mrpt::poses::CPose3D relativeError(const mrpt::poses::CPose3D& qa, const mrpt::poses::CPose3D& qb,
                                   const mrpt::poses::CPose3D& measured) {
  return measured - (qb - qa);
}

double rms(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return v.empty() ? 0.0 : std::sqrt(s / v.size());
}

// Relative pose errors over `delta` seconds (TUM evaluate_rpe.py, per second of interval).
void computeRpe(const std::vector<double>& t, const Trajectory& gt, const Trajectory& est,
                double delta, EvalResult& r) {
  const double span = t.back() - t.front();
  r.rpe_delta_used = std::min(delta, span);
  auto& et = r.rpe_trans_error;
  auto& er = r.rpe_rot_error;
  std::size_t j = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    j = std::max(j, i + 1);
    while (j < t.size() && t[j] - t[i] < r.rpe_delta_used - 1e-9) ++j;
    if (j >= t.size()) break;
    const double dt = t[j] - t[i];
    if (dt > 2 * r.rpe_delta_used) continue;  // a gap in the data, not an interval
    const auto e = relativeError(gt[i].pose, gt[j].pose, est[j].pose - est[i].pose);
    r.rpe_t.push_back(t[i]);
    et.push_back(e.translation().norm() / dt);
    er.push_back(rotationAngleDeg(e) / dt);
  }
  r.rpe_pairs = et.size();
  r.rpe_trans = rms(et);
  r.rpe_rot = rms(er);
}

/** Throws unless the estimate has one pose per time stamp: two poses at one time make the
 * association ambiguous and an RPE interval of 0 s. */
void requireUniqueTimes(const Trajectory& estimate) {
  std::vector<double> t;
  for (const auto& p : estimate) t.push_back(p.t);
  std::sort(t.begin(), t.end());
  const auto twice = std::adjacent_find(t.begin(), t.end());
  if (twice != t.end())
    throw std::runtime_error("the estimate has more than one pose at time stamp " +
                             formatSeconds(*twice) + "; it must have one pose per time");
}

/** Throws unless every associated position is within kMaxTrajectoryCoordinate of the origin. */
void requireEvaluablePositions(const Trajectory& traj, const std::string& name) {
  for (const auto& p : traj)
    for (int k = 0; k < 3; ++k)
      if (!(std::abs(p.pose[k]) <= kMaxTrajectoryCoordinate))
        throw std::runtime_error(
            "the " + name + "'s pose at time stamp " + formatSeconds(p.t) +
            " has a coordinate of " + formatSeconds(p.pose[k]) +
            " m; ATE and RPE are computed for coordinates up to 1e9 m " +
            "(beyond, a double's step exceeds 0.1 um and squares lose the figures)");
}

/** Throws unless every figure is finite: no inf or nan is ever reported. */
void requireFinite(const EvalResult& r) {
  const std::pair<const char*, double> figures[] = {{"ATE RMSE", r.ate_rmse},
                                                    {"unaligned ATE", r.ate_mean_unaligned},
                                                    {"RPE translation", r.rpe_trans},
                                                    {"RPE rotation", r.rpe_rot},
                                                    {"end-to-start error", r.end_to_start_trans},
                                                    {"end-to-start rotation", r.end_to_start_rot}};
  for (const auto& [name, value] : figures)
    if (!std::isfinite(value))
      throw std::runtime_error(std::string("the ") + name + " is not finite (" +
                               formatSeconds(value) + "); the trajectories cannot be evaluated");
}

}  // namespace

EvalResult evaluateTrajectory(const Trajectory& ground_truth, const Trajectory& estimate,
                              const EvalParams& params) {
  if (!(params.max_time_difference > 0) || !std::isfinite(params.max_time_difference))
    throw std::invalid_argument("evaluation: max_time_difference must be a number > 0 s");
  if (!(params.rpe_delta > 0) || !std::isfinite(params.rpe_delta))
    throw std::invalid_argument("evaluation: rpe_delta must be a number > 0 s");
  requireUniqueTimes(estimate);
  std::vector<double> tg, te;
  for (const auto& p : ground_truth) tg.push_back(p.t);
  for (const auto& p : estimate) te.push_back(p.t);
  for (const auto& [traj, name] :
       {std::pair{&ground_truth, "ground truth"}, {&estimate, "estimate"}})
    if (traj->empty()) throw std::runtime_error(std::string("the ") + name + " has no pose");
  const auto pairs = associateByTime(te, tg, params.max_time_difference);
  if (pairs.size() < 3)
    throw std::runtime_error("only " + std::to_string(pairs.size()) +
                             " estimated poses lie within " +
                             std::to_string(params.max_time_difference) +
                             " s of a ground-truth pose; at least 3 are needed");
  EvalResult r;
  r.pairs = pairs.size();
  Trajectory gt, est;
  for (const auto& [ie, ig] : pairs) {
    r.t.push_back(estimate[ie].t);
    gt.push_back(ground_truth[ig]);
    est.push_back(estimate[ie]);
  }
  requireEvaluablePositions(gt, "ground truth");
  requireEvaluablePositions(est, "estimate");

  // (1) ATE RMSE after Horn's closed-form alignment of the positions (mrpt::tfest).
  std::vector<mrpt::math::TPoint3D> pg, pe;
  for (std::size_t i = 0; i < gt.size(); ++i) {
    pg.push_back(gt[i].pose.translation());
    pe.push_back(est[i].pose.translation());
  }
  mrpt::poses::CPose3DQuat align;
  double scale = 1;
  if (!mrpt::tfest::se3_l2(pg, pe, align, scale, true))
    throw std::runtime_error("Horn alignment failed (degenerate trajectory)");
  const mrpt::poses::CPose3D S(align);
  for (std::size_t i = 0; i < gt.size(); ++i) {
    TimedPose a{est[i].t, S + est[i].pose};
    r.error_aligned.push_back((a.pose.translation() - gt[i].pose.translation()).norm());
    r.estimate_aligned.push_back(a);
  }
  r.ate_rmse = rms(r.error_aligned);

  // (2) Paper eq. (9)-(10) with S = identity: both trajectories relative to their first pose.
  double sum = 0;
  for (std::size_t i = 0; i < gt.size(); ++i) {
    const auto Q = gt[i].pose - gt[0].pose, P = est[i].pose - est[0].pose;
    sum += (P.translation() - Q.translation()).norm();
  }
  r.ate_mean_unaligned = sum / gt.size();

  // (3) RPE.
  computeRpe(r.t, gt, est, params.rpe_delta, r);

  // (4) End to start: the RPE's error over the single interval first -> last.
  const auto end_error =
      relativeError(gt.front().pose, gt.back().pose, est.back().pose - est.front().pose);
  r.end_to_start_trans = end_error.translation().norm();
  r.end_to_start_rot = rotationAngleDeg(end_error);
  r.ground_truth = gt;
  requireFinite(r);
  return r;
}

std::string toJson(const EvalResult& r) {
  // evaluateTrajectory() gives finite figures only; null stands for "none", never inf or nan.
  auto number = [](double v, const char* format) {
    if (!std::isfinite(v)) return std::string("null");
    char buf[512];
    std::snprintf(buf, sizeof buf, format, v);
    return std::string(buf);
  };
  const bool rpe = r.rpe_pairs > 0;
  return "{\"ate_rmse\": " + number(r.ate_rmse, "%.6f") +
         ", \"ate_mean_unaligned\": " + number(r.ate_mean_unaligned, "%.6f") +
         ", \"rpe_trans\": " + (rpe ? number(r.rpe_trans, "%.6f") : "null") +
         ", \"rpe_rot\": " + (rpe ? number(r.rpe_rot, "%.6f") : "null") +
         ", \"pairs\": " + std::to_string(r.pairs) +
         ", \"rpe_delta\": " + number(r.rpe_delta_used, "%.3f") +
         ", \"rpe_pairs\": " + std::to_string(r.rpe_pairs) +
         ", \"end_to_start_trans\": " + number(r.end_to_start_trans, "%.6f") +
         ", \"end_to_start_rot\": " + number(r.end_to_start_rot, "%.6f") + "}";
}

std::string toText(const EvalResult& r) {
  char buf[768];
  std::snprintf(buf, sizeof(buf),
                "pairs                 %zu\n"
                "ATE RMSE (aligned)    %.4f m\n"
                "ATE mean (unaligned)  %.4f m   (paper eq. 10, relative to the first pose)\n"
                "end-to-start error    %.4f m, %.3f deg (relative pose first -> last)\n",
                r.pairs, r.ate_rmse, r.ate_mean_unaligned, r.end_to_start_trans,
                r.end_to_start_rot);
  std::string out = buf;
  if (r.rpe_pairs == 0) {
    std::snprintf(buf, sizeof(buf),
                  "RPE                   none: no interval of %.2f s without a gap "
                  "(longer than twice that)\n",
                  r.rpe_delta_used);
    return out + buf;
  }
  std::snprintf(buf, sizeof(buf),
                "RPE translation       %.4f m/s (RMSE over %.2f s, %zu intervals)\n"
                "RPE rotation          %.4f deg/s\n",
                r.rpe_trans, r.rpe_delta_used, r.rpe_pairs, r.rpe_rot);
  return out + buf;
}

std::string toJsonArray(const std::vector<std::string>& names,
                        const std::vector<EvalResult>& results) {
  auto quoted = [](const std::string& s) {
    std::string out = "\"";
    for (const unsigned char c : s) {
      if (c == '"' || c == '\\') {
        out += '\\';
        out += static_cast<char>(c);
      } else if (c < 0x20) {
        char buf[8];
        std::snprintf(buf, sizeof buf, "\\u%04x", c);
        out += buf;
      } else {
        out += static_cast<char>(c);
      }
    }
    return out + "\"";
  };
  std::string out = "[";
  for (std::size_t k = 0; k < results.size(); ++k)
    out += std::string(k ? ",\n " : "") + "{\"estimate\": " + quoted(names.at(k)) + ", " +
           toJson(results[k]).substr(1);
  return out + "]\n";
}

std::string toTable(const std::vector<std::string>& names, const std::vector<EvalResult>& results) {
  int width = 8;
  for (const auto& n : names) width = std::max(width, static_cast<int>(n.size()));
  char buf[1024];
  std::snprintf(buf, sizeof buf, "%-*s %7s %12s %12s %10s %12s %10s %12s\n", width, "estimate",
                "pairs", "ATE RMSE [m]", "ATE mean [m]", "RPE [m/s]", "RPE [deg/s]", "e2s [m]",
                "e2s [deg]");
  std::string out = buf;
  for (std::size_t k = 0; k < results.size(); ++k) {
    const auto& r = results[k];
    std::string rpe_t = "-", rpe_r = "-";
    if (r.rpe_pairs > 0) {
      std::snprintf(buf, sizeof buf, "%.4f", r.rpe_trans);
      rpe_t = buf;
      std::snprintf(buf, sizeof buf, "%.4f", r.rpe_rot);
      rpe_r = buf;
    }
    std::snprintf(buf, sizeof buf, "%-*s %7zu %12.4f %12.4f %10s %12s %10.4f %12.3f\n", width,
                  names.at(k).c_str(), r.pairs, r.ate_rmse, r.ate_mean_unaligned, rpe_t.c_str(),
                  rpe_r.c_str(), r.end_to_start_trans, r.end_to_start_rot);
    out += buf;
  }
  return out;
}

RelativeCheck checkRelativePoses(const Trajectory& gt, const std::vector<RelativeMeasurement>& m,
                                 double max_dt) {
  std::vector<TimedPose> sorted = gt;
  std::sort(sorted.begin(), sorted.end(),
            [](const TimedPose& a, const TimedPose& b) { return a.t < b.t; });
  auto nearest = [&](double t) -> const TimedPose* {
    auto it = std::lower_bound(sorted.begin(), sorted.end(), t,
                               [](const TimedPose& p, double v) { return p.t < v; });
    const TimedPose* best = nullptr;
    if (it != sorted.end()) best = &*it;
    if (it != sorted.begin() && (!best || t - std::prev(it)->t < best->t - t))
      best = &*std::prev(it);
    return best && std::abs(best->t - t) <= max_dt ? best : nullptr;
  };
  RelativeCheck out;
  for (const auto& r : m) {
    const auto* a = nearest(r.t_from);
    const auto* b = nearest(r.t_to);
    if (!a || !b) continue;
    const auto err = relativeError(a->pose, b->pose, r.relative);
    ++out.checked;
    out.largest_translation = std::max(out.largest_translation, err.norm());
    out.largest_rotation = std::max(out.largest_rotation, rotationAngleDeg(err));
  }
  return out;
}

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  const auto k = static_cast<std::size_t>(q * (v.size() - 1) + 0.5);
  std::nth_element(v.begin(), v.begin() + k, v.end());
  return v[k];
}

}  // namespace hrgbd
