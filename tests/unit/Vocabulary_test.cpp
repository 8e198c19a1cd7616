// The bag of binary words: k-majority training recovers planted clusters, the file round-trips
// and refuses damage with the line named, the L1 score ranks the same scene above another.
#include "rgbd_slam/Vocabulary.h"

#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <stdexcept>
#include <string>

#include "TestData.h"

namespace {

using hrgbd::BowVector;
using hrgbd::Vocabulary;

// `clusters` random 256-bit centres, `per` members each with `flips` random bits flipped.
cv::Mat planted(int clusters, int per, int flips, std::vector<int>& cluster_of, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> byte(0, 255), bit(0, 255);
  cv::Mat centres(clusters, 32, CV_8U), out(clusters * per, 32, CV_8U);
  for (int c = 0; c < clusters; ++c)
    for (int b = 0; b < 32; ++b) centres.at<uchar>(c, b) = static_cast<uchar>(byte(rng));
  cluster_of.clear();
  for (int c = 0; c < clusters; ++c)
    for (int m = 0; m < per; ++m) {
      const int row = c * per + m;
      centres.row(c).copyTo(out.row(row));
      for (int f = 0; f < flips; ++f) {
        const int b = bit(rng);
        out.at<uchar>(row, b / 8) ^= static_cast<uchar>(1u << (b % 8));
      }
      cluster_of.push_back(c);
    }
  return out;
}

Vocabulary trainedOnPlanted(std::vector<int>& cluster_of, cv::Mat& d) {
  d = planted(8, 60, 20, cluster_of, 7);
  std::vector<int> image(static_cast<std::size_t>(d.rows));  // 4 images of 2 clusters each
  for (std::size_t i = 0; i < image.size(); ++i) image[i] = cluster_of[i] / 2;
  hrgbd::VocabularyTraining t;
  t.words = 8;
  return Vocabulary::train(d, image, t);
}

}  // namespace

TEST(Vocabulary, KMajorityRecoversPlantedClusters) {
  std::vector<int> cluster_of;
  cv::Mat d;
  const auto v = trainedOnPlanted(cluster_of, d);
  ASSERT_EQ(v.size(), 8u);
  // one word per cluster: members of a cluster share their word, clusters do not
  std::vector<int> word_of_cluster(8, -1);
  for (int i = 0; i < d.rows; ++i) EXPECT_EQ(v.transform(d.row(i)).size(), 1u);
  cv::Mat dist, idx;
  cv::batchDistance(d, v.words(), dist, CV_32S, idx, cv::NORM_HAMMING, 1);
  for (int i = 0; i < d.rows; ++i) {
    int& w = word_of_cluster[static_cast<std::size_t>(cluster_of[i])];
    if (w < 0) w = idx.at<int>(i);
    EXPECT_EQ(idx.at<int>(i), w) << "descriptor " << i;
  }
  std::sort(word_of_cluster.begin(), word_of_cluster.end());
  EXPECT_EQ(std::unique(word_of_cluster.begin(), word_of_cluster.end()), word_of_cluster.end());
}

TEST(Vocabulary, TrainingReportsItsStagesAndStopsWhenTheReportThrows) {
  std::vector<int> cluster_of;
  const cv::Mat d = planted(8, 60, 20, cluster_of, 7);
  std::vector<int> image(cluster_of.size());
  for (std::size_t i = 0; i < image.size(); ++i) image[i] = cluster_of[i] / 2;
  hrgbd::VocabularyTraining t;
  t.words = 8;
  std::vector<std::string> seen;
  t.progress = [&](const std::string& stage, const std::string& unit, std::size_t done,
                   std::size_t total) {
    seen.push_back(stage + " " + unit + " " + std::to_string(done) + "/" + std::to_string(total));
  };
  Vocabulary::train(d, image, t);
  ASSERT_GE(seen.size(), 10u);
  EXPECT_EQ(seen[0], "seeding words 0/8");
  EXPECT_EQ(seen[8], "seeding words 8/8");
  EXPECT_EQ(seen[9], "k-majority rounds 0/15");
  // planted clusters settle before round 15: the round that finds it so is not counted as made
  EXPECT_EQ(seen.back(), seen[seen.size() - 2]);
  EXPECT_NE(seen.back(), "k-majority rounds 15/15");
  t.progress = [](const std::string& stage, const std::string&, std::size_t, std::size_t) {
    if (stage == "k-majority") throw std::runtime_error("stopped");
  };
  EXPECT_THROW(Vocabulary::train(d, image, t), std::runtime_error);
}

