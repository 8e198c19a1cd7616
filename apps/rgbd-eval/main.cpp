// rgbd-eval GROUNDTRUTH ESTIMATE [--json] [--plot FILE.png]: TUM-format trajectory accuracy.
#include <iostream>

#include "rgbd_cli/CommandLine.h"
#include "rgbd_core/JobPaths.h"
#include "rgbd_eval/EvalPlot.h"
#include "rgbd_eval/Evaluate.h"

int main(int argc, char** argv) {
  hrgbd::CommandLine cmd("rgbd-eval",
                         "ATE (aligned RMSE and the paper's unaligned mean) and RPE of a "
                         "TUM-format trajectory against ground truth");
  TCLAP::UnlabeledValueArg<std::string> gt("groundtruth", "ground truth (TUM format)", true, "",
                                           "GROUNDTRUTH", cmd);
  TCLAP::UnlabeledValueArg<std::string> est("estimate", "estimate (TUM format)", true, "",
                                            "ESTIMATE", cmd);
  TCLAP::SwitchArg json("", "json", "print one JSON object", cmd);
  TCLAP::ValueArg<std::string> plot("", "plot", "write a PNG like the paper's Fig. 5", false, "",
                                    "FILE.png", cmd);
  TCLAP::ValueArg<double> max_dt("", "max-dt", "association limit [s], > 0 (0.02)", false, 0.02,
                                 cmd.above(0.0, "SECONDS"), cmd);
  TCLAP::ValueArg<double> delta("", "rpe-delta", "RPE interval [s], > 0 (1.0)", false, 1.0,
                                cmd.above(0.0, "SECONDS"), cmd);
  return cmd.run(argc, argv, [&] {
    hrgbd::checkJobPaths({{gt.getValue(), "the ground truth"}, {est.getValue(), "the estimate"}},
                         {{plot.getValue(), "--plot", false, true}});
    hrgbd::EvalParams p;
    p.max_time_difference = max_dt.getValue();
    p.rpe_delta = delta.getValue();
    // The estimate must have one pose per time (named by file and line); the ground truth may
    // repeat one, as TUM's own fr2/desk file does.
    const auto estimate = hrgbd::loadTumTrajectory(est.getValue(), true);
    const auto ground_truth = hrgbd::loadTumTrajectory(gt.getValue());
    hrgbd::EvalResult r;
    try {
      r = hrgbd::evaluateTrajectory(ground_truth, estimate, p);
    } catch (const std::runtime_error& e) {
      throw std::runtime_error("'" + est.getValue() + "' against '" + gt.getValue() +
                               "': " + e.what());
    }
    std::cout << (json.getValue() ? hrgbd::toJson(r) + "\n" : hrgbd::toText(r));
    if (!plot.getValue().empty()) hrgbd::plotEvaluation(r, plot.getValue(), est.getValue());
  });
}
