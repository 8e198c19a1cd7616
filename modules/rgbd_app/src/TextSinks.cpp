#include "rgbd_app/TextSinks.h"

#include <unistd.h>

#include <algorithm>
#include <iomanip>
#include <ostream>
#include <stdexcept>

#include "rgbd_core/Timestamp.h"

namespace hrgbd {

TrajectorySink::TrajectorySink(const std::string& path, const std::string& comment, bool streamed)
    : m_file(std::make_unique<StreamOutput>(path, "trajectory")), m_streamed(streamed) {
  m_file->stream() << comment << "\n";
  m_file->flush();
}

void TrajectorySink::add(const mrpt::obs::CObservation3DRangeScan& obs, const FrameResult& r) {
  m_trajectory.push_back({frameSeconds(obs.timestamp), r.pose});
  m_times.push_back(formatFrameTime(obs.timestamp));
  if (!m_file || !m_streamed) return;
  writeTumLine(m_file->stream(), m_times.back(), r.pose);
  m_file->flush();
}

void TrajectorySink::finish(std::ostream& log) {
  if (!m_file) return;
  timedStep(log, (m_corrected ? "trajectory (SLAM, optimised): " : "trajectory: ") + m_file->path(),
            [&] {
              if (!m_streamed)
                for (std::size_t i = 0; i < m_trajectory.size(); ++i)
                  writeTumLine(m_file->stream(), m_times[i], m_trajectory[i].pose);
              m_file->commit();
            });
  m_file.reset();
}

void TrajectorySink::reset() {
  m_trajectory.clear();
  m_times.clear();
}

void TrajectorySink::correct(const SlamPoses& slam) {
  if (slam.poses.size() != m_trajectory.size())
    throw std::logic_error("TrajectorySink: " + std::to_string(slam.poses.size()) +
                           " optimised poses for " + std::to_string(m_trajectory.size()) +
                           " frames");
  if (m_file && m_streamed)
    throw std::logic_error("TrajectorySink: optimised poses for '" + m_file->path() +
                           "', whose poses are written as they come");
  for (std::size_t i = 0; i < m_trajectory.size(); ++i) m_trajectory[i].pose = slam.poses[i];
  m_corrected = true;
}

void TrajectorySink::save(const std::string& path, const std::string& comment) const {
  StreamOutput out(path, "trajectory");
  out.stream() << comment << "\n";
  for (std::size_t i = 0; i < m_trajectory.size(); ++i)
    writeTumLine(out.stream(), m_times[i], m_trajectory[i].pose);
  out.commit();
}

CsvSink::CsvSink(const std::string& path) : m_file(path, "CSV") {
  m_file.stream() << "timestamp,status,path,refined,orb_features,features,matches,inliers,scale_m,"
                     "ms_prepare,ms_features,ms_matching,ms_estimation,ms_refine,ms_total,detail\n";
  m_file.flush();
}

void CsvSink::add(const mrpt::obs::CObservation3DRangeScan& obs, const FrameResult& r) {
  m_file.stream() << formatFrameTime(obs.timestamp) << "," << toString(r.status) << ","
                  << toString(r.path.sparse) << "," << toString(r.path.refined) << ","
                  << r.orb_features << "," << r.features << "," << r.matches << "," << r.inliers
                  << "," << std::fixed << std::setprecision(5) << r.scale << ","
                  << std::setprecision(3) << r.ms.prepare << "," << r.ms.features << ","
                  << r.ms.matching << "," << r.ms.estimation << "," << r.ms.refine << ","
                  << r.ms.total << ",\"" << r.detail << "\"\n";
  m_file.flush();
}

void CsvSink::finish(std::ostream& log) {
  timedStep(log, "CSV: " + m_file.path(), [&] { m_file.commit(); });
}

void ProgressSink::add(const mrpt::obs::CObservation3DRangeScan&, const FrameResult& r) {
  ++m_frames;
  m_registered += r.registered();
  const auto lost = m_frames - m_registered;
  m_progress.update(m_frames, lost ? std::to_string(lost) + " not registered" : "");
}

void ProgressSink::finish(std::ostream&) { m_progress.finish(); }

ProgressParams frameProgress(const FrameSource& source, std::size_t max_frames,
                             const std::string& label) {
  ProgressParams p;
  p.label = label;
  p.total = source.frameCount(max_frames);  // a rawlog is read up to max_frames at most
  if (p.total == 0) p.total = max_frames;   // a live sensor stops there too
  p.terminal = isatty(STDERR_FILENO);
  return p;
}

}  // namespace hrgbd
