#include "Peers.h"

namespace hrgbd {

std::string checkDepthAgreement(const RgbdImage& cur, const RgbdImage& ref,
                                const Eigen::Isometry3d& T) {
  const auto a = depthAgreement(cur, ref, T, {kDepthAgreementTolerance, 0}, 4);
  if (a.compared > 0 && a.agreeing >= kMinDepthAgreement * a.compared) return "";
  return "the depths do not agree after the estimated motion: " + std::to_string(a.agreeing) +
         " of " + std::to_string(a.compared) + " sampled points within " +
         std::to_string(int(100 * kDepthAgreementTolerance)) +
         " % of the reference depth (at least " + std::to_string(int(100 * kMinDepthAgreement)) +
         " % needed)";
}

}  // namespace hrgbd
