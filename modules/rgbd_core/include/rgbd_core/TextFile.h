#pragma once
/** \file TextFile.h
 * Reading the project's text inputs (TUM lists, trajectories, INI files) as a user's editor may
 * have saved them. */
#include <string>
#include <string_view>

namespace hrgbd {

/** `text` without a leading UTF-8 byte-order mark (EF BB BF), which Windows editors put at the
 * start of a file and which would otherwise be read as part of the first word. */
std::string_view withoutBom(std::string_view text);

/** The whole file at `path`, without a leading byte-order mark. Throws std::runtime_error naming
 * `what` and the path when it cannot be opened or is a folder ("cannot open trajectory file 'x'",
 * "trajectory file '/tmp' is a folder, not a file"). */
std::string readTextFile(const std::string& path, const std::string& what);

}  // namespace hrgbd
