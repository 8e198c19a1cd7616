// Inputs that are not regular files (TextFile.h): a device is refused, a pipe is read once and
// capped, a folder is named as one.
#include "rgbd_core/TextFile.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>

#include "TestData.h"

namespace {

/** The message of `f()`'s std::runtime_error, "" if it throws none. */
template <class F>
std::string message(F f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(TextFile, DevicesAndFoldersAreRefusedNamingTheFile) {
  if (!std::filesystem::exists("/dev/zero")) GTEST_SKIP() << "no /dev/zero on this system";
  // /dev/zero was read until memory ran out (std::bad_alloc, no file named).
  auto msg = message([] { hrgbd::readTextFile("/dev/zero", "trajectory file"); });
  EXPECT_EQ(msg, "trajectory file '/dev/zero' is a character device, not a regular file");
  const auto dir = hrgbd::test::tempDir("text_file_kinds");
  msg = message([&] { hrgbd::requireRegularFile(dir, "colour image"); });
  EXPECT_EQ(msg, "colour image '" + dir + "' is a folder, not a file");
  msg = message([] { hrgbd::requireRegularFile("/dev/zero", "rawlog", "give a file"); });
  EXPECT_EQ(msg, "rawlog '/dev/zero' is a character device, not a regular file; give a file");
  std::ofstream(dir + "/a.txt") << "x\n";
  EXPECT_NO_THROW(hrgbd::requireRegularFile(dir + "/a.txt", "list"));
  EXPECT_NO_THROW(hrgbd::requireRegularFile(dir + "/missing.txt", "list"));  // its open says so
}

TEST(TextFile, APipeIsReadOnceUpToTheCap) {
  const auto dir = hrgbd::test::tempDir("text_file_pipe");
  const auto fifo = dir + "/p.txt";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::thread small([&] {
    std::ofstream(fifo) << "\xEF\xBB\xBF"
                           "1 2 3\n";
  });
  EXPECT_EQ(hrgbd::readTextFile(fifo, "list"), "1 2 3\n");
  small.join();
  // Past the cap the read stops with an error; the writer then finds the pipe closed.
  ::signal(SIGPIPE, SIG_IGN);
  std::thread big([&] {
    std::ofstream out(fifo, std::ios::binary);
    const std::string block(1 << 20, 'x');
    for (std::size_t k = 0; k <= (hrgbd::kMaxPipedText >> 20) && out; ++k) out << block;
  });
  const auto msg = message([&] { hrgbd::readTextFile(fifo, "list"); });
  big.join();
  EXPECT_NE(msg.find("list '" + fifo + "' is a pipe holding more than 64 MiB"), std::string::npos)
      << msg;
}
