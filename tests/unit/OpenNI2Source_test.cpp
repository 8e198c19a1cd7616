#include "rgbd_io/OpenNI2Source.h"

#include <mrpt/config/CConfigFileMemory.h>

#include "TestData.h"

TEST(OpenNI2Source, WithoutSensorTheErrorSaysSo) {
  if (hrgbd::countOpenNI2Devices() > 0)
    GTEST_SKIP() << "an OpenNI2 sensor is connected; this test checks the no-sensor message";
  mrpt::config::CConfigFileMemory cfg("[OpenNI2]\nsensorLabel = KINECT\n");
  try {
    hrgbd::OpenNI2Source src(cfg);
    FAIL() << "expected an exception without a sensor";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no OpenNI2 device"), std::string::npos) << e.what();
  }
}
