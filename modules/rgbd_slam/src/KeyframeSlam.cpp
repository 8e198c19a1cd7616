#include "rgbd_slam/KeyframeSlam.h"

#include <mrpt/core/bits_math.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "SlamCommon.h"
#include "rgbd_core/Config.h"
#include "rgbd_core/Median.h"
#include "rgbd_core/Timing.h"
#include "rgbd_odometry/RigidFit.h"

namespace hrgbd {

using slam::fitSigma;
using slam::kPredictedSigma;
using slam::sigmaInformation;
using slam::viewDistance;

namespace {

/** The tracking's parameters with the loops' weight of the point-to-plane term, and without the
 * geometric fallback of a weak photometric registration: a loop needs loop_min_inliers, and the
 * keyframes then need not keep their images (keptForLoops()). */
OdometryParams loopRegistration(OdometryParams odometry, const SlamParams& p) {
  odometry.dense.geometric_weight = p.loop_geometric_weight;
  odometry.geometric_fallback = false;
  return odometry;
}

/** What the loop search keeps of a prepared keyframe: its features, and its pyramids' grey and
 * depth (the gradients, normals and textured cells are made again when the keyframe is a loop's
 * reference: 0.9 instead of 3.8 MB a keyframe at 320x240, the finest level used; packed in 2
 * bytes a pixel once the keyframe's own search is done, packLevels(): 0.5 MB). The images
 * (1.5 MB at 640x480) only serve to compute features: a textured keyframe has
 * its ORB features, one with too few has IS3D + SHOT (prepared by the tracker's hybrid
 * registration). A textured keyframe's IS3D + SHOT are not made, so a keyframe with too few ORB
 * features verifies only candidates like it (a geometric loop with loop_min_inliers between a
 * plain and a textured view was never seen: none on the real plain structure either way). */
std::shared_ptr<Frame> keptForLoops(const Frame& keyframe) {
  auto f = std::make_shared<Frame>(keyframe);
  f->guess.reset();
  f->peer.reset();
  if (f->orb || f->geometric) f->image.grey.release(), f->image.depth.release();
  if (f->dense) dropDerivatives(*f->dense);
  return f;
}

}  // namespace

std::string toText(const SlamStats& s) {
  std::vector<double> search, optimize;
  for (const auto& w : s.work) {
    if (w.verified > 0) search.push_back(w.search_ms);
    if (w.optimized) optimize.push_back(w.optimize_ms);
  }
  std::ostringstream out;
  out << std::fixed << std::setprecision(1) << "SLAM: " << s.keyframes << " nodes of "
      << s.tracker_keyframes << " keyframes (" << s.culled << " culled; " << s.kept_bytes / 1e6
      << " MB kept), " << s.candidates << " loop candidates verified (" << s.by_appearance
      << " by appearance), " << s.loops_accepted << " loops accepted (" << s.appearance_loops
      << " by appearance), " << s.loops_dropped << " dropped as inconsistent; loop search median "
      << (search.empty() ? 0.0 : median(search)) << " ms per keyframe, " << s.optimizations
      << " optimisations, median " << (optimize.empty() ? 0.0 : median(optimize)) << " ms (final "
      << s.final_optimize_ms << " ms); largest backlog " << s.largest_backlog
      << " keyframes, tracking waited " << s.backlog_waits << " times (" << s.waited_ms << " ms), "
      << s.searches_skipped << " loop searches skipped\n";
  return out.str();
}

KeyframeSlam::KeyframeSlam(const SlamParams& params, const OdometryParams& odometry, bool live)
    : m_params(params),
      m_live(live),
      m_odometry(odometry),
      m_registration(makeRegistration(loopRegistration(odometry, params),
                                      static_cast<std::size_t>(params.loop_min_inliers))) {
  if (!m_params.vocabulary.empty()) try {
      m_vocabulary = Vocabulary::load(m_params.vocabulary == "bundled" ? bundledVocabulary()
                                                                       : m_params.vocabulary);
    } catch (const std::exception& e) {
      throw ConfigError("[Slam] vocabulary = " + m_params.vocabulary + ": " + e.what());
    }
  if (m_params.background) m_thread = std::thread([this] { work(); });
}

KeyframeSlam::~KeyframeSlam() { stopWorker(); }

void KeyframeSlam::stopWorker() {
  if (!m_thread.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_stop = true;
    m_queue.clear();  // keyframes not searched yet are dropped with the rest
  }
  m_wake.notify_all();
  m_thread.join();
}

void KeyframeSlam::rethrowWorkerFailure() {
  std::lock_guard<std::mutex> lock(m_mutex);
  if (m_failed) std::rethrow_exception(m_failed);
}

bool KeyframeSlam::add(FrameResult& r, RgbdOdometry& tracker) {
  rethrowWorkerFailure();
  if (r.keyframe && tracker.keyframe()) {  // registered, or taken after failures
    ++m_tracker_keyframes;
    // the odometry from the last node to here: its variance grows with each keyframe's fit
    const double sigma = r.registered() ? fitSigma(m_params, r.inliers, false) : kPredictedSigma;
    m_chain_variance += sigma * sigma;
    const bool node = m_tracker_kf.empty() || !r.registered() ||
                      viewDistance((-m_tracker_kf.back()) + r.pose) >= m_params.node_spacing;
    addJob(r, tracker, node);
    r.node = node;
  }
  if (m_tracker_kf.empty()) {  // no keyframe yet (a first frame without depth): stays at origin
    m_places.push_back({0, r.pose});
    return false;
  }
  m_places.push_back({m_tracker_kf.size() - 1, (-m_tracker_kf.back()) + r.pose});
  const std::size_t before = m_applied;
  applyOptimization(tracker);
  r.pose = tracker.pose();
  return m_applied != before;
}

void KeyframeSlam::addJob(const FrameResult& r, const RgbdOdometry& tracker, bool node) {
  Job job;
  job.node = node;
  job.frame_index = m_places.size();
  job.frame = keptForLoops(*tracker.keyframe());
  job.pose = r.pose;
  job.first = m_tracker_kf.empty();
  if (!node) {
    job.id = m_tracker_kf.size() - 1;
    job.in_node = (-m_tracker_kf.back()) + r.pose;
  } else {
    job.id = m_tracker_kf.size();
    if (!job.first)
      job.odometry = PoseGraphEdge{job.id - 1, job.id, (-m_tracker_kf.back()) + r.pose,
                                   sigmaInformation(std::sqrt(m_chain_variance)), false};
    m_chain_variance = 0;
    m_tracker_kf.push_back(r.pose);
    m_keyframe_frame.push_back(m_places.size());
  }
  if (!m_params.background) return process(std::move(job));
  {
    std::unique_lock<std::mutex> lock(m_mutex);
    const auto backlog = static_cast<std::size_t>(m_params.max_backlog);
    // live, the keyframes waiting without a search of their own cost the worker little
    const auto searches = static_cast<std::size_t>(
        std::count_if(m_queue.begin(), m_queue.end(), [](const Job& j) { return j.search; }));
    // the back end drops work, not the tracker: a keyframe that is not a node goes unsearched,
    // and a node makes room by dropping the oldest such keyframe waiting
    const auto not_node =
        std::find_if(m_queue.begin(), m_queue.end(), [](const Job& j) { return !j.node; });
    if (searches >= backlog && !node) {
      ++m_stats.searches_skipped;
      return;
    } else if (searches >= backlog && not_node != m_queue.end()) {
      ++m_stats.searches_skipped;
      m_queue.erase(not_node);
    } else if (searches >= backlog && m_live) {
      // live, the node joins the graph with its odometry edge only
      ++m_stats.searches_skipped;
      job.search = false;
    } else if (!m_live && m_queue.size() >= backlog) {
      // offline, every node is searched: the tracking waits for room
      ++m_stats.backlog_waits;
      double ms = 0;
      timed(ms, [&] {
        m_idle.wait(lock, [&] { return m_queue.size() < backlog || m_failed; });
        return 0;
      });
      m_stats.waited_ms += ms;
    }
    // the worker failed: the graph is out of step, no more jobs for it
    if (m_failed) std::rethrow_exception(m_failed);
    m_queue.push_back(std::move(job));
    m_stats.largest_backlog = std::max(m_stats.largest_backlog, m_queue.size());
  }
  m_wake.notify_all();
}

void KeyframeSlam::applyOptimization(RgbdOdometry& tracker) {
  std::vector<mrpt::poses::CPose3D> optimized;
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (m_optimizations == m_applied) return;
    m_applied = m_optimizations;
    optimized = m_optimized;
  }
  if (optimized.empty()) return;
  // the newest optimised keyframe moves to its optimised pose, and everything after with it
  const std::size_t k = optimized.size() - 1;
  const mrpt::poses::CPose3D correction = optimized[k] + (-m_tracker_kf[k]);
  tracker.correct(correction);
  for (std::size_t i = 0; i < m_tracker_kf.size(); ++i)
    m_tracker_kf[i] = i <= k ? optimized[i] : toPose(toIsometry(correction + m_tracker_kf[i]));
}

