#pragma once
/** \file KeyframeSlam.h
 * The SLAM mode over the tracker: the tracker's keyframes, one per [Slam] node_spacing of view,
 * become nodes of the pose graph, linked to the previous node by the tracker's registrations.
 * Each new keyframe of the tracker (a node or not) looks for loops among the nodes near its
 * estimated pose and not yet linked with its node; every candidate goes through the tracking's
 * own registration (sparse MSSE, then the dense refinement when the sparse fit has enough
 * inliers), must register on enough inliers and land near where the graph puts it (allowing
 * for the drift over the path between them), and becomes a loop edge to the keyframe's node.
 * With a vocabulary, the older nodes that look most alike (bag of binary words, Vocabulary.h)
 * are candidates too, wherever the graph puts them. The graph is optimised when it disagrees
 * with an accepted loop (optimize_min_chi2) and at the end, with inconsistent loops dropped
 * (PoseGraph). The loop search and the optimisation run in a background thread (`background`),
 * and the tracker is moved onto the optimised poses when one finishes. Frames between nodes
 * follow their node. */
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "rgbd_odometry/RgbdOdometry.h"
#include "rgbd_slam/PoseGraph.h"
#include "rgbd_slam/SlamParams.h"
#include "rgbd_slam/SlamPoses.h"
#include "rgbd_slam/Vocabulary.h"

namespace hrgbd {

/** What the back end did for one keyframe of the tracker. */
struct KeyframeWork {
  std::size_t frame = 0;       //!< index of the keyframe's frame
  bool node = false;           //!< it became a node of the graph ([Slam] node_spacing)
  std::size_t verified = 0;    //!< loop candidates verified
  std::size_t accepted = 0;    //!< of them: loop edges
  double search_ms = 0;        //!< [ms] the loop search and its verifications
  bool optimized = false;      //!< the graph was optimised after this keyframe's search
  double optimize_ms = 0;      //!< [ms] that optimisation
  std::size_t iterations = 0;  //!< its Levenberg-Marquardt iterations, all rounds
  std::size_t nodes = 0;       //!< the graph's size after this keyframe
  std::size_t edges = 0;
};

/** What the SLAM mode did so far. */
struct SlamStats {
  std::size_t tracker_keyframes = 0;  //!< keyframes the tracker took
  std::size_t keyframes = 0;          //!< of them: nodes of the graph ([Slam] node_spacing)
  /** of the nodes: culled after their loop search (KeyframeSlam::redundant()): poses only */
  std::size_t culled = 0;
  std::size_t candidates = 0;        //!< loop candidates verified
  std::size_t by_appearance = 0;     //!< of them: found by appearance only (not by position)
  std::size_t loops_accepted = 0;    //!< passed verification and became loop edges
  std::size_t appearance_loops = 0;  //!< of them: candidates by appearance only
  std::size_t loops_dropped = 0;     //!< loop edges dropped as inconsistent by the optimisation
  std::size_t optimizations = 0;
  std::size_t largest_backlog = 0;  //!< most keyframes ever waiting for the loop search
  std::size_t backlog_waits = 0;    //!< times the tracking waited for it (max_backlog reached)
  double waited_ms = 0;             //!< [ms] the tracking waited for it, in all
  /** keyframes not searched for loops (max_backlog reached): those that are not nodes, and live
   * nodes too (these are still candidates of later keyframes' searches) */
  std::size_t searches_skipped = 0;
  /** what the kept keyframes hold (images, features, pyramids), counted as each is added; the
   * references made from the last 8 (KeyframeSlam::reference()) come on top, 3-4 MB each */
  std::size_t kept_bytes = 0;
  std::vector<KeyframeWork> work;  //!< per keyframe handed to the back end, in order
  double final_optimize_ms = 0;    //!< [ms] the optimisation of flush()
};

/** "SLAM: N nodes of K keyframes (M MB kept), ... loops ..., search ms median ..., optimisation
 * ms median ...; largest backlog ..., tracking waited ... times (... ms), ... loop searches
 * skipped\n" */
std::string toText(const SlamStats& s);

class KeyframeSlam {
 public:
  /** Loop candidates are verified with makeRegistration(`odometry`): the product's methods only
   * (throws ConfigError for a baseline or peer). Loads `params.vocabulary` (ConfigError naming
   * the key and the fault). With max_backlog keyframes waiting for the background loop search, a
   * new keyframe that is not a node goes unsearched (SlamStats::searches_skipped), and a node
   * takes the place of the oldest waiting keyframe that is not one; with only nodes waiting, a
   * node joins the graph without a loop search of its own when `live` (a sensor, or a recording
   * played as one: the tracking never waits), and otherwise the tracking waits for room, so that
   * every node is searched. */
  KeyframeSlam(const SlamParams& params, const OdometryParams& odometry, bool live = false);
  ~KeyframeSlam();
  KeyframeSlam(const KeyframeSlam&) = delete;
  KeyframeSlam& operator=(const KeyframeSlam&) = delete;

