// Two places where MRPT 2.5's deserialisation ends or crashes the whole program on a corrupt
// rawlog (both found by fuzz_rawlog). Each is fixed by interposing a function MRPT calls through
// the dynamic linker (every program linking rgbd_io exports these symbols, see CMakeLists.txt):
//
// 1. libjpeg's default error handler prints a message and calls exit(). MRPT's CImage uses it to
//    decode JPEG-compressed images inside a rawlog, so one corrupt image ended the program with
//    "Not a JPEG file" and no file name. jpeg_std_error() here installs libjpeg's defaults, then
//    an error_exit that frees the decoder (as libjpeg's own does before exiting) and throws.
//    OpenCV sets its own error_exit after calling jpeg_std_error(), so it is unaffected.
// 2. mrpt::aligned_malloc() returns NULL when it cannot allocate, and MRPT's aligned allocator
//    hands that to std::vector, which writes through it: a corrupt image size in a rawlog was a
//    segmentation fault. The version here throws std::bad_alloc instead, and while a rawlog
//    entry is read (ReadingRawlogEntry) it refuses single containers over 1 GiB: a 640x480
//    range image needs 600 KiB, and a corrupt size asked for 19 GB, which the allocator may
//    grant and the vector then fills until the OOM killer ends the program.
#include "ReadGuards.h"

#include <dlfcn.h>

#include <cstdio>
#include <new>
#include <stdexcept>
#include <string>
// clang-format off
#include <jpeglib.h>  // after <cstdio>: it needs FILE
// clang-format on

namespace {

constexpr std::size_t kMaxEntryAllocation = std::size_t{1} << 30;
thread_local int t_reading_entry = 0;

template <typename Fn>
Fn nextDefinition(const char* symbol) {
  const auto fn = reinterpret_cast<Fn>(dlsym(RTLD_NEXT, symbol));
  if (!fn) throw std::runtime_error(std::string("symbol not found: ") + symbol);
  return fn;
}

void throwingErrorExit(j_common_ptr cinfo) {
  char text[JMSG_LENGTH_MAX] = {};
  (*cinfo->err->format_message)(cinfo, text);
  jpeg_destroy(cinfo);
  throw std::runtime_error(std::string("corrupt JPEG image: ") + text);
}

}  // namespace

extern "C" struct jpeg_error_mgr* jpeg_std_error(struct jpeg_error_mgr* err) {
  using Fn = struct jpeg_error_mgr* (*)(struct jpeg_error_mgr*);
  static const auto real = nextDefinition<Fn>("jpeg_std_error");
  real(err);
  err->error_exit = throwingErrorExit;
  return err;
}

namespace mrpt {
void* aligned_malloc(size_t size, size_t alignment) {
  using Fn = void* (*)(size_t, size_t);
  static const auto real = nextDefinition<Fn>("_ZN4mrpt14aligned_mallocEmm");
  if (t_reading_entry > 0 && size > kMaxEntryAllocation) throw std::bad_alloc();
  void* p = real(size, alignment);
  if (!p && size > 0) throw std::bad_alloc();
  return p;
}
}  // namespace mrpt

namespace hrgbd {
void installReadGuards() {}  // referencing this links the interposers into the program
ReadingRawlogEntry::ReadingRawlogEntry() { ++t_reading_entry; }
ReadingRawlogEntry::~ReadingRawlogEntry() { --t_reading_entry; }
}  // namespace hrgbd
