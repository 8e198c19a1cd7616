#include "rgbd_app/TextSinks.h"

#include <iomanip>
#include <ostream>
#include <stdexcept>

namespace hrgbd {

TrajectorySink::TrajectorySink(const std::string& path, const std::string& comment)
    : m_path(path), m_file(path) {
  if (!m_file) throw std::runtime_error("cannot write trajectory '" + path + "'");
  m_file << comment << "\n";
}

void TrajectorySink::add(const mrpt::obs::CObservation3DRangeScan&, const FrameResult& r) {
  m_trajectory.push_back({r.t, r.pose});
  if (!m_file.is_open()) return;
  writeTumLine(m_file, m_trajectory.back());
  m_file.flush();
}

void TrajectorySink::finish(std::ostream& log) {
  if (m_file.is_open()) log << "trajectory: " << m_path << "\n";
}

CsvSink::CsvSink(const std::string& path) : m_file(path) {
  if (!m_file) throw std::runtime_error("cannot write CSV '" + path + "'");
  m_file << "timestamp,status,path,orb_features,features,matches,inliers,scale_m,ms_prepare,"
            "ms_features,ms_matching,ms_estimation,ms_refine,ms_total,detail\n";
}

void CsvSink::add(const mrpt::obs::CObservation3DRangeScan&, const FrameResult& r) {
  m_file << std::fixed << std::setprecision(6) << r.t << "," << toString(r.status) << "," << r.path
         << "," << r.orb_features << "," << r.features << "," << r.matches << "," << r.inliers
         << "," << std::setprecision(5) << r.scale << "," << std::setprecision(3) << r.ms.prepare
         << "," << r.ms.features << "," << r.ms.matching << "," << r.ms.estimation << ","
         << r.ms.refine << "," << r.ms.total << ",\"" << r.detail << "\"\n";
  m_file.flush();
}

void ProgressSink::add(const mrpt::obs::CObservation3DRangeScan&, const FrameResult& r) {
  ++m_frames;
  m_registered += r.registered();
  m_out << "\r  frame " << std::setw(6) << m_frames << "  registered " << std::setw(6)
        << m_registered << "  " << std::fixed << std::setprecision(1) << std::setw(6) << r.ms.total
        << " ms/frame" << std::flush;
}

void ProgressSink::finish(std::ostream&) { m_out << "\n"; }

}  // namespace hrgbd
