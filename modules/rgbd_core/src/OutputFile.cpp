#include "rgbd_core/OutputFile.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "rgbd_core/Interrupt.h"

namespace hrgbd {
namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMaxName = 255;  // NAME_MAX of Linux file systems

/** Creates a new, empty file beside `target` whose name no other writer uses; returns its path.
 * `error` is set (and "" returned) if the folder does not take it. */
std::string createTemporary(const fs::path& target, std::string& error) {
  static std::atomic<unsigned> counter{0};
  for (int attempt = 0; attempt < 100; ++attempt) {
    const auto suffix = "." + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ".tmp";
    // A name near the file system's limit (255 bytes) must leave room for the suffix: the
    // temporary name keeps as much of it as fits.
    const auto stem = target.filename().string().substr(0, kMaxName - 1 - suffix.size());
    const auto name = "." + stem + suffix;
    const auto tmp = (target.parent_path() / name).string();
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);
      return tmp;
    }
    if (errno != EEXIST) break;
  }
  error = std::strerror(errno);
  return "";
}

}  // namespace

OutputFile::OutputFile(const std::string& path, const std::string& what)
    : m_path(path), m_what(what) {
  if (path.empty()) fail("no file name");
  std::error_code ec;
  const auto status = fs::status(path, ec);  // follows symbolic links
  if (fs::is_directory(status)) fail("it is a folder");
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    m_direct = true;  // a device or FIFO: written in place, see the file comment
    m_write_path = path;
    return;
  }
  // A symbolic link's target is replaced, in the target's folder.
  const fs::path target = fs::weakly_canonical(fs::absolute(path), ec);
  if (ec) fail(ec.message());
  if (!fs::is_directory(target.parent_path()))
    fail("folder '" + target.parent_path().string() + "' does not exist");
  m_target = target.string();
  std::string error;
  m_write_path = createTemporary(target, error);
  if (m_write_path.empty()) fail(error);
  m_slot = registerTemporary(m_write_path);
}

OutputFile::~OutputFile() {
  if (m_done || m_write_path.empty()) return;
  if (interrupted()) noteNotWritten(m_what + " '" + m_path + "'" + (m_direct ? " (in part)" : ""));
  if (m_direct) return;
  std::error_code ec;
  fs::remove(m_write_path, ec);
  unregisterTemporary(m_slot);
}

void OutputFile::commit() {
  if (m_done) throw std::logic_error("OutputFile::commit() twice for '" + m_path + "'");
  if (!m_direct) {
    std::error_code ec;
    const auto old = fs::status(m_target, ec);
    if (fs::is_regular_file(old)) fs::permissions(m_write_path, old.permissions(), ec);
    fs::rename(m_write_path, m_target, ec);
    if (ec) fail(ec.message());
    unregisterTemporary(m_slot);
  }
  m_done = true;
}

void OutputFile::fail(const std::string& detail) const {
  std::string why = detail;
  if (why.empty() && errno != 0) why = std::strerror(errno);
  throw std::runtime_error("cannot write " + m_what + " '" + m_path + "'" +
                           (why.empty() ? "" : ": " + why));
}

StreamOutput::StreamOutput(const std::string& path, const std::string& what, bool binary)
    : m_file(path, what) {
  errno = 0;
  m_stream.open(m_file.writePath(), binary ? std::ios::out | std::ios::trunc | std::ios::binary
                                           : std::ios::out | std::ios::trunc);
  if (!m_stream) m_file.fail();
}

void StreamOutput::flush() {
  if (m_stream) {  // a write that failed already left its errno
    errno = 0;
    m_stream.flush();
  }
  if (!m_stream) m_file.fail();
}

void StreamOutput::commit() {
  flush();
  m_stream.close();
  if (!m_stream) m_file.fail();
  m_file.commit();
}

void writeOutputFile(const std::string& path, const std::string& what, const void* data,
                     std::size_t size) {
  StreamOutput out(path, what, true);
  out.stream().write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.commit();
}

}  // namespace hrgbd
