#pragma once
/** \file EvalPlot.h
 * A PNG like the paper's Fig. 5: ground truth vs aligned estimate seen from above with the error
 * segments between associated poses, and the error over time. */
#include <string>

#include "rgbd_eval/Evaluate.h"

namespace hrgbd {

/** Draws `r` into a 1200x560 PNG. "From above" = the two world axes along which the ground truth
 * spreads most (x-y for TUM's motion-capture frame). Writes the file in full or not at all
 * (OutputFile.h); throws std::runtime_error naming it if it cannot. */
void plotEvaluation(const EvalResult& r, const std::string& png_path,
                    const std::string& title = "");

}  // namespace hrgbd