  /** After `tracker` processed a frame (result `r`): keeps the frame's place relative to its
   * keyframe, hands a new keyframe to the loop search, and applies an optimisation that has
   * finished to the tracker; `r.pose` follows. Returns true when the poses changed (an
   * optimisation was applied): poses() then gives the corrected ones. */
  bool add(FrameResult& r, RgbdOdometry& tracker);
  /** Waits for the loop search to finish the keyframes handed to it and optimises. add() and
   * flush() rethrow an exception of the loop search (e.g. out of memory). */
  void flush();
  /** The current estimate of every frame's pose and the loops. */
  SlamPoses poses() const;
  /** Statistics so far (waits for nothing). */
  SlamStats stats() const;
  /** The pose graph (call flush() first for a complete one). */
  const PoseGraph& graph() const { return m_graph; }
  /** Forgets everything (the tracker was reset): the next frame starts a new graph. */
  void reset();

 private:
  struct Job {
    std::size_t id = 0;  //!< the node: this keyframe's, or the one it follows (node = false)
    std::size_t frame_index = 0;
    std::shared_ptr<Frame> frame;
    /** false: a keyframe of the tracker that is not a node (node_spacing): searched for loops,
     * which join its node through `in_node`, then forgotten */
    bool node = true;
    mrpt::poses::CPose3D in_node;  //!< node = false: the keyframe's pose in its node's
    bool first = true;             //!< the first keyframe: no odometry edge
    PoseGraphEdge odometry;        //!< from the previous node
    mrpt::poses::CPose3D pose;     //!< tracker's estimate (the first node only)
    bool search = true;            //!< false: a node and its odometry edge, no loop search
  };
  struct Place {
    std::size_t keyframe;
    mrpt::poses::CPose3D relative;  //!< the frame's pose in its keyframe's
  };
  /** A job for the loop search: the tracker's keyframe (result `r`), a new node or not. */
  void addJob(const FrameResult& r, const RgbdOdometry& tracker, bool node);
  void work();
  void process(Job job);
  /** A keyframe whose loops are searched: a node, or one that follows a node (Job::node). */
  struct Query {
    Frame& frame;
    std::size_t node;                     //!< its node
    bool is_node;                         //!< the node itself
    const mrpt::poses::CPose3D& in_node;  //!< its pose in its node's (identity: the node)
    const BowVector& words;
  };
  struct Candidate {
    std::size_t keyframe;
    bool by_appearance;  //!< not near enough by position
  };
  std::vector<Candidate> candidates(const Query& q) const;
  /** Older keyframes that look like `q`, most alike first. */
  std::vector<std::size_t> alike(const Query& q) const;
  /** The loop edge from `candidate` to q's node, if `q` registers with it and lands near where
   * the graph puts it. */
  std::optional<PoseGraphEdge> verify(const Query& q, std::size_t candidate);
  /** Node `id`, just searched, is redundant: one of its new loops ties it to a kept node less than
   * half node_spacing away in view. Such a node is culled: it keeps its pose and edges (frames
   * follow it, loops link it) but not its features and pyramids, and is no candidate: memory
   * follows the views of the scene, not the time spent in them. */
  bool redundant(std::size_t id) const;
  /** Keyframe `id` ready to be a registration's reference (its pyramids' derivatives made). */
  Frame& reference(std::size_t id);
  void applyOptimization(RgbdOdometry& tracker);
  /** Makes the graph's poses and loops the latest optimisation (under m_mutex). */
  void publish();
  void stopWorker();
  /** Rethrows, in the tracking thread, what the worker failed with. */
  void rethrowWorkerFailure();

  SlamParams m_params;
  bool m_live = false;  //!< the tracking never waits (constructor)
  OdometryParams m_odometry;
  // tracking thread
  std::vector<Place> m_places;                     //!< per frame
  std::vector<mrpt::poses::CPose3D> m_tracker_kf;  //!< node poses as the tracker has them
  std::vector<std::size_t> m_keyframe_frame;       //!< frame index of each node
  /** [m^2] variance of the odometry from the last node to the tracker's keyframe (translation;
   * the tracker's keyframes that were not made nodes, node_spacing) */
  double m_chain_variance = 0;
  std::size_t m_tracker_keyframes = 0;
  std::size_t m_applied = 0;  //!< optimisations applied to the tracker
  // worker (the graph, the keyframes and the registration); m_mutex guards what both touch
  std::unique_ptr<Registration> m_registration;
  std::vector<std::shared_ptr<Frame>> m_keyframes;  //!< per node; null: culled
  /** The last keyframes made references, the most recent first: consecutive keyframes mostly
   * have the same candidates */
  std::deque<std::pair<std::size_t, std::shared_ptr<Frame>>> m_references;
  std::optional<Vocabulary> m_vocabulary;
  std::vector<BowVector> m_words;  //!< per keyframe (empty without ORB features)
  std::vector<double> m_path;      //!< [m] per keyframe: path from the first (+ 1.5 m x angle)
  /** per node: the older nodes a loop edge links it with */
  std::vector<std::vector<std::size_t>> m_linked;
  PoseGraph m_graph;
  mutable std::mutex m_mutex;
  std::condition_variable m_wake, m_idle;
  std::deque<Job> m_queue;
  bool m_busy = false, m_stop = false;
  std::exception_ptr m_failed;  //!< what the worker threw, rethrown by add() and flush()
  std::vector<mrpt::poses::CPose3D> m_optimized;  //!< node poses of the latest optimisation
  std::vector<PoseGraphEdge> m_loops;             //!< its loop edges that hold (keyframe ids)
  std::size_t m_optimizations = 0;
  SlamStats m_stats;
  std::thread m_thread;
};

}  // namespace hrgbd
