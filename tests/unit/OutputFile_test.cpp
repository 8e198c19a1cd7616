// Output files written in full or not at all, every write checked (OutputFile.h, GzOutput.h).
#include "rgbd_core/OutputFile.h"

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "TestData.h"
#include "rgbd_core/GzOutput.h"

namespace fs = std::filesystem;

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t entries(const std::string& dir) {
  const fs::directory_iterator it(dir);
  return static_cast<std::size_t>(std::distance(begin(it), end(it)));
}

}  // namespace

TEST(OutputFile, AppearsUnderItsNameOnlyWhenCommitted) {
  const auto dir = hrgbd::test::tempDir("output_file");
  const auto path = dir + "/out.txt";
  std::ofstream(path) << "previous\n";
  ::chmod(path.c_str(), 0640);
  {
    hrgbd::StreamOutput out(path, "test output");
    out.stream() << "new\n";
    out.flush();
    EXPECT_EQ(slurp(path), "previous\n");  // the data is in the temporary file beside it
    EXPECT_EQ(entries(dir), 2u);
  }  // destroyed without commit(): the previous file stays, the temporary one goes
  EXPECT_EQ(slurp(path), "previous\n");
  EXPECT_EQ(entries(dir), 1u);
  hrgbd::StreamOutput out(path, "test output");
  out.stream() << "new\n";
  out.commit();
  EXPECT_EQ(slurp(path), "new\n");
  EXPECT_EQ(entries(dir), 1u);
  EXPECT_EQ(fs::status(path).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
}

TEST(OutputFile, ASymbolicLinkKeepsPointingAtTheNewFile) {
  const auto dir = hrgbd::test::tempDir("output_file_link");
  fs::create_directories(dir + "/real");
  std::ofstream(dir + "/real/target.txt") << "old\n";
  fs::create_symlink(dir + "/real/target.txt", dir + "/link.txt");
  hrgbd::StreamOutput out(dir + "/link.txt", "test output");
  out.stream() << "new\n";
  out.commit();
  EXPECT_TRUE(fs::is_symlink(dir + "/link.txt"));
  EXPECT_EQ(slurp(dir + "/real/target.txt"), "new\n");
}

TEST(OutputFile, DevicesAreWrittenInPlaceAndChecked) {
  // /dev/full takes no data: the error names it, on the first flush at the latest.
  const auto full = hrgbd::test::errorOf([] {
    hrgbd::StreamOutput out("/dev/full", "trajectory");
    out.stream() << "1 0 0 0 0 0 0 1\n";
    out.commit();
  });
  EXPECT_NE(full.find("cannot write trajectory '/dev/full'"), std::string::npos) << full;
  EXPECT_NE(full.find("No space left"), std::string::npos) << full;
  EXPECT_NE(hrgbd::test::errorOf([] {
              const char bytes[1 << 16] = {};  // larger than the stream's buffer
              hrgbd::writeOutputFile("/dev/full", "plot", bytes, sizeof bytes);
            }).find("/dev/full"),
            std::string::npos);
  // /dev/null takes it, and stays a device (not replaced by a renamed regular file).
  hrgbd::StreamOutput null("/dev/null", "trajectory");
  null.stream() << "1 0 0 0 0 0 0 1\n";
  EXPECT_NO_THROW(null.commit());
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST(OutputFile, UnwritablePlacesAreErrorsNamingThem) {
  const auto dir = hrgbd::test::tempDir("output_file_bad");
  const auto missing =
      hrgbd::test::errorOf([&] { hrgbd::OutputFile f(dir + "/no/such/t.txt", "CSV"); });
  EXPECT_NE(missing.find("cannot write CSV '" + dir + "/no/such/t.txt'"), std::string::npos)
      << missing;
  EXPECT_NE(missing.find("does not exist"), std::string::npos) << missing;
  const auto folder = hrgbd::test::errorOf([&] { hrgbd::OutputFile f(dir, "CSV"); });
  EXPECT_NE(folder.find("it is a folder"), std::string::npos) << folder;
  EXPECT_NE(hrgbd::test::errorOf([] { hrgbd::OutputFile f("", "CSV"); }), "");
}

TEST(GzOutput, CompressedArchivesAreCheckedAndAppearOnlyWhenClosed) {
  const auto dir = hrgbd::test::tempDir("gz_output");
  const mrpt::poses::CPose3D pose(1, 2, 3, 0.1, 0.2, 0.3);
  {
    hrgbd::GzOutputStream out(dir + "/p.gz", "test archive");
    auto a = mrpt::serialization::archiveFrom(out);
    a << pose;
  }  // not closed
  EXPECT_FALSE(fs::exists(dir + "/p.gz"));
  EXPECT_EQ(entries(dir), 0u);
  hrgbd::saveCompressed(pose, dir + "/p.gz", "test archive");
  mrpt::io::CFileGZInputStream in(dir + "/p.gz");
  mrpt::poses::CPose3D back;
  mrpt::serialization::archiveFrom(in) >> back;
  EXPECT_NEAR((back.asVectorVal() - pose.asVectorVal()).norm(), 0, 1e-12);
  // gzip buffers: the failure shows at the latest when the stream is closed.
  const auto full =
      hrgbd::test::errorOf([&] { hrgbd::saveCompressed(pose, "/dev/full", "simplemap"); });
  EXPECT_NE(full.find("cannot write simplemap '/dev/full'"), std::string::npos) << full;
  EXPECT_EQ(full.find("MRPT exception"), std::string::npos) << full;
}

TEST(OutputFile, ANameNearTheFileSystemsLimitGetsATemporaryNameThatFits) {
  // ".<name>.<pid>-<n>.tmp" of a 254-byte name is over 255 bytes: the output was refused.
  const auto dir = hrgbd::test::tempDir("output_long_name");
  const auto path = dir + "/" + std::string(250, 'a') + ".txt";
  hrgbd::StreamOutput out(path, "test output");
  out.stream() << "data\n";
  out.commit();
  EXPECT_EQ(slurp(path), "data\n");
  EXPECT_EQ(entries(dir), 1u);
}