void KeyframeSlam::flush() {
  if (m_params.background) {
    std::unique_lock<std::mutex> lock(m_mutex);
    m_idle.wait(lock, [&] { return (m_queue.empty() && !m_busy) || m_failed; });
  }
  rethrowWorkerFailure();
  if (m_graph.nodes() == 0) return;
  const auto opt = m_graph.optimize(m_params.loop_max_chi2, m_params.optimizer_iterations);
  std::lock_guard<std::mutex> lock(m_mutex);
  m_stats.loops_dropped += opt.dropped.size();
  m_stats.final_optimize_ms = opt.ms;
  ++m_stats.optimizations;
  publish();
  m_applied = m_optimizations;  // the final poses are every keyframe's, not a correction
  m_tracker_kf = m_graph.poses();
}

SlamPoses KeyframeSlam::poses() const {
  std::vector<PoseGraphEdge> loops;
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    loops = m_loops;
  }
  // m_tracker_kf holds the optimisation last applied (and after flush() the final one), so every
  // frame follows one consistent set of keyframe poses; re-orthonormalised (toPose()): the
  // optimiser's nodes drift off SO(3) by rounding, and CPose3D's angles and matrix then disagree
  SlamPoses out;
  for (const auto& p : m_places)
    out.poses.push_back(p.keyframe < m_tracker_kf.size()
                            ? toPose(toIsometry(m_tracker_kf[p.keyframe] + p.relative))
                            : p.relative);
  for (const auto& e : loops) {
    out.loops.emplace_back(m_keyframe_frame.at(e.from), m_keyframe_frame.at(e.to));
    out.loop_measured.push_back(e.relative);
  }
  return out;
}

SlamStats KeyframeSlam::stats() const {
  std::lock_guard<std::mutex> lock(m_mutex);
  SlamStats s = m_stats;
  s.tracker_keyframes = m_tracker_keyframes;
  return s;
}

void KeyframeSlam::reset() {
  stopWorker();
  m_places.clear();
  m_tracker_kf.clear();
  m_keyframe_frame.clear();
  m_chain_variance = 0;
  m_tracker_keyframes = 0;
  m_keyframes.clear();
  m_references.clear();
  m_words.clear();
  m_path.clear();
  m_linked.clear();
  m_graph = PoseGraph();
  m_queue.clear();
  m_optimized.clear();
  m_loops.clear();
  m_stop = m_busy = false;
  m_failed = nullptr;
  m_applied = m_optimizations = 0;
  m_stats = SlamStats();
  m_registration = makeRegistration(loopRegistration(m_odometry, m_params),
                                    static_cast<std::size_t>(m_params.loop_min_inliers));
  if (m_params.background) m_thread = std::thread([this] { work(); });
}

}  // namespace hrgbd
