#include "rgbd_io/OpenNI2Source.h"

#include <OpenNI.h>
#include <mrpt/hwdrivers/COpenNI2Sensor.h>

#include <stdexcept>

namespace hrgbd {

int countOpenNI2Devices() {
  if (openni::OpenNI::initialize() != openni::STATUS_OK) return 0;
  openni::Array<openni::DeviceInfo> devices;
  openni::OpenNI::enumerateDevices(&devices);
  return devices.getSize();
}

OpenNI2Source::OpenNI2Source(const mrpt::config::CConfigFileBase& cfg, const std::string& section) {
  // Count first: MRPT 2.5's COpenNI2Sensor destructor throws when there is no device.
  if (countOpenNI2Devices() == 0)
    throw std::runtime_error(
        "no OpenNI2 device found: connect a Kinect/Xtion (and check its udev permissions), or "
        "play a rawlog or TUM folder instead");
  m_sensor = std::make_unique<mrpt::hwdrivers::COpenNI2Sensor>();
  try {
    m_sensor->loadConfig(cfg, section);
    m_sensor->initialize();
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot start the OpenNI2 sensor (INI section [" + section +
                             "]): " + e.what());
  }
}

OpenNI2Source::~OpenNI2Source() = default;

mrpt::obs::CObservation3DRangeScan::Ptr OpenNI2Source::next() {
  for (;;) {
    auto obs = mrpt::obs::CObservation3DRangeScan::Create();
    bool there_is_obs = false, hardware_error = false;
    m_sensor->getNextObservation(*obs, there_is_obs, hardware_error);
    if (hardware_error) throw std::runtime_error("OpenNI2 sensor reported a hardware error");
    if (there_is_obs) {
      ++m_stats.frames;
      return obs;
    }
  }
}

std::string OpenNI2Source::describe() const { return "live OpenNI2 sensor"; }

}  // namespace hrgbd
