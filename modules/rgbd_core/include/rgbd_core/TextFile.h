#pragma once
/** \file TextFile.h
 * Opening the project's inputs as users name them: text inputs (TUM lists, trajectories, INI
 * files, vocabularies) as a user's editor may have saved them, and the check that a file read
 * in place (an image, a rawlog, a recording) is a regular file, so that `/dev/zero`, a FIFO or a
 * folder given by mistake is an error naming it rather than a hang or a read without end. */
#include <cstddef>
#include <string>
#include <string_view>

namespace hrgbd {

/** At most this many bytes are read from a pipe or FIFO given as a text input (`-c <(...)`):
 * far above any list, trajectory or INI file, far below the memory a read without end takes. */
constexpr std::size_t kMaxPipedText = std::size_t{64} << 20;

/** `text` without a leading UTF-8 byte-order mark (EF BB BF), which Windows editors put at the
 * start of a file and which would otherwise be read as part of the first word. */
std::string_view withoutBom(std::string_view text);

/** What `path` is when it is neither a regular file nor missing ("a folder", "a FIFO (named
 * pipe)", "a character device", "a block device", "a socket"); "" for a regular file (symbolic
 * links followed) or a path that does not exist (its reader's open names that). */
std::string specialFileKind(const std::string& path);

/** Throws std::runtime_error "<what> '<path>' is a character device, not a regular file" (or a
 * folder, FIFO, ...) unless `path` is a regular file or does not exist; `why` is appended
 * after "; " when given (why this input must be a file). */
void requireRegularFile(const std::string& path, const std::string& what,
                        const std::string& why = "");

/** The whole file at `path`, read once, without a leading byte-order mark. A regular file is read
 * whole; a pipe or FIFO (`-c <(...)`, `/dev/stdin` on a pipe) up to kMaxPipedText bytes; anything
 * else is refused. Throws std::runtime_error naming `what` and the path: "cannot open trajectory
 * file 'x'", "trajectory file '/tmp' is a folder, not a file", "config file '/dev/zero' is a
 * character device, not a regular file", "... is a pipe holding more than 64 MiB". */
std::string readTextFile(const std::string& path, const std::string& what);

}  // namespace hrgbd
