#include "rgbd_io/TumLists.h"

#include <filesystem>
#include <fstream>
#include <utility>
#include <vector>

#include "TestData.h"
#include "rgbd_core/Timestamp.h"

TEST(TumLists, ParsesEntriesAndSkipsComments) {
  const auto v = hrgbd::parseTumListText(
      "# color images\n# timestamp filename\n\n1.0 rgb/1.png\n1.5 rgb/2.png\n", "rgb.txt");
  ASSERT_EQ(v.size(), 2u);
  EXPECT_DOUBLE_EQ(v[1].t, 1.5);
  EXPECT_EQ(v[1].file, "rgb/2.png");
  EXPECT_EQ(v[1].line, 5);
}

TEST(TumLists, OutOfOrderAndDuplicateStampsAreErrors) {
  for (const char* text : {"1.0 a.png\n0.9 b.png\n", "1.0 a.png\n1.0 b.png\n"}) {
    try {
      hrgbd::parseTumListText(text, "rgb.txt");
      FAIL() << "expected an exception for: " << text;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("rgb.txt' line 2"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(hrgbd::parseTumListText("1.0\n", "rgb.txt"), std::runtime_error);
  EXPECT_THROW(hrgbd::parseTumListText("nan a.png\n", "rgb.txt"), std::runtime_error);
}

TEST(TumLists, StampsAreKeptExactlyOrRefusedNamingTheLine) {
  const auto v =
      hrgbd::parseTumListText("1700000000.1234567 a.png\n1700000000.1234568 b.png\n", "rgb.txt");
  ASSERT_EQ(v.size(), 2u);  // 100 ns apart: one double step is 238 ns there
  EXPECT_EQ(hrgbd::formatFrameTime(v[0].stamp), "1700000000.123456700");
  EXPECT_EQ(hrgbd::formatFrameTime(v[1].stamp), "1700000000.123456800");
  for (const auto& [stamp, why] :
       std::vector<std::pair<std::string, std::string>>{{"-1", "negative"},
                                                        {"1e308", "not below 1e11 s"},
                                                        {"1700000000123456789", "not below 1e11 s"},
                                                        {"1.00000002", "finer than 100 ns"}}) {
    try {
      hrgbd::parseTumListText("# list\n1 a.png\n" + stamp + " b.png\n", "rgb.txt");
      FAIL() << "expected an exception for " << stamp;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("'rgb.txt' line 3: time stamp " + stamp + " "),
                std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  }
  // Two stamps closer than 100 ns would be one time: refused, not merged.
  EXPECT_THROW(hrgbd::parseTumListText("1.00000001 a.png\n1.00000002 b.png\n", "rgb.txt"),
               std::runtime_error);
}

TEST(TumLists, AssociationPairsNearestWithinLimit) {
  const auto rgb = hrgbd::parseTumListText("1.000 r1\n1.033 r2\n1.066 r3\n2.000 r4\n", "rgb");
  const auto depth = hrgbd::parseTumListText("1.004 d1\n1.030 d2\n1.070 d3\n1.5 d4\n", "depth");
  const auto p = hrgbd::associateTumLists(rgb, depth, 0.02);
  ASSERT_EQ(p.size(), 3u);  // r4 has no depth within 0.02 s
  EXPECT_EQ(p[0].depth.file, "d1");
  EXPECT_EQ(p[1].depth.file, "d2");
  EXPECT_EQ(p[2].depth.file, "d3");
}

TEST(TumLists, AByteOrderMarkAtTheStartIsSkipped) {
  // Windows editors save "EF BB BF" first; it was read as part of the first time stamp.
  const auto dir = hrgbd::test::tempDir("tum_bom");
  std::ofstream(dir + "/rgb.txt") << "\xEF\xBB\xBF"
                                     "1.0 rgb/1.png\n1.5 rgb/2.png\n";
  const auto v = hrgbd::parseTumList(dir + "/rgb.txt");
  ASSERT_EQ(v.size(), 2u);
  EXPECT_DOUBLE_EQ(v[0].t, 1.0);
  EXPECT_EQ(v[0].file, "rgb/1.png");
  EXPECT_EQ(hrgbd::parseTumListText("\xEF\xBB\xBF# comment\n2.0 a.png\n", "rgb.txt").size(), 1u);
}

TEST(TumLists, AFolderInPlaceOfAListIsNamed) {
  const auto dir = hrgbd::test::tempDir("tum_list_folder");
  std::filesystem::create_directories(dir + "/rgb.txt");
  try {
    hrgbd::parseTumList(dir + "/rgb.txt");
    FAIL() << "a folder read as an empty list";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("rgb.txt' is a folder"), std::string::npos) << e.what();
  }
}
