#pragma once
/** \file SlamParams.h
 * Parameters of the SLAM mode. INI section [Slam]. */
#include <string>

#include "rgbd_core/Params.h"

namespace hrgbd {

struct SlamParams : public Params<SlamParams> {
  bool enabled = true;     //!< false: the odometry alone, exactly as the tracker gives it
  bool background = true;  //!< loop search and optimisation in a thread beside the tracking
  /** [keyframes] with this many keyframes waiting for the background loop search, a keyframe
   * of the tracker that is not a node goes unsearched, and a node takes the place of the oldest
   * waiting one that is not; with only nodes waiting, a node makes the tracking wait (memory and
   * delay stay bounded and every node is searched), except live (a sensor, or a recording played
   * as one: KeyframeSlam's `live`), where it joins the graph without a search of its own. */
  int max_backlog = 16;
  /** [m] a keyframe of the tracker becomes a node of the graph when its view is at least this far
   * from the last node's (translation plus rotation over a 1.5 m lever arm); the tracker's
   * keyframes in between chain the odometry edge (their variances add up) and are searched for
   * loops too, which join their node, but are not kept. The tracker keeps its own keyframes
   * (OdometryParams::keyframe_max_translation) as references; what the graph keeps (keyframes,
   * map clouds) and optimises falls with this. A node that a loop ties to a kept node less than
   * half this away in view is culled after its search: a pose and edges only, no candidate, no
   * map cloud (KeyframeSlam::redundant()), so that memory follows the views of the scene. 0:
   * every keyframe of the tracker is a node, none culled; a keyframe taken after failures is
   * always a node. Measured (aligned ATE fr1/rpy, teddy; the 4x
   * fr1/rpy palindrome's nodes of 432 keyframes): 0: 0.0126, 0.0090, 432; 0.1: 0.0132, 0.0090,
   * 349; 0.2: 0.0131, 0.0092; 0.25: 0.0132, 0.0095, 147 */
  double node_spacing = 0.2;
  /** [chi-square] an accepted loop edge optimises the graph only when the graph disagrees with
   * it by more than this (the edge's chi-square at the graph's poses; 12.59: 95 % of chi-square
   * with 6 degrees of freedom); loops the graph already agrees with wait for the next
   * optimisation (the final one includes every edge). 0: every accepted loop optimises (fr1/rpy:
   * 100 optimisations, 12.59: 1, aligned ATE 0.0127 and 0.0126 m). */
  double optimize_min_chi2 = 12.59;
  /** [nodes] an optimisation during the run frees only this many newest nodes, the older held
   * where they are (PoseGraph::optimize's window): its cost follows the window, not the map.
   * A loop the graph disagrees with beyond loop_max_chi2 (a cycle closed after a long drift)
   * optimises the whole graph, as does the final optimisation. 0: always the whole graph. */
  int optimize_window = 50;
  /** [m] keyframes whose estimated position is within this distance of a new keyframe ... */
  double loop_search_radius = 0.6;
  double loop_search_angle_deg = 35;  //!< [deg] ... and whose view is within this rotation
  int loop_max_candidates = 3;        //!< [count] candidates verified per new keyframe
  int loop_min_separation = 3;        //!< [keyframes] candidates at least this far apart in id
  /** [count] a loop needs at least this many sparse inliers (with 40, accepted loops were up to
   * 10 cm off the ground truth in fr1/rpy's fast motion; with 100 at most 4.7 cm, ATE unchanged) */
  int loop_min_inliers = 100;
  /** [m] a verified loop that moves the candidate further than this from where the graph puts it
   * is refused (the registration found another place) ... */
  double loop_max_discrepancy = 0.3;
  double loop_max_discrepancy_deg = 15;  //!< [deg] ... or turns it further than this
  /** [m] standard deviation of an edge's translation registered on 100 inliers (it grows as
   * 1/sqrt(inliers)); the rotation's is this over a 1.5 m lever arm */
  double edge_sigma = 0.01;
  /** a loop edge's sigmas are this many times those of a tracking edge on as many inliers: loops
   * are registered across wider baselines (measured: loop edges up to 2.4 cm off the ground
   * truth with 80+ inliers on the plain structure, 1.6 cm on the simulated desk). Aligned ATE
   * for 1 / 3 / 6: fr1/rpy 0.0191 / 0.0163 / 0.0147, teddy 0.0090 / 0.0085 / 0.0087, plain
   * structure 0.0064 / 0.0061 / 0.0055, cabinet 0.0929 / 0.1026 / 0.1040 m */
  double loop_sigma_factor = 6;
  /** chi-square of a loop edge after optimisation beyond which it is dropped as inconsistent
   * with the others (99.9 % of chi-square with 6 degrees of freedom: 22.46) */
  double loop_max_chi2 = 22.46;
  /** [Dense] geometric_weight of the loops' registration. A depth camera's systematic errors are
   * fixed in its image, so the same surface seen from viewpoints far apart is distorted
   * differently and the point-to-plane term can be biased over a loop's baseline: on a simulated
   * 17 cm / 12 deg pair, weight 1 is 6.2 mm, 0.26 deg off, 0.1 is 1.7 mm, 0.08 deg. On the real
   * frames the term helps: aligned ATE for 1 / 0.3 / 0.1: fr1/rpy 0.0147 / 0.0158 / 0.0169,
   * teddy 0.0087 / 0.0098 / 0.0116 m (the simulated 32 s loop: 0.0089 / 0.0075 / 0.0060). */
  double loop_geometric_weight = 1;
  int optimizer_iterations = 100;  //!< [count] Levenberg-Marquardt iterations per optimisation
  /** ORB vocabulary file (rgbd-vocabulary) for loop candidates by appearance, relative to the
   * INI file's folder; "bundled": the one shipped (bundledVocabulary()), made from the shared
   * real TUM frames; empty: candidates by position only */
  std::string vocabulary = "bundled";
  /** [count] candidates by appearance verified per keyframe, besides those by position: the
   * older keyframes that look most alike (bag-of-words score) ... */
  int loop_appearance_candidates = 2;
  /** ... with a score at least this fraction of the score between the keyframe and the one
   * before it (DBoW2's normalised score) */
  double loop_min_appearance = 0.5;
  /** [m/m] odometry drift allowed for: a verified loop may be loop_max_discrepancy plus this
   * times the path between the two keyframes (at most loop_search_radius) from where the graph
   * puts it (rotation: the same over a 1.5 m lever arm) */
  double loop_drift = 0.05;

