// The back end's worker side of KeyframeSlam: each job from the tracking becomes a node (or a
// keyframe searched for its node), its loop search, culling, and an optimisation when the graph
// disagrees with a new loop; the result is published for the tracking thread.
#include <algorithm>

#include "SlamCommon.h"
#include "rgbd_core/Timing.h"
#include "rgbd_slam/KeyframeSlam.h"

namespace hrgbd {

using slam::viewDistance;

namespace {

std::size_t bytes(const cv::Mat& m) { return m.total() * m.elemSize(); }
std::size_t bytes(const FeatureSet& f) {
  return f.keypoints.size() * sizeof(cv::KeyPoint) + bytes(f.descriptors) +
         f.points.size() * sizeof(Eigen::Vector3d);
}

/** [bytes] a kept keyframe's images, features and pyramids */
std::size_t keptBytes(const Frame& f) {
  std::size_t n = bytes(f.image.grey) + bytes(f.image.depth);
  if (f.orb) n += bytes(*f.orb);
  if (f.geometric)
    n += bytes(f.geometric->features) +
         (f.geometric->cloud.size() + f.geometric->normals.size()) * sizeof(Eigen::Vector3f);
  if (f.dense)
    for (const auto& l : f.dense->levels)
      n += bytes(l.grey) + bytes(l.depth) + bytes(l.samples) + bytes(l.normals) + bytes(l.textured);
  return n;
}

}  // namespace

void KeyframeSlam::work() {
  std::unique_lock<std::mutex> lock(m_mutex);
  for (;;) {
    m_wake.wait(lock, [&] { return m_stop || !m_queue.empty(); });
    if (m_queue.empty()) return;  // stopping, nothing left
    Job job = std::move(m_queue.front());
    m_queue.pop_front();
    m_busy = true;
    m_idle.notify_all();  // room in the queue: add() may go on
    lock.unlock();
    std::exception_ptr failed;
    try {
      process(std::move(job));
    } catch (...) {  // handed to the tracking thread, which rethrows it (add(), flush())
      failed = std::current_exception();
    }
    lock.lock();
    if (failed && !m_failed) m_failed = failed;
    if (m_failed) m_queue.clear();  // the keyframes may be out of step: search no more
    m_busy = false;
    m_idle.notify_all();  // flush() waits for an empty queue and an idle worker
  }
}

void KeyframeSlam::process(Job job) {
  const std::size_t id = job.id;
  const auto& orb = job.frame->orb;
  BowVector words = m_vocabulary && orb ? m_vocabulary->transform(orb->descriptors) : BowVector{};
  if (job.node) {
    m_keyframes.push_back(job.frame);
    m_words.push_back(std::move(words));
    m_linked.emplace_back();
    if (!job.first) {
      m_graph.addNode(m_graph.pose(job.odometry.from) + job.odometry.relative);
      m_graph.addEdge(job.odometry);
      m_path.push_back(m_path.back() + viewDistance(job.odometry.relative));
    } else {
      m_graph.addNode(job.pose);
      m_path.push_back(0);
    }
  }
  const Query query{*job.frame, id, job.node, job.in_node, job.node ? m_words.back() : words};
  KeyframeWork work;
  work.frame = job.frame_index;
  work.node = job.node;
  std::size_t by_appearance = 0, appearance_loops = 0;
  double disagreement = 0;  // largest chi-square of a new loop edge at the graph's poses
  timed(work.search_ms, [&] {
    if (!job.search) return 0;
    for (const Candidate& c : candidates(query)) {
      ++work.verified;
      by_appearance += c.by_appearance;
      if (auto edge = verify(query, c.keyframe)) {
        disagreement = std::max(disagreement,
                                edgeChi2(*edge, m_graph.pose(edge->from), m_graph.pose(edge->to)));
        m_graph.addEdge(*edge);
        m_linked[id].push_back(edge->from);
        ++work.accepted;
        appearance_loops += c.by_appearance;
      }
    }
    return 0;
  });
  std::size_t kept = 0;
  bool culled = false;
  if (job.node) {
    culled = job.search && redundant(id);
    if (culled) {
      // an older node sees the same view and a loop ties this one to it: a pose and its edges
      // are all the graph needs of it (never a candidate again)
      m_keyframes.back().reset();
      m_words.back().clear();
    } else {
      // searched: from now on only a reference (reference() unpacks a copy)
      if (m_keyframes.back()->dense) packLevels(*m_keyframes.back()->dense);
      kept = keptBytes(*m_keyframes.back());
    }
  }
  std::optional<PoseGraphOptimization> opt;
  if (work.accepted > 0 && disagreement >= m_params.optimize_min_chi2) {
    // the newest nodes only, unless the loop closes a cycle the window could only bend
    const auto window = static_cast<std::size_t>(m_params.optimize_window);
    const std::size_t first_free =
        window == 0 || disagreement > m_params.loop_max_chi2 || m_graph.nodes() <= window
            ? 1
            : m_graph.nodes() - window;
    opt = m_graph.optimize(m_params.loop_max_chi2, m_params.optimizer_iterations, first_free);
  }
  work.nodes = m_graph.nodes();
  work.edges = m_graph.edges().size();
  if (opt) work.optimized = true, work.optimize_ms = opt->ms, work.iterations = opt->iterations;
  std::lock_guard<std::mutex> lock(m_mutex);
  m_stats.keyframes = m_graph.nodes();
  m_stats.kept_bytes += kept;
  m_stats.culled += culled;
  m_stats.candidates += work.verified;
  m_stats.by_appearance += by_appearance;
  m_stats.loops_accepted += work.accepted;
  m_stats.appearance_loops += appearance_loops;
  m_stats.work.push_back(work);
  if (opt) {
    m_stats.loops_dropped += opt->dropped.size();
    ++m_stats.optimizations;
    publish();
  }
}

bool KeyframeSlam::redundant(std::size_t id) const {
  const auto& edges = m_graph.edges();
  // this search's loop edges are the last ones, all into `id`
  for (auto e = edges.rbegin(); e != edges.rend() && e->loop && e->to == id; ++e)
    if (viewDistance(e->relative) < 0.5 * m_params.node_spacing && m_keyframes[e->from])
      return true;
  return false;
}

void KeyframeSlam::publish() {
  m_optimized = m_graph.poses();
  m_loops.clear();
  const auto& edges = m_graph.edges();
  for (std::size_t i = 0; i < edges.size(); ++i)
    if (edges[i].loop && m_graph.active(i)) m_loops.push_back(edges[i]);
  ++m_optimizations;
}

}  // namespace hrgbd
