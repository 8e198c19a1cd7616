#pragma once
/** \file OniFileSource.h
 * An OpenNI recording (.oni) played through OpenNI2's own file driver (libOniFile), the same API
 * as a live sensor: openni::Device::open("file.oni"). */
#include <cstddef>
#include <memory>
#include <string>

#include "rgbd_io/FrameSource.h"

namespace hrgbd {

/** Plays the depth and colour streams of a recording, frame by frame and losslessly (OpenNI's
 * "manual" playback speed, -1: a frame is produced when the previous one has been taken), once
 * (repeat off): next() returns nullptr after the last frame of either stream.
 *
 * - Registration: depth-to-colour registration (IMAGE_REGISTRATION_DEPTH_TO_COLOR) is switched
 *   on when the device supports it. OpenNI2's file driver never does (a recording is played as
 *   recorded) and a recording holds no depth-to-colour extrinsics to register it in software, so
 *   depth is then taken as registered when recorded: equal resolutions are required (otherwise
 *   the constructor refuses, saying so), and describe() says when the two fields of view differ
 *   (a recording made without registration would then be misaligned).
 * - Intrinsics: from the colour stream's fields of view (the only intrinsics a recording holds):
 *   fx = (width / 2) / tan(hfov / 2), principal point at the image centre ((w - 1) / 2).
 * - Pairing: depth and colour frames are paired when their device time stamps differ by less
 *   than half a colour frame period; an unpaired frame is passed over and counted.
 * - Time stamps: the colour frame's device time [us] as seconds (Timestamp.h), i.e. seconds
 *   since the device started, not UNIX time.
 * - Dropped frames: gaps in a stream's frame indices are counted (droppedFrames()).
 * - Ground truth: "<dir>/<stem>_groundtruth.txt" beside the recording when it exists (TUM format,
 *   in the recording's clock), as for rawlogs (rgbd-simulate --oni writes one).
 * Errors throw std::runtime_error naming the file: missing file, not an ONI file, a recording
 * OpenNI2 cannot open (truncated or corrupt), no depth or no colour stream, an unsupported pixel
 * format, and a recording that stops delivering frames before its recorded end. */
class OniFileSource : public FrameSource {
 public:
  explicit OniFileSource(const std::string& path);
  ~OniFileSource() override;
  mrpt::obs::CObservation3DRangeScan::Ptr next() override;
  Trajectory groundTruth() const override;
  std::string describe() const override;
  /** The recording and its ground truth file. */
  std::vector<JobPath> inputs() const override;

  /** [count] frames missing from the streams' frame indices (depth + colour). */
  std::size_t droppedFrames() const;
  /** [count] frames passed over because no frame of the other stream was close in time. */
  std::size_t unpairedFrames() const;
  /** [count] frames of the depth and of the colour stream, as recorded. */
  std::size_t recordedDepthFrames() const;
  std::size_t recordedColourFrames() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> m;
};

/** True if `path` names an OpenNI recording by its extension (".oni", any case). */
bool isOniFile(const std::string& path);

}  // namespace hrgbd
