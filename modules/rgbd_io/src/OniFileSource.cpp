#include "rgbd_io/OniFileSource.h"

#include <OpenNI.h>
#include <mrpt/img/TCamera.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "rgbd_core/RgbdFrame.h"
#include "rgbd_core/TextFile.h"
#include "rgbd_core/Timestamp.h"
#include "rgbd_io/RawlogSource.h"

namespace hrgbd {
namespace {

/** [ms] A recording that produces no frame for this long before its recorded end is broken. */
constexpr int kFrameTimeoutMs = 5000;
/** Waited at every close for a frame hand-over of OpenNI2's file driver to end (see ~Impl). */
constexpr std::chrono::milliseconds kHandOverMs{50};

std::runtime_error fail(const std::string& path, const std::string& what) {
  return std::runtime_error("OpenNI recording " + path + ": " + what);
}

std::string openniError() {
  std::string e = openni::OpenNI::getExtendedError();
  e.erase(std::remove_if(e.begin(), e.end(), [](char c) { return c == '\n' || c == '\t'; }),
          e.end());
  return e.empty() ? "no detail" : e;
}

/** One stream and where it is in the recording. */
struct Stream {
  openni::VideoStream stream;
  openni::VideoFrameRef pending;  // read, not yet paired
  int recorded = 0;               // frames in the recording (its last frame index)
  int last_index = 0;             // last frame index read
  std::size_t dropped = 0;
  bool ended() const { return last_index >= recorded; }
};

}  // namespace

bool isOniFile(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext == ".oni";
}

struct OniFileSource::Impl {
  std::string path;
  openni::Device device;
  Stream depth, colour;
  mrpt::img::TCamera camera;
  double depth_unit = 0.001;  // [m] per depth value
  double max_dt_us = 0;       // [us] pairing tolerance
  std::size_t unpaired = 0;
  Trajectory ground_truth;
  std::string registration;  // how depth comes to be in the colour camera, for describe()

  /** Also after a constructor that threw. OpenNI2's file driver walks its stream list on its
   * player thread without the list's lock (PlayerDevice::MainLoop), so destroying a stream
   * while that thread runs can crash it: close the device first (it stops and joins the
   * thread), then release the streams.
   *
   * Closing while that thread still hands over a frame crashed it too (in OpenNI2's frame
   * release, during the join): stopped mid-playback, 3 of 900 teardowns with three test
   * processes on two cores. A stopped stream takes no new frame, but one already being handed
   * over is finished (even after the last frame: a hand-over ends after its frame is readable),
   * and OpenNI2 says nothing when it is. The wait below makes a hand-over still running at the
   * close unlikely rather than impossible (it takes microseconds; a preempted thread can take
   * longer): no crash in 2,520 teardowns after it. */
  ~Impl() {
    for (Stream* s : {&depth, &colour}) {
      s->pending.release();
      s->stream.stop();
    }
    std::this_thread::sleep_for(kHandOverMs);
    device.close();
    for (Stream* s : {&depth, &colour}) s->stream.destroy();
  }

  void openStream(Stream& s, openni::SensorType type, const char* name) {
    if (!device.hasSensor(type)) throw fail(path, std::string("has no ") + name + " stream");
    if (s.stream.create(device, type) != openni::STATUS_OK)
      throw fail(path, std::string("cannot create its ") + name + " stream: " + openniError());
    s.recorded = device.getPlaybackControl()->getNumberOfFrames(s.stream);
    if (s.recorded <= 0)  // none, or 0xFFFFFFFF: a recorder that never finished the file
      throw fail(path, std::string("its ") + name +
                           " stream has no frames or no frame count (a recording that was not "
                           "finished)");
  }

  /** Reads one frame of whichever stream has one; false at the end of the recording. */
  bool readAny() {
    openni::VideoStream* waiting[2];
    Stream* owners[2];
    int n = 0;
    for (Stream* s : {&depth, &colour})
      if (!s->ended() && !s->pending.isValid()) {
        owners[n] = s;
        waiting[n++] = &s->stream;
      }
    if (n == 0) return false;
    int ready = -1;
    if (openni::OpenNI::waitForAnyStream(waiting, n, &ready, kFrameTimeoutMs) != openni::STATUS_OK)
      throw fail(path, "no frame for " + std::to_string(kFrameTimeoutMs / 1000) +
                           " s before its recorded end (depth frame " +
                           std::to_string(depth.last_index) + " of " +
                           std::to_string(depth.recorded) + ", colour frame " +
                           std::to_string(colour.last_index) + " of " +
                           std::to_string(colour.recorded) + "): truncated or corrupt");
    Stream& s = *owners[ready];
    if (s.stream.readFrame(&s.pending) != openni::STATUS_OK)
      throw fail(path, "cannot read a frame: " + openniError());
    const int index = s.pending.getFrameIndex();
    if (index > s.last_index + 1) s.dropped += static_cast<std::size_t>(index - s.last_index - 1);
    s.last_index = std::max(s.last_index, index);
    return true;
  }