TEST(Vocabulary, DataThatCannotMakeAUsefulVocabularyIsRefused) {
  std::vector<int> cluster_of;
  const cv::Mat d = planted(8, 60, 20, cluster_of, 5);
  hrgbd::VocabularyTraining t;
  t.words = 8;
  auto message = [&](const cv::Mat& rows, const std::vector<int>& image) {
    try {
      Vocabulary::train(rows, image, t);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("trained");
  };
  // one image: no word can weigh more than another
  EXPECT_NE(message(d, std::vector<int>(480, 0)).find("one image"), std::string::npos);
  // every word in every image (each image holds all eight clusters)
  std::vector<int> mixed(480);
  for (std::size_t i = 0; i < mixed.size(); ++i) mixed[i] = static_cast<int>(i % 10);
  EXPECT_NE(message(d, mixed).find("every word is in every image"), std::string::npos);
  // fewer distinct descriptors than words: 480 copies of 4 rows
  cv::Mat copies;
  for (int i = 0; i < 120; ++i) copies.push_back(d.rowRange(0, 4));
  std::vector<int> two(480);
  for (std::size_t i = 0; i < two.size(); ++i) two[i] = static_cast<int>(i % 2);
  EXPECT_NE(message(copies, two).find("4 distinct descriptors for 8 words"), std::string::npos);
}

TEST(Vocabulary, ScoreRanksTheSameImageAboveAnother) {
  // images made of clusters: image A of clusters 0-3, B of 4-7; words weigh by idf
  std::vector<int> cluster_of;
  const cv::Mat d = planted(8, 60, 20, cluster_of, 3);
  std::vector<int> image(static_cast<std::size_t>(d.rows));
  for (int i = 0; i < d.rows; ++i) image[static_cast<std::size_t>(i)] = cluster_of[i] / 2;
  hrgbd::VocabularyTraining t;
  t.words = 8;
  const auto v = Vocabulary::train(d, image, t);
  const BowVector a1 = v.transform(d.rowRange(0, 120)), a2 = v.transform(d.rowRange(120, 240)),
                  a = v.transform(d.rowRange(0, 240)), b = v.transform(d.rowRange(240, 480));
  EXPECT_NEAR(hrgbd::bowScore(a, a), 1.0, 1e-6);
  EXPECT_NEAR(hrgbd::bowScore(a, b), 0.0, 1e-6);  // no word in common
  EXPECT_NEAR(hrgbd::bowScore(a1, a), hrgbd::bowScore(a, a1), 1e-9);
  EXPECT_NEAR(hrgbd::bowScore(a1, a), 0.5, 0.05);  // half of A's words, equally weighted
  EXPECT_NEAR(hrgbd::bowScore(a1, a2), 0.0, 1e-6);
  EXPECT_EQ(hrgbd::bowScore(a, BowVector{}), 0.0);
}

TEST(Vocabulary, FileRoundTripsAndRefusesDamage) {
  std::vector<int> cluster_of;
  cv::Mat d;
  const auto v = trainedOnPlanted(cluster_of, d);
  const auto dir = hrgbd::test::tempDir("vocabulary");
  const auto path = dir + "/v.txt";
  v.save(path);
  const auto back = Vocabulary::load(path);
  EXPECT_EQ(cv::norm(back.words(), v.words(), cv::NORM_INF), 0.0);
  EXPECT_EQ(back.idf(), v.idf());

  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  auto message = [&](const std::vector<std::string>& text) {
    const auto bad = dir + "/bad.txt";
    std::ofstream out(bad);
    for (const auto& l : text) out << l << "\n";
    out.close();
    try {
      Vocabulary::load(bad);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("loaded");
  };
  auto with = [&](std::size_t i, const std::string& line) {
    auto t = lines;
    t[i] = line;
    return t;
  };
  EXPECT_NE(message(with(0, "HRGBD_ORB_VOCABULARY 2 8")).find("line 1"), std::string::npos);
  EXPECT_NE(message(with(3, "zz" + lines[3].substr(2))).find("line 4"), std::string::npos);
  EXPECT_NE(message(with(5, lines[5].substr(1))).find("line 6"), std::string::npos);
  EXPECT_NE(message(with(5, lines[5].substr(0, 64) + " nan")).find("line 6"), std::string::npos);
  EXPECT_NE(message(with(5, lines[5].substr(0, 64) + " 1e300")).find("line 6"), std::string::npos);
  EXPECT_NE(message(with(5, lines[5] + " junk")).find("line 6"), std::string::npos);
  EXPECT_NE(message(with(5, lines[5] + "abc")).find("line 6"), std::string::npos);
  EXPECT_NE(message(with(0, lines[0] + " junk")).find("line 1"), std::string::npos);
  auto zero = lines;  // every idf 0: cannot tell images apart
  for (std::size_t i = 1; i < zero.size(); ++i) zero[i] = zero[i].substr(0, 64) + " 0";
  EXPECT_NE(message(zero).find("every idf is 0"), std::string::npos);
  EXPECT_NE(message({lines.begin(), lines.end() - 1}).find("7 of 8 words"), std::string::npos);
  auto longer = lines;
  longer.push_back(lines[1]);
  EXPECT_NE(message(longer).find("more words"), std::string::npos);
  EXPECT_NE(message({}).find("not a vocabulary"), std::string::npos);
  try {
    Vocabulary::load(dir);
    ADD_FAILURE() << "a folder loaded";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("is a folder"), std::string::npos) << e.what();
  }
  try {
    Vocabulary::load(dir + "/missing.txt");
    ADD_FAILURE() << "a missing file loaded";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("missing.txt"), std::string::npos);
  }
}

TEST(Vocabulary, BundledOneLoads) {
  const auto v = Vocabulary::load(hrgbd::bundledVocabulary());
  EXPECT_EQ(v.size(), 1000u);
  // SHOT descriptors or other bytes are refused, not misread
  EXPECT_THROW(v.transform(cv::Mat(3, 352, CV_32F, cv::Scalar(0))), std::invalid_argument);
}
