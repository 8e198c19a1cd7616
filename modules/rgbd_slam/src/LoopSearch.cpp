// The loop search of KeyframeSlam: candidates by position and by appearance, and their
// verification by the tracking's own registration.
#include <mrpt/core/bits_math.h>

#include <algorithm>

#include "SlamCommon.h"
#include "rgbd_slam/KeyframeSlam.h"

namespace hrgbd {

using slam::angleRad;
using slam::fitInformation;
using slam::kLever;
using slam::viewDistance;

namespace {
constexpr std::size_t kReferences = 8;  //!< keyframes kept as references: 3-4 MB each
}  // namespace

std::vector<KeyframeSlam::Candidate> KeyframeSlam::candidates(const Query& q) const {
  const auto sep = static_cast<std::size_t>(m_params.loop_min_separation);
  if (q.node < sep) return {};
  const auto here = m_graph.pose(q.node) + q.in_node;
  std::vector<std::pair<double, std::size_t>> near;  // (view distance, keyframe)
  for (std::size_t j = 0; j + sep <= q.node; ++j) {
    if (!m_keyframes[j]) continue;  // culled: a pose only
    const auto d = (-m_graph.pose(j)) + here;
    const double metres = d.norm(), angle = angleRad(d);
    if (metres <= m_params.loop_search_radius &&
        angle <= mrpt::DEG2RAD(m_params.loop_search_angle_deg))
      near.emplace_back(viewDistance(d), j);
  }
  std::sort(near.begin(), near.end());
  // the nearest views, then the most alike, spread over the sequence: each at least
  // loop_min_separation keyframes from those already chosen
  std::vector<Candidate> out;
  auto take = [&](std::size_t j, bool by_appearance, std::size_t at_most) {
    if (out.size() >= at_most) return;
    if (std::all_of(out.begin(), out.end(), [&](const Candidate& c) {
          return (j > c.keyframe ? j - c.keyframe : c.keyframe - j) >= sep;
        }))
      out.push_back({j, by_appearance});
  };
  const auto spatial = static_cast<std::size_t>(m_params.loop_max_candidates);
  for (const auto& [score, j] : near) take(j, false, spatial);
  // by appearance: only keyframes the graph puts outside the search window (after drift); those
  // inside had their chance by position (more loops over the same views only add correlated
  // errors: fr1/rpy 0.0146 -> 0.0159 m with them)
  std::vector<bool> inside(q.node + 1, false);
  for (const auto& [score, j] : near) inside[j] = true;
  const std::size_t all =
      out.size() + static_cast<std::size_t>(m_params.loop_appearance_candidates);
  for (std::size_t j : alike(q))
    if (!inside[j]) take(j, true, all);
  // a candidate a loop already links with q's node (found from another of its keyframes) is not
  // verified again: another edge over the same views adds work, and little but correlated error
  const auto& linked = m_linked[q.node];
  out.erase(std::remove_if(out.begin(), out.end(),
                           [&](const Candidate& c) {
                             return std::find(linked.begin(), linked.end(), c.keyframe) !=
                                    linked.end();
                           }),
            out.end());
  return out;
}

std::vector<std::size_t> KeyframeSlam::alike(const Query& q) const {
  const auto sep = static_cast<std::size_t>(m_params.loop_min_separation);
  if (q.words.empty() || q.node < sep) return {};
  // DBoW2's normalised score: relative to the keyframe's score with the node before it (a node),
  // or with its node (a keyframe that follows one)
  const double expected = bowScore(q.words, m_words[q.is_node ? q.node - 1 : q.node]);
  if (expected <= 0) return {};
  std::vector<std::pair<double, std::size_t>> scored;
  for (std::size_t j = 0; j + sep <= q.node; ++j) {
    if (!m_keyframes[j]) continue;  // culled: a pose only
    const double s = bowScore(q.words, m_words[j]) / expected;
    if (s >= m_params.loop_min_appearance) scored.emplace_back(-s, j);
  }
  std::sort(scored.begin(), scored.end());
  std::vector<std::size_t> out;
  for (const auto& [s, j] : scored) out.push_back(j);
  return out;
}

std::optional<PoseGraphEdge> KeyframeSlam::verify(const Query& q, std::size_t candidate) {
  // The graph's prediction is a second start of the dense refinement (it wins over a poorer
  // sparse fit: fr1/rpy's largest loop error 8.4 -> 4.7 cm), but a loop needs a sparse fit that
  // succeeded: the refinement from the prediction alone only repeats the graph (such results
  // came back as loops up to 13 cm off on fr1/rpy).
  const mrpt::poses::CPose3D predicted =
      (-m_graph.pose(candidate)) + (m_graph.pose(q.node) + q.in_node);
  Frame& cur = q.frame;  // the worker's own: the guess is set for this attempt only
  cur.guess = toIsometry(predicted);
  const RegistrationResult reg = m_registration->align(cur, reference(candidate));
  cur.guess.reset();
  if (!reg.ok() || !reg.sparse_ok ||
      reg.inliers < static_cast<std::size_t>(m_params.loop_min_inliers))
    return std::nullopt;
  const mrpt::poses::CPose3D measured = toPose(reg.T);
  const auto d = (-predicted) + measured;
  // where the graph puts it, give or take the odometry's drift between the two
  // [m], at most the search radius: beyond that the inliers and the chi-square check decide
  const double path = m_path[q.node] + viewDistance(q.in_node) - m_path[candidate];
  const double drift = std::min(m_params.loop_drift * path, m_params.loop_search_radius);
  if (d.norm() > m_params.loop_max_discrepancy + drift ||
      angleRad(d) > mrpt::DEG2RAD(m_params.loop_max_discrepancy_deg) + drift / kLever)
    return std::nullopt;
  // to q's node: the keyframe's measured pose, back along its place in its node
  return PoseGraphEdge{candidate, q.node, measured + (-q.in_node),
                       fitInformation(m_params, reg.inliers, true), true};
}

Frame& KeyframeSlam::reference(std::size_t id) {
  auto it = std::find_if(m_references.begin(), m_references.end(),
                         [&](const auto& r) { return r.first == id; });
  if (it == m_references.end()) {
    // a copy (sharing the kept images and pyramids, its feature vectors copied) whose pyramids
    // are unpacked (new images) and get their derivatives again
    auto f = std::make_shared<Frame>(*m_keyframes[id]);
    if (f->dense) unpackLevels(*f->dense), addDerivatives(*f->dense, m_odometry.dense);
    m_references.emplace_front(id, std::move(f));
    if (m_references.size() > kReferences) m_references.pop_back();
    return *m_references.front().second;
  }
  if (it != m_references.begin()) std::rotate(m_references.begin(), it, it + 1);
  return *m_references.front().second;
}

}  // namespace hrgbd
