#pragma once
/** \file PoseGraph.h
 * The keyframe pose graph on MRPT's graph tools: nodes are keyframe poses, edges relative poses
 * with an information matrix, optimised by mrpt::graphslam::optimize_graph_spa_levmarq (SPA,
 * Levenberg-Marquardt on the manifold). MRPT's optimiser has no robust kernel, so loop edges are
 * checked for consistency after each optimisation: the loop edge with the largest chi-square
 * beyond `max_chi2` is dropped and the graph optimised again, until every loop agrees. */
#include <mrpt/graphs/CNetworkOfPoses.h>
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/poses/CPose3D.h>

#include <cstddef>
#include <string>
#include <vector>

namespace hrgbd {

/** One constraint: pose(to) = pose(from) (+) relative. */
struct PoseGraphEdge {
  std::size_t from = 0, to = 0;
  mrpt::poses::CPose3D relative;
  mrpt::math::CMatrixDouble66 information;  //!< order x y z, then the rotation vector
  bool loop = false;                        //!< loop edges may be dropped; odometry edges stay
};

/** Information matrix of a relative pose with translation sigma `metres` and rotation sigma
 * `radians` (independent, isotropic). */
mrpt::math::CMatrixDouble66 edgeInformation(double metres, double radians);

/** [chi-square] of `e` for the poses `from` and `to`: the residual's log in SE(3), weighted by
 * its information. */
double edgeChi2(const PoseGraphEdge& e, const mrpt::poses::CPose3D& from,
                const mrpt::poses::CPose3D& to);

struct PoseGraphOptimization {
  std::size_t iterations = 0;        //!< Levenberg-Marquardt iterations, all rounds
  std::vector<std::size_t> dropped;  //!< indices (in edges()) of loop edges found inconsistent
  double largest_loop_chi2 = 0;      //!< of the loop edges kept
  double ms = 0;                     //!< [ms]
};

class PoseGraph {
 public:
  /** Adds node `id` = nodes() with its initial pose; node 0 is the fixed origin. */
  std::size_t addNode(const mrpt::poses::CPose3D& pose);
  void addEdge(const PoseGraphEdge& edge);
  /** Optimises every node from `first_free` on (node 0, the origin, always stays), the others
   * held where they are: only the edges that touch a free node take part, so the cost follows
   * the window, not the graph. Drops inconsistent loop edges (see file comment; among those
   * that touch a free node), each reported once in the result of the optimisation that dropped
   * it. */
  PoseGraphOptimization optimize(double max_chi2, int max_iterations, std::size_t first_free = 1);
  std::size_t nodes() const { return m_poses.size(); }
  const mrpt::poses::CPose3D& pose(std::size_t id) const { return m_poses.at(id); }
  const std::vector<mrpt::poses::CPose3D>& poses() const { return m_poses; }
  const std::vector<PoseGraphEdge>& edges() const { return m_edges; }
  /** Whether edges()[i] takes part (false once dropped). */
  bool active(std::size_t i) const { return m_active.at(i); }
  std::size_t activeLoops() const;
  /** The graph as MRPT's CNetworkOfPoses3DInf (active edges only); with `first_free` > 1, only
   * the edges that touch a node from `first_free` on and the nodes they reach. */
  mrpt::graphs::CNetworkOfPoses3DInf toMrpt(std::size_t first_free = 1) const;
  /** Writes the graph in MRPT's text format (VERTEX_SE3:QUAT / EDGE_SE3:QUAT lines, as
   * CNetworkOfPoses::saveToTextFile() writes and graph-slam loads), in full or not at all;
   * throws naming the file on failure. */
  void save(const std::string& path) const;

 private:
  std::vector<mrpt::poses::CPose3D> m_poses;
  std::vector<PoseGraphEdge> m_edges;
  std::vector<bool> m_active;
};

}  // namespace hrgbd