  template <class P, class V>
  static void declare(P& p, V& v) {
    HRGBD_PARAM(enabled, "SLAM mode: keyframe pose graph with loop closures");
    HRGBD_PARAM(background, "loop search and optimisation in a background thread");
    HRGBD_PARAM(max_backlog,
                "[keyframes] waiting for the loop search: a keyframe not a node goes "
                "unsearched, a node waits (live: goes unsearched)",
                Range::atLeast(1));
    HRGBD_PARAM(node_spacing, "[m] view distance from the last node for a keyframe to be a node",
                Range::atLeast(0));
    HRGBD_PARAM(optimize_min_chi2, "[chi-square] a loop the graph disagrees with more: optimise",
                Range::atLeast(0));
    HRGBD_PARAM(optimize_window, "[nodes] newest nodes freed by an optimisation (0: all)",
                Range::atLeast(0));
    HRGBD_PARAM(loop_search_radius, "[m] loop candidates: keyframes this near", Range::above(0));
    HRGBD_PARAM(loop_search_angle_deg, "[deg] loop candidates: view within this rotation",
                Range::openClosed(0, 180));
    HRGBD_PARAM(loop_max_candidates, "[count] candidates verified per keyframe", Range::atLeast(0));
    HRGBD_PARAM(loop_min_separation, "[keyframes] candidates at least this far apart",
                Range::atLeast(2));
    HRGBD_PARAM(loop_min_inliers, "[count] sparse inliers a loop needs", Range::atLeast(3));
    HRGBD_PARAM(loop_max_discrepancy, "[m] verified loop further from the graph: refused",
                Range::above(0));
    HRGBD_PARAM(loop_max_discrepancy_deg, "[deg] verified loop turned further: refused",
                Range::openClosed(0, 180));
    HRGBD_PARAM(edge_sigma, "[m] edge translation sigma at 100 inliers", Range::above(0));
    HRGBD_PARAM(loop_sigma_factor, "loop edge sigmas: this times a tracking edge's",
                Range::atLeast(1));
    HRGBD_PARAM(loop_max_chi2, "loop edges beyond this chi-square after optimisation: dropped",
                Range::above(0));
    HRGBD_PARAM(loop_geometric_weight, "[Dense] geometric_weight of loop registrations",
                Range::atLeast(0));
    HRGBD_PARAM(optimizer_iterations, "[count] Levenberg-Marquardt iterations", Range::atLeast(1));
    HRGBD_PARAM(vocabulary, "ORB vocabulary file (bundled|FILE|empty: none) for loop candidates");
    HRGBD_PARAM(loop_appearance_candidates, "[count] candidates by appearance per keyframe",
                Range::atLeast(0));
    HRGBD_PARAM(loop_min_appearance, "appearance score needed, as a fraction of the previous's",
                Range::above(0));
    HRGBD_PARAM(loop_drift, "[m/m] drift allowed for over the path between loop keyframes",
                Range::atLeast(0));
  }
};

}  // namespace hrgbd
