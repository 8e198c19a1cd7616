#pragma once
/** \file OpenNI2Source.h
 * A live OpenNI2 sensor (Kinect, Xtion, ...) through mrpt::hwdrivers::COpenNI2Sensor. */
#include <mrpt/config/CConfigFileBase.h>

#include <memory>

#include "rgbd_io/FrameSource.h"

namespace mrpt::hwdrivers {
class COpenNI2Sensor;
}

namespace hrgbd {

/** Live frames. The INI section (default [OpenNI2]) is passed to COpenNI2Sensor::loadConfig, so
 * its keys are MRPT's own (sensorLabel, preferredWidth, preferredHeight, ...). The constructor
 * throws std::runtime_error "no OpenNI2 device found ..." when no sensor is connected. next()
 * never returns nullptr (a live sensor has no end); a hardware error throws. */
/** Number of OpenNI2 devices connected (0 if OpenNI2 cannot start). */
int countOpenNI2Devices();

class OpenNI2Source : public FrameSource {
 public:
  OpenNI2Source(const mrpt::config::CConfigFileBase& cfg, const std::string& section = "OpenNI2");
  ~OpenNI2Source() override;
  mrpt::obs::CObservation3DRangeScan::Ptr next() override;
  std::string describe() const override;

 private:
  std::unique_ptr<mrpt::hwdrivers::COpenNI2Sensor> m_sensor;
};

}  // namespace hrgbd