  /** Throws unless `f` holds a whole image of the recording's size with `bpp` bytes per pixel. */
  void checkFrame(const openni::VideoFrameRef& f, const char* name, int bpp) const {
    const bool fits = f.getWidth() == static_cast<int>(camera.ncols) &&
                      f.getHeight() == static_cast<int>(camera.nrows) &&
                      f.getStrideInBytes() >= f.getWidth() * bpp &&
                      f.getDataSize() >= f.getHeight() * f.getStrideInBytes();
    if (!fits)
      throw fail(path, std::string(name) + " frame " + std::to_string(f.getFrameIndex()) + " is " +
                           std::to_string(f.getWidth()) + "x" + std::to_string(f.getHeight()) +
                           " in " + std::to_string(f.getDataSize()) + " bytes, not a whole " +
                           std::to_string(camera.ncols) + "x" + std::to_string(camera.nrows) +
                           " image (corrupt)");
  }

  mrpt::obs::CObservation3DRangeScan::Ptr makeFrame() {
    const auto& d = depth.pending;
    const auto& c = colour.pending;
    checkFrame(d, "depth", 2);
    checkFrame(c, "colour", 3);
    const cv::Mat depth_raw(d.getHeight(), d.getWidth(), CV_16UC1, const_cast<void*>(d.getData()),
                            static_cast<std::size_t>(d.getStrideInBytes()));
    const cv::Mat rgb(c.getHeight(), c.getWidth(), CV_8UC3, const_cast<void*>(c.getData()),
                      static_cast<std::size_t>(c.getStrideInBytes()));
    cv::Mat bgr;
    cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
    // makeRgbdObservation copies the depth; the frames go back to OpenNI below.
    auto obs = makeRgbdObservation(
        bgr, depth_raw.clone(), depth_unit, camera,
        frameTimeFromSeconds(static_cast<double>(c.getTimestamp()) * 1e-6), "OpenNI2");
    depth.pending.release();
    colour.pending.release();
    return obs;
  }
};

OniFileSource::OniFileSource(const std::string& path) : m(std::make_unique<Impl>()) {
  m->path = path;
  // OpenNI2 says only "Couldn't open device" for a missing file or another format: check first.
  requireRegularFile(path, "OpenNI recording");  // OpenNI2 seeks in it
  std::ifstream probe(path, std::ios::binary);
  if (!probe) throw fail(path, "cannot open the file (missing or unreadable)");
  char magic[4] = {};
  probe.read(magic, 4);
  if (probe.gcount() != 4 || std::memcmp(magic, "NI10", 4) != 0)
    throw fail(path, "not an ONI file (it does not start with \"NI10\")");
  probe.close();
  const auto gt = groundTruthPathFor(path);
  if (std::filesystem::exists(gt)) m->ground_truth = loadTumTrajectory(gt);

  if (openni::OpenNI::initialize() != openni::STATUS_OK)
    throw fail(path, "OpenNI2 cannot start: " + openniError());
  if (m->device.open(path.c_str()) != openni::STATUS_OK)
    throw fail(path,
               "OpenNI2's file driver cannot open it (truncated or corrupt?): " + openniError());
  auto* playback = m->device.getPlaybackControl();
  if (!playback) throw fail(path, "OpenNI2 opened it as a live device, not as a recording");
  // Manual speed: each frame waits to be taken, so none is lost; no repeat: the run ends.
  if (playback->setSpeed(-1) != openni::STATUS_OK ||
      playback->setRepeatEnabled(false) != openni::STATUS_OK)
    throw fail(path, "cannot set the playback speed and repeat: " + openniError());
  m->openStream(m->depth, openni::SENSOR_DEPTH, "depth");
  m->openStream(m->colour, openni::SENSOR_COLOR, "colour");

  const auto dm = m->depth.stream.getVideoMode();
  const auto cm = m->colour.stream.getVideoMode();
  switch (dm.getPixelFormat()) {
    case openni::PIXEL_FORMAT_DEPTH_1_MM:
      m->depth_unit = 0.001;
      break;
    case openni::PIXEL_FORMAT_DEPTH_100_UM:
      m->depth_unit = 0.0001;
      break;
    default:
      throw fail(path, "unsupported depth pixel format " + std::to_string(dm.getPixelFormat()) +
                           " (DEPTH_1_MM or DEPTH_100_UM expected)");
  }
  if (cm.getPixelFormat() != openni::PIXEL_FORMAT_RGB888)
    throw fail(path, "unsupported colour pixel format " + std::to_string(cm.getPixelFormat()) +
                         " (RGB888 expected)");

  const double hfov = m->colour.stream.getHorizontalFieldOfView();
  const double vfov = m->colour.stream.getVerticalFieldOfView();
  if (m->device.isImageRegistrationModeSupported(openni::IMAGE_REGISTRATION_DEPTH_TO_COLOR)) {
    if (m->device.setImageRegistrationMode(openni::IMAGE_REGISTRATION_DEPTH_TO_COLOR) !=
        openni::STATUS_OK)
      throw fail(path, "cannot switch on depth-to-colour registration: " + openniError());
    m->registration = "depth registered to colour by the device";
  } else {
    // OpenNI2's file driver supports IMAGE_REGISTRATION_OFF only (PlayerDevice keeps the
    // driver API's default isImageRegistrationModeSupported()), and a recording holds no
    // depth-to-colour extrinsics to register it here: depth must have been registered when
    // recorded. A recording does not say whether it was; its sizes at least must agree.
    if (dm.getResolutionX() != cm.getResolutionX() || dm.getResolutionY() != cm.getResolutionY())
      throw fail(path, "depth (" + std::to_string(dm.getResolutionX()) + "x" +
                           std::to_string(dm.getResolutionY()) + ") and colour (" +
                           std::to_string(cm.getResolutionX()) + "x" +
                           std::to_string(cm.getResolutionY()) +
                           ") differ, so depth was not registered to colour when recorded, and "
                           "OpenNI2's file driver cannot register it "
                           "(IMAGE_REGISTRATION_DEPTH_TO_COLOR is not supported for recordings, "
                           "which hold no depth-to-colour extrinsics): record with registration "
                           "on");
    m->registration = "depth taken as registered to colour when recorded";
    const auto near = [](double a, double b) { return std::abs(a - b) <= 0.01 * std::abs(b); };
    if (!near(m->depth.stream.getHorizontalFieldOfView(), hfov) ||
        !near(m->depth.stream.getVerticalFieldOfView(), vfov))
      m->registration +=
          " (its field of view differs from colour's: if it was recorded without "
          "registration, depth and colour are misaligned)";
  }
  if (!(hfov > 0.05 && hfov < 3.0 && vfov > 0.05 && vfov < 3.0))
    throw fail(path, "colour field of view " + std::to_string(hfov) + " x " + std::to_string(vfov) +
                         " rad is not a camera's");
  const int w = cm.getResolutionX(), h = cm.getResolutionY();
  m->camera.ncols = static_cast<uint32_t>(w);
  m->camera.nrows = static_cast<uint32_t>(h);
  m->camera.fx(0.5 * w / std::tan(0.5 * hfov));
  m->camera.fy(0.5 * h / std::tan(0.5 * vfov));
  m->camera.cx(0.5 * (w - 1));
  m->camera.cy(0.5 * (h - 1));
  m->max_dt_us = 0.5e6 / std::max(1, cm.getFps());

  m->device.setDepthColorSyncEnabled(true);  // best effort: frames are paired below anyway
  if (m->depth.stream.start() != openni::STATUS_OK || m->colour.stream.start() != openni::STATUS_OK)
    throw fail(path, "cannot start its streams: " + openniError());
}

OniFileSource::~OniFileSource() = default;

mrpt::obs::CObservation3DRangeScan::Ptr OniFileSource::next() {
  for (;;) {
    while (!m->depth.pending.isValid() || !m->colour.pending.isValid())
      if (!m->readAny()) return nullptr;  // a stream has ended: no more pairs
    const auto td = static_cast<double>(m->depth.pending.getTimestamp());
    const auto tc = static_cast<double>(m->colour.pending.getTimestamp());
    if (std::abs(td - tc) <= m->max_dt_us) {
      ++m_stats.frames;
      return m->makeFrame();
    }
    (td < tc ? m->depth : m->colour).pending.release();  // the older has no partner
    ++m->unpaired;
  }
}

std::string OniFileSource::describe() const {
  std::ostringstream s;
  s << "OpenNI recording " << m->path << " (" << m->camera.ncols << "x" << m->camera.nrows << ", "
    << m->depth.recorded << " depth and " << m->colour.recorded << " colour frames, fx "
    << std::fixed << std::setprecision(1) << m->camera.fx() << " px from the field of view; "
    << m->registration << ")";
  return s.str();
}

Trajectory OniFileSource::groundTruth() const { return m->ground_truth; }

std::vector<JobPath> OniFileSource::inputs() const {
  return {{m->path, "the input recording (--input)"},
          {groundTruthPathFor(m->path), "the input recording's ground truth"}};
}

std::size_t OniFileSource::droppedFrames() const { return m->depth.dropped + m->colour.dropped; }
std::size_t OniFileSource::unpairedFrames() const { return m->unpaired; }
std::size_t OniFileSource::recordedDepthFrames() const {
  return static_cast<std::size_t>(m->depth.recorded);
}
std::size_t OniFileSource::recordedColourFrames() const {
  return static_cast<std::size_t>(m->colour.recorded);
}

}  // namespace hrgbd
