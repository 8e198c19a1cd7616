#include "rgbd_app/MapSinks.h"

#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/obs/T3DPointsProjectionParams.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>

#include <opencv2/core.hpp>
#include <ostream>
#include <stdexcept>

#include "rgbd_core/GzOutput.h"
#include "rgbd_core/Trajectory.h"

namespace hrgbd {

ColouredMapSink::ColouredMapSink(const MapParams& params, MapFiles files)
    : m_map(params), m_files(std::move(files)) {}

void ColouredMapSink::add(const mrpt::obs::CObservation3DRangeScan& obs, const FrameResult& r) {
  m_path.push_back(opticalToMrptWorld(r.pose));
  if (r.registered()) m_map.insert(obs, r.pose);
}

void ColouredMapSink::finish(std::ostream& log) {
  save(m_files);
  if (!m_files.ply.empty())
    log << "map (PLY, " << m_map.size() << " points): " << m_files.ply << "\n";
  if (!m_files.scene.empty()) log << "map (.3Dscene): " << m_files.scene << "\n";
}

void ColouredMapSink::reset() {
  m_map.clear();
  m_path.clear();
}

void ColouredMapSink::save(const MapFiles& files) const {
  if (!files.ply.empty()) m_map.savePly(files.ply);
  if (!files.scene.empty()) saveScene(m_map, m_path, files.scene);
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

void PosedRawlogSink::finish(std::ostream& log) {
  if (!m_writer) return;
  m_writer->close();
  m_writer.reset();
  log << "rawlog with poses: " << m_path << "\n";
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

void SimplemapSink::finish(std::ostream& log) {
  saveCompressed(m_simplemap, m_path, "simplemap");
  log << "simplemap: " << m_path << "\n";
}

}  // namespace hrgbd
