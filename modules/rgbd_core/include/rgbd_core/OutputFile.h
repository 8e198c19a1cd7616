#pragma once
/** \file OutputFile.h
 * Output files written in full or not at all, every write checked.
 *
 * An output that is a regular file, or does not exist yet, is written to a temporary file beside
 * it (".<name>.<pid>-<n>.tmp", same folder, so on the same file system; a name too long for that
 * keeps as many of its first bytes as fit in 255) and renamed onto its name
 * by commit() once complete and checked: a run that fails on the way leaves the previous file or
 * none, never a truncated one that looks complete. A symbolic link is followed: its target is
 * replaced. An output that exists and is not a regular file (a device such as /dev/null or
 * /dev/full, a FIFO, a terminal) cannot be replaced by renaming: it is written directly, and every
 * write and the close are checked just the same, so /dev/full is an error and /dev/null is not.
 * A program killed outright (SIGKILL, power loss) can leave a temporary file behind, never a
 * partial output under the output's name; SIGINT and SIGTERM remove it (Interrupt.h). */
#include <cstddef>
#include <fstream>
#include <ostream>
#include <string>

namespace hrgbd {

/** One output file: where to write it until it is complete, and moving it into place. */
class OutputFile {
 public:
  /** `what` names the output in messages ("trajectory", "CSV", ...). Throws std::runtime_error
   * naming the file when it cannot be written (missing folder, a folder of that name). */
  OutputFile(const std::string& path, const std::string& what);
  /** Removes the temporary file unless commit() succeeded. */
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  /** Where the writer writes until commit(): the temporary file, or the output itself when it
   * is not a regular file. */
  const std::string& writePath() const { return m_write_path; }
  /** The output's name as given. */
  const std::string& path() const { return m_path; }
  /** Moves the complete file into place (keeping the replaced file's permissions); throws
   * std::runtime_error naming the file if it cannot. Call once, after the writer closed. */
  void commit();
  /** Throws std::runtime_error "cannot write <what> '<path>': <detail>" (the errno text when
   * `detail` is empty and errno is set). For writers that detect a failure. */
  [[noreturn]] void fail(const std::string& detail = "") const;

 private:
  std::string m_path, m_what, m_target, m_write_path;
  bool m_direct = false, m_done = false;
  int m_slot = -1;  //!< registerTemporary()'s slot of the temporary file
};

/** An output written through an std::ofstream on an OutputFile. The stream's state is checked by
 * flush() and commit(), which throw naming the file once a write failed (full disk, /dev/full,
 * I/O error). Destroyed without commit(), it leaves nothing under the output's name. */
class StreamOutput {
 public:
  StreamOutput(const std::string& path, const std::string& what, bool binary = false);
  std::ostream& stream() { return m_stream; }
  /** Flushes what was written so far; throws if a write failed. */
  void flush();
  /** Flushes, closes, checks and moves the file into place. */
  void commit();
  const std::string& path() const { return m_file.path(); }

 private:
  OutputFile m_file;
  std::ofstream m_stream;
};

/** Writes `size` bytes to `path` in full or not at all; throws naming the file (`what`). */
void writeOutputFile(const std::string& path, const std::string& what, const void* data,
                     std::size_t size);

}  // namespace hrgbd
