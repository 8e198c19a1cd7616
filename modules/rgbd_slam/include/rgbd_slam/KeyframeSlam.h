#pragma once
/** \file KeyframeSlam.h
 * The SLAM mode over the tracker: every keyframe the tracker makes becomes a node of the pose
 * graph, linked to the previous keyframe by the tracker's registration. Each new keyframe looks
 * for loops among the keyframes near its estimated pose; every candidate goes through the
 * tracking's own registration (sparse MSSE, then the dense refinement), must register on enough
 * inliers and land near where the graph puts it (allowing for the drift over the path between
 * them), and becomes a loop edge. With a vocabulary, the older keyframes that look most alike
 * (bag of binary words, Vocabulary.h) are candidates too, wherever the graph puts them. The graph
 * is optimised after each accepted loop, with inconsistent loops dropped (PoseGraph). The loop
 * search and the optimisation run in a background thread (`background`), and the tracker is moved
 * onto the optimised poses when one finishes. Frames between keyframes follow their keyframe. */
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

/** What the SLAM mode did so far. */
struct SlamStats {
  std::size_t keyframes = 0;
  std::size_t candidates = 0;        //!< loop candidates verified
  std::size_t by_appearance = 0;     //!< of them: found by appearance only (not by position)
  std::size_t loops_accepted = 0;    //!< passed verification and became loop edges
  std::size_t appearance_loops = 0;  //!< of them: candidates by appearance only
  std::size_t loops_dropped = 0;     //!< loop edges dropped as inconsistent by the optimisation
  std::size_t optimizations = 0;
  std::size_t largest_backlog = 0;  //!< most keyframes ever waiting for the loop search
  std::size_t backlog_waits = 0;    //!< times the tracking waited for it (max_backlog reached)
  double waited_ms = 0;             //!< [ms] the tracking waited for it, in all
  /** live: keyframes that joined the graph without a loop search of their own (max_backlog
   * reached; they are still candidates of later keyframes' searches) */
  std::size_t searches_skipped = 0;
  /** what the kept keyframes hold (images, features, pyramids), counted as each is added; the
   * references made from the last 8 (KeyframeSlam::reference()) come on top, 3-4 MB each */
  std::size_t kept_bytes = 0;
  std::vector<double> search_ms;    //!< [ms] loop search and verification, per keyframe with
                                    //!< candidates
  std::vector<double> optimize_ms;  //!< [ms] per optimisation
};

/** "SLAM: N keyframes (M MB kept), ... loops ..., search ms median ..., optimisation ms median ...;
 * largest backlog ..., tracking waited ... times (... ms), ... loop searches skipped\n" */
std::string toText(const SlamStats& s);

class KeyframeSlam {
 public:
  /** Loop candidates are verified with makeRegistration(`odometry`): the product's methods only
   * (throws ConfigError for a baseline or peer). Loads `params.vocabulary` (ConfigError naming
   * the key and the fault). `live` (a sensor, or a recording played as one): the tracking never
   * waits for the background loop search; with max_backlog keyframes waiting, a new keyframe
   * joins the graph without a loop search of its own (SlamStats::searches_skipped). Otherwise
   * the tracking waits there, and every keyframe is searched. */
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
    std::size_t id = 0;
    std::shared_ptr<Frame> frame;
    bool first = true;          //!< the first keyframe: no odometry edge
    PoseGraphEdge odometry;     //!< from the previous keyframe
    mrpt::poses::CPose3D pose;  //!< tracker's estimate (the first node only)
    bool search = true;         //!< false: a node and its odometry edge, no loop search
  };
  struct Place {
    std::size_t keyframe;
    mrpt::poses::CPose3D relative;  //!< the frame's pose in its keyframe's
  };
  void work();
  void process(Job job);
  struct Candidate {
    std::size_t keyframe;
    bool by_appearance;  //!< not near enough by position
  };
  std::vector<Candidate> candidates(std::size_t id) const;
  /** Older keyframes that look like keyframe `id`, most alike first. */
  std::vector<std::size_t> alike(std::size_t id) const;
  std::optional<PoseGraphEdge> verify(std::size_t id, std::size_t candidate);
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
  std::vector<mrpt::poses::CPose3D> m_tracker_kf;  //!< keyframe poses as the tracker has them
  std::vector<std::size_t> m_keyframe_frame;       //!< frame index of each keyframe
  std::size_t m_applied = 0;                       //!< optimisations applied to the tracker
  // worker (the graph, the keyframes and the registration); m_mutex guards what both touch
  std::unique_ptr<Registration> m_registration;
  std::vector<std::shared_ptr<Frame>> m_keyframes;
  /** The last keyframes made references, the most recent first: consecutive keyframes mostly
   * have the same candidates */
  std::deque<std::pair<std::size_t, std::shared_ptr<Frame>>> m_references;
  std::optional<Vocabulary> m_vocabulary;
  std::vector<BowVector> m_words;  //!< per keyframe (empty without ORB features)
  std::vector<double> m_path;      //!< [m] per keyframe: path from the first (+ 1.5 m x angle)
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
