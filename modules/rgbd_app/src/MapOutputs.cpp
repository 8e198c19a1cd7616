#include "MapOutputs.h"

#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/obs/T3DPointsProjectionParams.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>

#include <ostream>

#include "rgbd_core/Trajectory.h"

namespace hrgbd {

MapOutputs::MapOutputs(const MapOutputPaths& paths, const MapParams& params) : m_paths(paths) {
  if (!paths.output_rawlog.empty())
    m_rawlog = std::make_unique<RawlogWriter>(paths.output_rawlog, ImageStorage::ExternalPng);
  if (!paths.map_ply.empty() || !paths.map_scene.empty()) m_map.emplace(params);
}

void MapOutputs::add(const mrpt::obs::CObservation3DRangeScan& obs, const FrameResult& r) {
  const auto pose = opticalToMrptWorld(r.pose);
  if (!m_paths.map_scene.empty()) m_path.push_back(pose);
  if (m_rawlog) {
    // The camera's estimated pose in the MRPT world, where RawLogViewer and rawlog-edit
    // --list-poses read it. The frame's own sensorPose is replaced.
    mrpt::obs::CObservation3DRangeScan copy = obs;
    copy.sensorPose = pose;
    m_rawlog->write(copy);
  }
  if (!m_paths.simplemap.empty()) {
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
    m_simplemap.insert(mrpt::poses::CPose3DPDFGaussian::Create(pose), sf);
  }
  if (m_map && r.registered()) m_map->insert(obs, r.pose);
}

std::size_t MapOutputs::finish(std::ostream& log) {
  m_rawlog.reset();  // closes (flushes) the gzip stream
  if (!m_paths.output_rawlog.empty()) log << "rawlog with poses: " << m_paths.output_rawlog << "\n";
  if (!m_paths.simplemap.empty()) {
    if (!m_simplemap.saveToFile(m_paths.simplemap))
      throw std::runtime_error("cannot write simplemap '" + m_paths.simplemap + "'");
    log << "simplemap: " << m_paths.simplemap << "\n";
  }
  if (!m_map) return 0;
  if (!m_paths.map_ply.empty()) {
    m_map->savePly(m_paths.map_ply);
    log << "map (PLY, " << m_map->size() << " points): " << m_paths.map_ply << "\n";
  }
  if (!m_paths.map_scene.empty()) {
    saveScene(*m_map, m_path, m_paths.map_scene);
    log << "map (.3Dscene): " << m_paths.map_scene << "\n";
  }
  return m_map->size();
}

}  // namespace hrgbd
