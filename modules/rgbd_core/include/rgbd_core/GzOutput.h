#pragma once
/** \file GzOutput.h
 * gzip-compressed MRPT archives (rawlogs, .simplemap, .3Dscene) written in full or not at all.
 * Hand-written over zlib because MRPT's CFileGZOutputStream drops the result of gzclose(), where
 * a full disk shows: its files could be cut short without an error. */
#include <mrpt/io/CStream.h>
#include <mrpt/serialization/CSerializable.h>

#include <cstdint>
#include <string>

#include "rgbd_core/OutputFile.h"

namespace hrgbd {

/** A gzip output stream on an OutputFile: a failed write throws std::runtime_error naming the
 * file, close() checks the end of the stream and moves the file into place. Destroyed without
 * close(), it leaves nothing under the output's name. */
class GzOutputStream : public mrpt::io::CStream {
 public:
  /** `what` names the output in messages ("rawlog", ...); `level` is the gzip level, 1..9. */
  GzOutputStream(const std::string& path, const std::string& what, int level = 1);
  ~GzOutputStream() override;
  size_t Write(const void* buffer, size_t count) override;
  /** Completes the file and moves it into place; throws naming it on failure. */
  void close();
  const std::string& path() const { return m_file.path(); }

  size_t Read(void*, size_t) override;
  uint64_t Seek(int64_t, CStream::TSeekOrigin) override;
  uint64_t getTotalBytesCount() const override { return m_written; }
  uint64_t getPosition() const override { return m_written; }

 private:
  OutputFile m_file;
  void* m_gz = nullptr;  // gzFile
  uint64_t m_written = 0;
};

/** Saves `obj` as a gzip-compressed MRPT archive, as MRPT's own saveToFile() methods do (level
 * 1), in full or not at all; throws std::runtime_error naming the file (`what`). */
void saveCompressed(const mrpt::serialization::CSerializable& obj, const std::string& path,
                    const std::string& what);

}  // namespace hrgbd
