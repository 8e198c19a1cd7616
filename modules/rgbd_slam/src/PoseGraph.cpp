#include "rgbd_slam/PoseGraph.h"

#include <mrpt/graphslam/levmarq.h>
#include <mrpt/poses/Lie/SE.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <stdexcept>

#include "rgbd_core/OutputFile.h"
#include "rgbd_core/Timing.h"
#include "rgbd_odometry/RigidFit.h"

namespace hrgbd {

mrpt::math::CMatrixDouble66 edgeInformation(double metres, double radians) {
  mrpt::math::CMatrixDouble66 info;
  info.setZero();
  for (int i = 0; i < 3; ++i) info(i, i) = 1.0 / (metres * metres);
  for (int i = 3; i < 6; ++i) info(i, i) = 1.0 / (radians * radians);
  return info;
}

double edgeChi2(const PoseGraphEdge& e, const mrpt::poses::CPose3D& from,
                const mrpt::poses::CPose3D& to) {
  // the error as the optimiser sees it: log(relative^-1 (+) from^-1 (+) to)
  const mrpt::poses::CPose3D d = (-e.relative) + ((-from) + to);
  const auto err = mrpt::poses::Lie::SE<3>::log(d);
  double chi2 = 0;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) chi2 += err[i] * e.information(i, j) * err[j];
  return chi2;
}

std::size_t PoseGraph::addNode(const mrpt::poses::CPose3D& pose) {
  m_poses.push_back(pose);
  return m_poses.size() - 1;
}

void PoseGraph::addEdge(const PoseGraphEdge& edge) {
  if (edge.from >= m_poses.size() || edge.to >= m_poses.size() || edge.from == edge.to)
    throw std::invalid_argument("PoseGraph: edge between missing or equal nodes");
  m_edges.push_back(edge);
  m_active.push_back(true);
}

std::size_t PoseGraph::activeLoops() const {
  std::size_t n = 0;
  for (std::size_t i = 0; i < m_edges.size(); ++i) n += m_edges[i].loop && m_active[i];
  return n;
}

mrpt::graphs::CNetworkOfPoses3DInf PoseGraph::toMrpt(std::size_t first_free) const {
  mrpt::graphs::CNetworkOfPoses3DInf g;
  g.root = 0;
  // with a window, only the nodes its edges reach (the others would only be copied)
  std::vector<bool> used(m_poses.size(), first_free <= 1);
  for (std::size_t i = 0; i < m_edges.size(); ++i) {
    const auto& e = m_edges[i];
    if (m_active[i] && std::max(e.from, e.to) >= first_free) used[e.from] = used[e.to] = true;
  }
  used[0] = true;
  for (std::size_t i = 0; i < m_poses.size(); ++i)
    if (used[i]) g.nodes[i] = m_poses[i];
  for (std::size_t i = 0; i < m_edges.size(); ++i) {
    const auto& e = m_edges[i];
    if (!m_active[i] || !used[e.from] || !used[e.to]) continue;
    if (first_free > 1 && std::max(e.from, e.to) < first_free) continue;
    g.insertEdge(e.from, e.to, mrpt::poses::CPose3DPDFGaussianInf(e.relative, e.information));
  }
  return g;
}

PoseGraphOptimization PoseGraph::optimize(double max_chi2, int max_iterations,
                                          std::size_t first_free) {
  PoseGraphOptimization out;
  first_free = std::max<std::size_t>(first_free, 1);
  if (first_free >= m_poses.size()) return out;  // nothing free
  // an edge takes part when it touches a free node
  auto touches = [&](const PoseGraphEdge& e) { return std::max(e.from, e.to) >= first_free; };
  std::set<mrpt::graphs::TNodeID> free;
  for (std::size_t i = first_free; i < m_poses.size(); ++i) free.insert(free.end(), i);
  double ms = 0;
  timed(ms, [&] {
    mrpt::containers::yaml extra;
    extra["max_iterations"] = max_iterations;
    for (;;) {
      auto g = toMrpt(first_free);
      mrpt::graphslam::TResultInfoSpaLevMarq info;
      mrpt::graphslam::optimize_graph_spa_levmarq(g, info, first_free > 1 ? &free : nullptr, extra);
      out.iterations += info.num_iters;
      const bool finite = std::all_of(g.nodes.begin(), g.nodes.end(), [](const auto& n) {
        return n.second.asVectorVal().array().isFinite().all();
      });
      if (!finite) {  // diverged: the poses stay as they were, the newest loop goes
        std::size_t newest = m_edges.size();
        for (std::size_t i = 0; i < m_edges.size(); ++i)
          if (m_edges[i].loop && m_active[i] && touches(m_edges[i])) newest = i;
        if (newest == m_edges.size()) break;
        m_active[newest] = false;
        out.dropped.push_back(newest);
        continue;
      }
      // re-orthonormalised: the optimiser's compositions drift off SO(3) by rounding
      for (std::size_t i = first_free; i < m_poses.size(); ++i)
        m_poses[i] = toPose(toIsometry(g.nodes.at(i)));
      // the least consistent loop edge, if beyond the limit, goes; then optimise again
      std::size_t worst = m_edges.size();
      double worst_chi2 = 0;
      for (std::size_t i = 0; i < m_edges.size(); ++i) {
        if (!m_edges[i].loop || !m_active[i] || !touches(m_edges[i])) continue;
        const double c = edgeChi2(m_edges[i], m_poses[m_edges[i].from], m_poses[m_edges[i].to]);
        if (c > worst_chi2) worst_chi2 = c, worst = i;
      }
      if (worst == m_edges.size() || worst_chi2 <= max_chi2) {
        out.largest_loop_chi2 = worst_chi2;
        break;
      }
      m_active[worst] = false;
      out.dropped.push_back(worst);
    }
    return 0;
  });
  out.ms = ms;
  return out;
}

void PoseGraph::save(const std::string& path) const {
  // MRPT's saveToTextFile() checks none of its writes (--graph /dev/full exited 0): the same
  // text through a checked stream
  StreamOutput out(path, "pose graph");
  toMrpt().writeAsText(out.stream());
  out.commit();
}

}  // namespace hrgbd
