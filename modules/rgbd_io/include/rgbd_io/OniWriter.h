#pragma once
/** \file OniWriter.h
 * Writes RGB-D frames as an OpenNI recording (.oni) that OpenNI2's own file driver (libOniFile)
 * plays (OniFileSource.h, or any OpenNI2 program), e.g. simulated sequences (rgbd-simulate
 * --oni). OpenNI2's Recorder needs an opened device (a sensor), so this writes the format by hand,
 * record by record as the Recorder does (file header, node-added, property, state-ready, data-begin
 * and new-data records, then per stream a node-removed record and a seek table, the node-added
 * records rewritten with the frame count and seek table position, and the end record). Frames are
 * stored uncompressed (codec "NONE"): depth as DEPTH_1_MM (uint16 millimetres), colour as RGB888.
 * The layout follows OpenNI2's sources (Source/Core/OniRecorder.cpp and OniDataRecords.h, the
 * reader in Source/Drivers/OniFile/PlayerNode.cpp); like them, little-endian hosts only.
 */
#include <cstdint>
#include <fstream>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "rgbd_core/OutputFile.h"

namespace hrgbd {

/** One stream of the recording. */
struct OniStreamSpec {
  int width = 640, height = 480;  //!< [px]
  double hfov = 1.0, vfov = 0.8;  //!< [rad] fields of view (the only intrinsics a recording has)
  int fps = 30;                   //!< [Hz] nominal rate in the video mode
};

class OniWriter {
 public:
  /** Starts the file (an OutputFile: it appears under its name only when close() succeeds);
   * either spec may be absent (width 0) to write a recording without that stream. Throws naming
   * the file if it cannot be written. */
  OniWriter(const std::string& path, const OniStreamSpec& depth, const OniStreamSpec& colour);
  /** Without close(): nothing is left under the recording's name. */
  ~OniWriter();
  /** Appends one depth frame (CV_16UC1, millimetres) with the device time [us] and frame index
   * (1, 2, ...; increasing, gaps allowed: they stand for frames the device dropped). */
  void writeDepth(std::uint64_t timestamp_us, std::uint32_t frame_index, const cv::Mat& depth_mm);
  /** Appends one colour frame (CV_8UC3, BGR as OpenCV holds it; stored as RGB). */
  void writeColour(std::uint64_t timestamp_us, std::uint32_t frame_index, const cv::Mat& bgr);
  /** Writes the seek tables, patches the node records and the header, closes the file and moves
   * it into place; throws naming the file if a write failed. */
  void close();

 private:
  struct Node {
    std::uint32_t id = 0, type = 0;  // OpenNI 1 node type: 2 depth, 3 image
    std::string name;
    OniStreamSpec spec;
    std::uint64_t added_pos = 0, last_data_pos = 0, max_ts = 0;
    std::uint32_t frames = 0;  // last frame index written
    struct Entry {
      std::uint64_t ts, pos;
      std::uint32_t frame;
    };
    std::vector<Entry> index;
  };
  void addNode(Node& n, std::uint32_t pixel_format, std::uint32_t xn_pixel_format, int bpp);
  void writeNodeAdded(const Node& n, std::uint32_t frames, std::uint64_t seek_pos);
  void writeFrame(Node& n, std::uint64_t ts, std::uint32_t index, const void* data,
                  std::size_t size);
  /** Writes one record: header (28 bytes), `fields` (after the header), `payload`. */
  std::uint64_t record(std::uint32_t type, std::uint32_t node, std::uint64_t undo,
                       const std::string& fields, const void* payload = nullptr,
                       std::size_t payload_size = 0);
  void intProperty(const Node& n, const char* name, std::uint64_t value);
  void generalProperty(const Node& n, const char* name, const void* data, std::uint32_t size);

  OutputFile m_output;
  std::ofstream m_file;
  Node m_depth, m_colour;
  bool m_closed = false;
};

}  // namespace hrgbd
