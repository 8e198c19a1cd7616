#pragma once
/** \file Intrinsics.h
 * Pinhole intrinsics of the TUM RGB-D cameras (TUM's published calibration) and helpers. */
#include <mrpt/img/TCamera.h>

#include <string>

namespace hrgbd {

/** Builds a 640x480 TCamera for a named preset:
 *  - "fr1", "fr2", "fr3": TUM's calibration of each Freiburg Kinect (fr1/fr2 with their
 *    plumb_bob distortion coefficients recorded; fr3 images are already undistorted);
 *  - "ros_default": fx = fy = 525, cx = 319.5, cy = 239.5.
 * Throws std::invalid_argument for any other name. */
mrpt::img::TCamera intrinsicsPreset(const std::string& name);

/** A pinhole camera from explicit values [px], no distortion. */
mrpt::img::TCamera pinholeCamera(double fx, double fy, double cx, double cy, unsigned width = 640,
                                 unsigned height = 480);

/** Guesses the preset from a TUM path ("freiburg1", "fr1_", "/fr1/" ...): "fr1", "fr2", "fr3",
 * or "" when nothing in the path says which Freiburg camera took it. The deepest path component
 * that names one wins; "fr" must start a word ("afr1" names none). */
std::string guessTumPreset(const std::string& path);

}  // namespace hrgbd
