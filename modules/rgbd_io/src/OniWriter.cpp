#include "rgbd_io/OniWriter.h"

#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace hrgbd {
namespace {

// Record types and constants of the ONI format (OpenNI2 Source/Core/OniDataRecords.h).
constexpr std::uint32_t kRecordMagic = 0x0052494E;  // "NIR\0"
enum : std::uint32_t {
  kIntProperty = 0x03,
  kGeneralProperty = 0x06,
  kNodeRemoved = 0x07,
  kNodeDataBegin = 0x08,
  kNodeStateReady = 0x09,
  kNewData = 0x0A,
  kEnd = 0x0B,
  kNodeAdded = 0x0D,
  kSeekTable = 0x0E,
};
constexpr std::uint32_t kCodecNone = 'N' | ('O' << 8) | ('N' << 16) | (std::uint32_t('E') << 24);
constexpr std::size_t kRecordHeaderSize =
    28;  // magic, type, node, fields, payload (u32), undo (u64)

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "the ONI format is little-endian");

template <class T>
void put(std::string& s, T value) {
  s.append(reinterpret_cast<const char*>(&value), sizeof(value));
}

void putString(std::string& s, const std::string& text) {
  put<std::uint32_t>(s, static_cast<std::uint32_t>(text.size() + 1));
  s.append(text.c_str(), text.size() + 1);
}

}  // namespace

OniWriter::OniWriter(const std::string& path, const OniStreamSpec& depth,
                     const OniStreamSpec& colour)
    : m_output(path, "OpenNI recording"),
      m_file(m_output.writePath(), std::ios::binary | std::ios::trunc) {
  if (!m_file) m_output.fail();
  std::string header = "NI10";
  put<std::uint8_t>(header, 1);  // version 1.0.1.0, as OpenNI2's Recorder writes
  put<std::uint8_t>(header, 0);
  put<std::uint16_t>(header, 1);
  put<std::uint32_t>(header, 0);
  put<std::uint64_t>(header, 0);  // max time stamp, patched by close()
  put<std::uint32_t>(header, 0);  // max node id, patched by close()
  m_file.write(header.data(), static_cast<std::streamsize>(header.size()));
  std::uint32_t next_id = 1;
  if (depth.width > 0) {
    m_depth = {next_id++, 2, "Depth", depth, 0, 0, 0, 0, {}};
    addNode(m_depth, 100 /*ONI_PIXEL_FORMAT_DEPTH_1_MM*/, 4 /*grey 16*/, 2);
  }
  if (colour.width > 0) {
    m_colour = {next_id++, 3, "Image", colour, 0, 0, 0, 0, {}};
    addNode(m_colour, 200 /*ONI_PIXEL_FORMAT_RGB888*/, 1 /*RGB24*/, 3);
  }
  for (const Node* n : {&m_depth, &m_colour})
    if (n->id) {
      record(kNodeStateReady, n->id, 0, "");
      std::string f;
      put<std::uint32_t>(f, 0xFFFFFFFFu);  // frame count and max time stamp: unknown yet
      put<std::uint64_t>(f, ~std::uint64_t(0));
      record(kNodeDataBegin, n->id, 0, f);
    }
}

void OniWriter::addNode(Node& n, std::uint32_t pixel_format, std::uint32_t xn_pixel_format,
                        int bpp) {
  n.added_pos = static_cast<std::uint64_t>(m_file.tellp());
  writeNodeAdded(n, 0xFFFFFFFFu, 0);
  const auto w = static_cast<std::uint32_t>(n.spec.width);
  const auto h = static_cast<std::uint32_t>(n.spec.height);
  const auto fps = static_cast<std::uint32_t>(n.spec.fps);
  intProperty(n, "oniRequiredFrameSize", std::uint64_t(w) * h * bpp);
  intProperty(n, "xnIsGenerating", 1);
  if (n.type == 2) intProperty(n, "xnDeviceMaxDepth", 10000);
  intProperty(n, "xnSupportedMapOutputModesCount", 1);
  const std::uint32_t mode[3] = {w, h, fps};
  generalProperty(n, "xnSupportedMapOutputModes", mode, sizeof(mode));
  generalProperty(n, "xnMapOutputMode", mode, sizeof(mode));
  const std::uint32_t supported = 1u << (xn_pixel_format - 1);  // bit field, one bit per format
  generalProperty(n, "xnSupportedPixelFormats", &supported, sizeof(supported));
  intProperty(n, "xnPixelFormat", xn_pixel_format);
  intProperty(n, "oniPixelFormat", pixel_format);
  const double fov[2] = {n.spec.hfov, n.spec.vfov};
  generalProperty(n, "xnFOV", fov, sizeof(fov));
  // Cropping (off): the player drops every frame of a stream whose cropping it cannot read.
  intProperty(n, "Cropping", 1);
  struct {
    std::int32_t enabled;
    std::uint16_t x, y, width, height;
  } cropping = {0, 0, 0, 0, 0};
  static_assert(sizeof(cropping) == 12);
  generalProperty(n, "xnCropping", &cropping, sizeof(cropping));
}

void OniWriter::writeNodeAdded(const Node& n, std::uint32_t frames, std::uint64_t seek_pos) {
  std::string f;
  putString(f, n.name);
  put<std::uint32_t>(f, n.type);
  put<std::uint32_t>(f, kCodecNone);
  put<std::uint32_t>(f, frames);
  put<std::uint64_t>(f, 0);                                         // min time stamp
  put<std::uint64_t>(f, frames == 0xFFFFFFFFu ? ~0ull : n.max_ts);  // max time stamp
  put<std::uint64_t>(f, seek_pos);
  record(kNodeAdded, n.id, 0, f);
}

