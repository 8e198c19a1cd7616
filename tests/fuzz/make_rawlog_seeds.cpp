// Writes the seed corpus of fuzz_rawlog into the folder given: small valid rawlogs (32x24
// frames, so the fuzzer runs fast) in the formats RawlogSource reads. Deterministic.
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <iostream>

#include "rgbd_core/RgbdFrame.h"
#include "rgbd_io/RawlogWriter.h"

namespace {

mrpt::obs::CObservation3DRangeScan::Ptr frame(double t, bool colour) {
  mrpt::img::TCamera cam;
  cam.ncols = 32;
  cam.nrows = 24;
  cam.fx(26.25);
  cam.fy(26.25);
  cam.cx(15.5);
  cam.cy(11.5);
  cv::Mat depth(24, 32, CV_16UC1), bgr(24, 32, CV_8UC3);
  for (int v = 0; v < 24; ++v)
    for (int u = 0; u < 32; ++u) {
      depth.at<uint16_t>(v, u) = static_cast<uint16_t>(u < 4 ? 0 : 5000 + 40 * u + 10 * v);
      bgr.at<cv::Vec3b>(v, u) = cv::Vec3b(u * 8, v * 10, (u * v) % 256);
    }
  return hrgbd::makeRgbdObservation(colour ? bgr : cv::Mat(), depth, 1.0 / 5000, cam, t);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: make_rawlog_seeds <folder>\n";
    return 2;
  }
  const std::filesystem::path dir(argv[1]);
  std::filesystem::create_directories(dir);
  {  // plain, observations-only: two frames and an odometry entry
    mrpt::io::CFileOutputStream f((dir / "plain.rawlog").string());
    auto a = mrpt::serialization::archiveFrom(f);
    a << *frame(1.0, true) << mrpt::obs::CObservationOdometry() << *frame(1.033, true);
  }
  {  // gzip, SensoryFrame format, one frame without colour
    hrgbd::RawlogWriter w((dir / "sensoryframe.rawlog").string());
    mrpt::obs::CSensoryFrame sf;
    sf.insert(frame(2.0, false));
    w.write(sf);
    w.close();
  }
  std::cout << "seeds written to " << dir.string() << "\n";
  return 0;
}
