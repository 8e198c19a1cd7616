#include "rgbd_core/GzOutput.h"

#include <mrpt/serialization/CArchive.h>
#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <limits>
#include <stdexcept>

#include "rgbd_core/ErrorText.h"

namespace hrgbd {

GzOutputStream::GzOutputStream(const std::string& path, const std::string& what, int level)
    : m_file(path, what) {
  const std::string mode = "wb" + std::to_string(level < 1 || level > 9 ? 1 : level);
  errno = 0;
  m_gz = gzopen(m_file.writePath().c_str(), mode.c_str());
  if (!m_gz) m_file.fail();
}

GzOutputStream::~GzOutputStream() {
  if (m_gz) gzclose(static_cast<gzFile>(m_gz));  // not completed: OutputFile discards it
}

size_t GzOutputStream::Write(const void* buffer, size_t count) {
  if (!m_gz) throw std::logic_error("GzOutputStream: write after close() to '" + path() + "'");
  const auto* p = static_cast<const char*>(buffer);
  for (size_t left = count; left > 0;) {
    const auto chunk = static_cast<unsigned>(std::min<size_t>(left, 1u << 30));
    errno = 0;
    const int n = gzwrite(static_cast<gzFile>(m_gz), p, chunk);
    if (n <= 0) {
      int code = 0;
      const char* msg = gzerror(static_cast<gzFile>(m_gz), &code);
      m_file.fail(code == Z_ERRNO ? "" : msg);
    }
    p += n, left -= static_cast<size_t>(n);
  }
  m_written += count;
  return count;
}

void GzOutputStream::close() {
  if (!m_gz) throw std::logic_error("GzOutputStream: close() twice for '" + path() + "'");
  errno = 0;
  const int r = gzclose(static_cast<gzFile>(m_gz));
  m_gz = nullptr;
  if (r != Z_OK) m_file.fail(r == Z_ERRNO ? "" : "gzip error " + std::to_string(r));
  m_file.commit();
}

size_t GzOutputStream::Read(void*, size_t) {
  throw std::logic_error("GzOutputStream: cannot read '" + path() + "'");
}

uint64_t GzOutputStream::Seek(int64_t, CStream::TSeekOrigin) {
  throw std::logic_error("GzOutputStream: cannot seek in '" + path() + "'");
}

void saveCompressed(const mrpt::serialization::CSerializable& obj, const std::string& path,
                    const std::string& what) {
  GzOutputStream out(path, what, 1);
  auto archive = mrpt::serialization::archiveFrom(out);
  try {
    archive << obj;
  } catch (const std::exception& e) {  // MRPT wraps the stream's error in its banner
    throw std::runtime_error(errorText(e));
  }
  out.close();
}

}  // namespace hrgbd