void OniWriter::intProperty(const Node& n, const char* name, std::uint64_t value) {
  std::string f;
  putString(f, name);
  put<std::uint32_t>(f, sizeof(value));
  put<std::uint64_t>(f, value);
  record(kIntProperty, n.id, 0, f);
}

void OniWriter::generalProperty(const Node& n, const char* name, const void* data,
                                std::uint32_t size) {
  std::string f;
  putString(f, name);
  put<std::uint32_t>(f, size);
  f.append(static_cast<const char*>(data), size);
  record(kGeneralProperty, n.id, 0, f);
}

std::uint64_t OniWriter::record(std::uint32_t type, std::uint32_t node, std::uint64_t undo,
                                const std::string& fields, const void* payload,
                                std::size_t payload_size) {
  const auto pos = static_cast<std::uint64_t>(m_file.tellp());
  std::string h;
  put<std::uint32_t>(h, kRecordMagic);
  put<std::uint32_t>(h, type);
  put<std::uint32_t>(h, node);
  put<std::uint32_t>(h, static_cast<std::uint32_t>(kRecordHeaderSize + fields.size()));
  put<std::uint32_t>(h, static_cast<std::uint32_t>(payload_size));
  put<std::uint64_t>(h, undo);
  m_file.write(h.data(), static_cast<std::streamsize>(h.size()));
  m_file.write(fields.data(), static_cast<std::streamsize>(fields.size()));
  if (payload_size)
    m_file.write(static_cast<const char*>(payload), static_cast<std::streamsize>(payload_size));
  if (!m_file) m_output.fail();
  return pos;
}

void OniWriter::writeFrame(Node& n, std::uint64_t ts, std::uint32_t index, const void* data,
                           std::size_t size) {
  if (!n.id) throw std::logic_error("OniWriter: this recording has no such stream");
  std::string f;
  put<std::uint64_t>(f, ts);
  put<std::uint32_t>(f, index);
  n.last_data_pos = record(kNewData, n.id, n.last_data_pos, f, data, size);
  if (index <= n.frames) throw std::invalid_argument("OniWriter: frame indices must increase");
  n.index.push_back({ts, n.last_data_pos, index});
  n.frames = index;  // the player takes the last index as the stream's frame count
  n.max_ts = std::max(n.max_ts, ts);
}

void OniWriter::writeDepth(std::uint64_t timestamp_us, std::uint32_t frame_index,
                           const cv::Mat& depth_mm) {
  if (depth_mm.type() != CV_16UC1 || depth_mm.cols != m_depth.spec.width ||
      depth_mm.rows != m_depth.spec.height)
    throw std::invalid_argument("OniWriter: depth must be CV_16UC1 of the stream's size");
  const cv::Mat d = depth_mm.isContinuous() ? depth_mm : depth_mm.clone();
  writeFrame(m_depth, timestamp_us, frame_index, d.data, d.total() * d.elemSize());
}

void OniWriter::writeColour(std::uint64_t timestamp_us, std::uint32_t frame_index,
                            const cv::Mat& bgr) {
  if (bgr.type() != CV_8UC3 || bgr.cols != m_colour.spec.width || bgr.rows != m_colour.spec.height)
    throw std::invalid_argument("OniWriter: colour must be CV_8UC3 of the stream's size");
  cv::Mat rgb;
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  writeFrame(m_colour, timestamp_us, frame_index, rgb.data, rgb.total() * rgb.elemSize());
}

void OniWriter::close() {
  if (m_closed) return;
  m_closed = true;
  std::uint64_t max_ts = 0;
  for (Node* n : {&m_depth, &m_colour}) {
    if (!n->id) continue;
    if (n->index.empty()) throw std::logic_error("OniWriter: a stream without frames");
    record(kNodeRemoved, n->id, n->added_pos, "");
    // Seek table: an empty entry for frame 0, then one per frame (time stamp, configuration id,
    // file position), 20 bytes each.
    // The table is indexed by frame number: a frame missing from the recording (a gap in the
    // indices) repeats the entry before it.
    std::string table(20, '\0');
    std::size_t k = 0;
    for (std::uint32_t f = 1; f <= n->frames; ++f) {
      while (k + 1 < n->index.size() && n->index[k + 1].frame <= f) ++k;
      put<std::uint64_t>(table, n->index[k].ts);
      put<std::uint32_t>(table, 0);
      put<std::uint64_t>(table, n->index[k].pos);
    }
    const auto seek_pos = record(kSeekTable, n->id, 0, "", table.data(), table.size());
    const auto end = m_file.tellp();
    m_file.seekp(static_cast<std::streamoff>(n->added_pos));
    writeNodeAdded(*n, n->frames, seek_pos);
    m_file.seekp(end);
    max_ts = std::max(max_ts, n->max_ts);
  }
  record(kEnd, 0, 0, "");
  m_file.seekp(12);  // header: "NI10", version (8 bytes), then max time stamp and max node id
  std::string patch;
  put<std::uint64_t>(patch, max_ts);
  put<std::uint32_t>(patch, m_colour.id ? m_colour.id : m_depth.id);
  m_file.write(patch.data(), static_cast<std::streamsize>(patch.size()));
  m_file.close();
  if (!m_file) m_output.fail();
  m_output.commit();
}

OniWriter::~OniWriter() = default;

}  // namespace hrgbd
