// rgbd-eval GROUNDTRUTH ESTIMATE... [--json] [--plot FILE.png|svg|pdf] [--plane auto|xy|xz|yz]:
// TUM-format trajectory accuracy of one or more estimates.
#include <filesystem>
#include <iostream>

#include "rgbd_cli/CommandLine.h"
#include "rgbd_core/JobPaths.h"
#include "rgbd_eval/EvalPlot.h"
#include "rgbd_eval/Evaluate.h"

int main(int argc, char** argv) {
  hrgbd::CommandLine cmd("rgbd-eval",
                         "ATE (aligned RMSE and the paper's unaligned mean) and RPE of TUM-format "
                         "trajectories against ground truth");
  TCLAP::UnlabeledValueArg<std::string> gt("groundtruth", "ground truth (TUM format)", true, "",
                                           "GROUNDTRUTH", cmd);
  TCLAP::UnlabeledMultiArg<std::string> est(
      "estimate", "estimates (TUM format); several: one table row or JSON object each", true,
      "ESTIMATE", cmd);
  TCLAP::SwitchArg json(
      "", "json", "print JSON: one object, or an array of objects for several estimates", cmd);
  TCLAP::ValueArg<std::string> plot(
      "", "plot",
      "write the figure (trajectories, ATE and RPE over time); format by extension: .png, .svg, "
      ".pdf",
      false, "", "FILE", cmd);
  TCLAP::ValueArg<std::string> plane("", "plane", "plane of the trajectory plot (auto)", false,
                                     "auto", cmd.oneOf({"auto", "xy", "xz", "yz"}), cmd);
  TCLAP::ValueArg<double> max_dt("", "max-dt", "association limit [s], > 0 (0.02)", false, 0.02,
                                 cmd.above(0.0, "SECONDS"), cmd);
  TCLAP::ValueArg<double> delta("", "rpe-delta", "RPE interval [s], > 0 (1.0)", false, 1.0,
                                cmd.above(0.0, "SECONDS"), cmd);
  return cmd.run(argc, argv, [&] {
    std::vector<hrgbd::JobPath> inputs{{gt.getValue(), "the ground truth"}};
    for (const auto& e : est.getValue()) inputs.push_back({e, "the estimate"});
    hrgbd::checkJobPaths(inputs, {{plot.getValue(), "--plot", false, true}});
    if (!plot.getValue().empty()) {
      try {
        hrgbd::checkPlotPath(plot.getValue(), "--plot");
      } catch (const std::invalid_argument& e) {
        throw hrgbd::UsageError(e.what());
      }
    }
    hrgbd::EvalParams p;
    p.max_time_difference = max_dt.getValue();
    p.rpe_delta = delta.getValue();
    const auto ground_truth = hrgbd::loadTumTrajectory(gt.getValue());
    std::vector<hrgbd::EvalResult> results;
    for (const auto& e : est.getValue()) {
      // The estimate must have one pose per time (named by file and line); the ground truth may
      // repeat one, as TUM's own fr2/desk file does.
      const auto estimate = hrgbd::loadTumTrajectory(e, true);
      try {
        results.push_back(hrgbd::evaluateTrajectory(ground_truth, estimate, p));
      } catch (const std::runtime_error& ex) {
        throw std::runtime_error("'" + e + "' against '" + gt.getValue() + "': " + ex.what());
      }
    }
    std::vector<hrgbd::PlotSeries> series;
    for (std::size_t k = 0; k < results.size(); ++k)
      series.push_back({std::filesystem::path(est.getValue()[k]).stem().string(), &results[k]});
    if (results.size() == 1)  // the single-estimate output, as it always was
      std::cout << (json.getValue() ? hrgbd::toJson(results[0]) + "\n" : hrgbd::toText(results[0]));
    else
      std::cout << (json.getValue() ? hrgbd::toJsonArray(est.getValue(), results)
                                    : hrgbd::toTable(est.getValue(), results));
    if (!plot.getValue().empty()) {
      hrgbd::PlotParams pp;
      pp.plane = hrgbd::parsePlotPlane(plane.getValue());
      pp.title = results.size() == 1 ? est.getValue()[0] : "against " + gt.getValue();
      hrgbd::plotEvaluations(series, plot.getValue(), pp);
    }
  });
}
