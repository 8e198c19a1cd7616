#include "rgbd_app/MapSinks.h"

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/obs/T3DPointsProjectionParams.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>
#include <mrpt/serialization/CArchive.h>

#include <opencv2/core.hpp>
#include <ostream>
#include <stdexcept>

#include "rgbd_core/GzOutput.h"
#include "rgbd_core/PoseGap.h"
#include "rgbd_core/Progress.h"
#include "rgbd_core/Trajectory.h"
#include "rgbd_odometry/RigidFit.h"

namespace hrgbd {

ColouredMapSink::ColouredMapSink(const MapParams& params, MapFiles files, bool keyframes_only,
                                 double cloud_spacing)
    : m_map(params),
      m_files(std::move(files)),
      m_keyframes_only(keyframes_only),
      m_cloud_spacing(cloud_spacing) {}

void ColouredMapSink::add(const mrpt::obs::CObservation3DRangeScan& obs, const FrameResult& r) {
  m_path.push_back(opticalToMrptWorld(r.pose));
  if (!r.registered()) return;
  if (!m_keyframes_only) {
    m_map.insert(obs, r.pose);
  } else if (r.node) {
    const auto here = toIsometry(m_path.back());
    for (const auto& kept : m_clouds)
      if (viewDistance(poseGap(toIsometry(m_path[kept.first]), here)) < m_cloud_spacing) return;
    ColouredMap cloud(m_map.params());
    cloud.insert(obs, mrpt::poses::CPose3D());
    m_map.insert(cloud, r.pose);
    cloud.freeze();  // kept only to be inserted again
    m_clouds.emplace_back(m_path.size() - 1, std::move(cloud));
  }
}

void ColouredMapSink::correct(const SlamPoses& slam) {
  if (slam.poses.size() != m_path.size())
    throw std::logic_error("ColouredMapSink: optimised poses do not match the frames");
  for (std::size_t i = 0; i < m_path.size(); ++i) m_path[i] = opticalToMrptWorld(slam.poses[i]);
  m_loops = slam.loops;
  if (!m_keyframes_only) return;  // frames inserted as they came cannot be moved
  m_map.clear();
  for (const auto& [frame, cloud] : m_clouds) m_map.insert(cloud, slam.poses[frame]);
}

void ColouredMapSink::finish(std::ostream& log) {
  if (!m_files.ply.empty())
    timedStep(log, "map (PLY, " + std::to_string(m_map.size()) + " points): " + m_files.ply, [&] {
      save({m_files.ply, ""});
    });
  if (!m_files.scene.empty())
    timedStep(log, "map (.3Dscene): " + m_files.scene, [&] { save({"", m_files.scene}); });
}

void ColouredMapSink::reset() {
  m_map.clear();
  m_path.clear();
  m_clouds.clear();
  m_loops.clear();
}

void ColouredMapSink::save(const MapFiles& files) const {
  if (!files.ply.empty()) m_map.savePly(files.ply);
  if (!files.scene.empty()) saveScene(m_map, m_path, files.scene, m_loops);
}

PosedRawlogSink::PosedRawlogSink(const std::string& path)
    : m_path(path), m_writer(std::make_unique<RawlogWriter>(path, ImageStorage::ExternalPng)) {}

void PosedRawlogSink::add(const mrpt::obs::CObservation3DRangeScan& obs, const FrameResult& r) {
  if (!m_writer) throw std::logic_error("PosedRawlogSink: frame after finish()");
  // The frame's own sensorPose is replaced by the camera's estimated pose in the MRPT world.
  mrpt::obs::CObservation3DRangeScan copy = obs;
  copy.sensorPose = opticalToMrptWorld(r.pose);
  m_writer->write(copy);
}

void PosedRawlogSink::correct(const SlamPoses& slam) { m_corrected = slam.poses; }

void PosedRawlogSink::finish(std::ostream& log) {
  if (!m_writer) return;
  const std::size_t written = m_writer->written();
  if (!m_corrected.empty() && m_corrected.size() != written)
    throw std::logic_error("PosedRawlogSink: optimised poses do not match the frames");
  if (m_corrected.empty()) {
    timedStep(log, "rawlog with poses: " + m_path, [&] { m_writer->close(); });
    m_writer.reset();
    return;
  }
  timedStep(log, "rawlog with poses (SLAM, optimised): " + m_path, [&] {
    m_writer->close();
    m_writer.reset();
    // Read back object by object and written again with the optimised poses; the external
    // image names are kept as they are (MRPT loads external images lazily, and on demand only).
    mrpt::io::CFileGZInputStream in(m_path);
    auto reader = mrpt::serialization::archiveFrom(in);
    RawlogWriter out(m_path);  // inline: objects as they are; moved onto m_path by close()
    for (std::size_t i = 0; i < written; ++i) {
      auto obs = reader.ReadObject<mrpt::obs::CObservation3DRangeScan>();
      obs->sensorPose = opticalToMrptWorld(m_corrected[i]);
      out.write(*obs);
    }
    out.close();
  });
}

void SimplemapSink::add(const mrpt::obs::CObservation3DRangeScan& obs, const FrameResult& r) {
  // observations2map inserts each frame at (simplemap pose) (+) sensorPose.
  auto copy = mrpt::obs::CObservation3DRangeScan::Create(obs);
  copy->sensorPose = mrpt::poses::CPose3D();
  copy->intensityImage = mrpt::img::CImage(  // inline, not external
      obs.intensityImage.asCvMat<cv::Mat>(mrpt::img::DEEP_COPY), mrpt::img::SHALLOW_COPY);
  // MRPT's point maps insert a 3D range scan from its stored point cloud (as
  // `rawlog-edit --generate-3d-pointclouds` makes it), not from the depth image.
  mrpt::obs::T3DPointsProjectionParams pp;
  pp.decimation = 2;
  copy->unprojectInto(*copy, pp);
  auto sf = mrpt::obs::CSensoryFrame::Create();
  sf->insert(copy);
  m_simplemap.insert(mrpt::poses::CPose3DPDFGaussian::Create(opticalToMrptWorld(r.pose)), sf);
}

void SimplemapSink::correct(const SlamPoses& slam) {
  if (slam.poses.size() != m_simplemap.size())
    throw std::logic_error("SimplemapSink: optimised poses do not match the frames");
  for (std::size_t i = 0; i < m_simplemap.size(); ++i)
    m_simplemap.getAsPair(i).pose =
        mrpt::poses::CPose3DPDFGaussian::Create(opticalToMrptWorld(slam.poses[i]));
}

void SimplemapSink::finish(std::ostream& log) {
  timedStep(log, "simplemap: " + m_path, [&] { saveCompressed(m_simplemap, m_path, "simplemap"); });
}

}  // namespace hrgbd
