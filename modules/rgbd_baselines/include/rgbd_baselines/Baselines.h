#pragma once
/** \file Baselines.h
 * The methods the paper compares against (Tables I-II: ORB + RANSAC, ORB + RANSAC + ICP) and
 * OpenCV contrib's dense odometries as peers, as registrations for the tracker, fed the same
 * prepared frames as the product's own. */
#include <memory>

#include "rgbd_baselines/IcpRefine.h"
#include "rgbd_baselines/RansacEstimator.h"
#include "rgbd_core/Params.h"
#include "rgbd_odometry/OdometryParams.h"
#include "rgbd_odometry/Registration.h"

namespace hrgbd {

/** Parameters of the baselines: INI sections [RANSAC] and [ICP]. They have no keys of their
 * own; load and save them with kSection, a name no INI file uses. */
struct BaselineParams : public Params<BaselineParams> {
  static constexpr const char* kSection = "Baselines";
  RansacParams ransac;  //!< section [RANSAC]
  IcpParams icp;        //!< section [ICP]

  template <class P, class V>
  static void declare(P& p, V& v) {
    v.section(p.ransac, "RANSAC");
    v.section(p.icp, "ICP");
  }
};

/** Registration for any `odometry.method`: the product's (makeRegistration()), ORB + RANSAC,
 * ORB + RANSAC + ICP, or an OpenCV peer. */
std::unique_ptr<Registration> makeAnyRegistration(const OdometryParams& odometry,
                                                  const BaselineParams& baselines);

}  // namespace hrgbd
