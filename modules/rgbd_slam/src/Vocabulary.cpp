#include "rgbd_slam/Vocabulary.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>

#include "rgbd_core/TextFile.h"

namespace hrgbd {
namespace {

constexpr int kBytes = 32;  // ORB: 256 bits
const char* const kHeader = "HRGBD_ORB_VOCABULARY";
constexpr double kMaxIdf = 50;  // log(images / 1): 50 would need e^50 training images

void checkDescriptors(const cv::Mat& d, const char* what) {
  if (!d.empty() && (d.type() != CV_8U || d.cols != kBytes))
    throw std::invalid_argument(std::string(what) +
                                ": ORB descriptors (CV_8U, 32 bytes a row) needed");
}

/** Index of the nearest word of every row of `d` (OpenCV's Hamming search). */
cv::Mat nearestWords(const cv::Mat& d, const cv::Mat& words) {
  cv::Mat dist, idx;
  cv::batchDistance(d, words, dist, CV_32S, idx, cv::NORM_HAMMING, 1);
  return idx;
}

}  // namespace

std::string bundledVocabulary() {
  namespace fs = std::filesystem;
  std::vector<fs::path> places;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) places.push_back(exe.parent_path() / ".." / "share" / "hrgbd" / "orb_vocabulary.txt");
  places.emplace_back(HRGBD_INSTALLED_VOCABULARY);
  places.emplace_back(HRGBD_SOURCE_VOCABULARY);
  std::string looked;
  for (const auto& p : places) {
    if (fs::is_regular_file(p, ec)) return p.lexically_normal().string();
    looked += (looked.empty() ? "" : ", ") + p.lexically_normal().string();
  }
  throw std::runtime_error("the bundled vocabulary is not installed (looked in " + looked + ")");
}

double bowScore(const BowVector& a, const BowVector& b) {
  // both sum to 1 with non-negative weights: 1 - |a - b|_1 / 2 = sum over shared words of min
  double s = 0;
  auto i = a.begin(), j = b.begin();
  while (i != a.end() && j != b.end()) {
    if (i->first < j->first)
      ++i;
    else if (j->first < i->first)
      ++j;
    else
      s += std::min(i->second, j->second), ++i, ++j;
  }
  return s;
}

Vocabulary Vocabulary::train(const cv::Mat& d, const std::vector<int>& image,
                             const VocabularyTraining& p) {
  checkDescriptors(d, "Vocabulary::train");
  if (p.words < 2 || d.rows < p.words)
    throw std::invalid_argument("Vocabulary::train: " + std::to_string(d.rows) +
                                " descriptors for " + std::to_string(p.words) + " words");
  if (image.size() != static_cast<std::size_t>(d.rows))
    throw std::invalid_argument("Vocabulary::train: one image index per descriptor needed");
  if (std::set<int>(image.begin(), image.end()).size() < 2)
    throw std::invalid_argument(
        "Vocabulary::train: descriptors of one image only (the words' weights need several)");
  std::set<std::string> distinct;
  for (int i = 0; i < d.rows; ++i) distinct.emplace(d.ptr<char>(i), kBytes);
  if (distinct.size() < static_cast<std::size_t>(p.words))
    throw std::invalid_argument("Vocabulary::train: " + std::to_string(distinct.size()) +
                                " distinct descriptors for " + std::to_string(p.words) + " words");
  std::mt19937 rng(p.seed);
  std::uniform_int_distribution<int> any(0, d.rows - 1);
  // start: k-means++ seeding (each next centre drawn with probability growing with the squared
  // Hamming distance to the nearest centre so far), so that clusters are not seeded twice
  Vocabulary v;
  v.m_words.create(p.words, kBytes, CV_8U);
  std::vector<double> nearest(static_cast<std::size_t>(d.rows), 1e300);
  const auto report = [&](const char* stage, const char* unit, int done, int total) {
    if (p.progress)
      p.progress(stage, unit, static_cast<std::size_t>(done), static_cast<std::size_t>(total));
  };
  int pick = any(rng);
  for (int k = 0; k < p.words; ++k) {
    report("seeding", "words", k, p.words);
    d.row(pick).copyTo(v.m_words.row(k));
    cv::Mat dist;
    cv::batchDistance(d, v.m_words.row(k), dist, CV_32S, cv::noArray(), cv::NORM_HAMMING);
    for (int i = 0; i < d.rows; ++i) {
      const double h = dist.at<int>(i);
      nearest[static_cast<std::size_t>(i)] = std::min(nearest[static_cast<std::size_t>(i)], h * h);
    }
    if (*std::max_element(nearest.begin(), nearest.end()) <= 0) {  // all alike: any will do
      pick = any(rng);
      continue;
    }
    std::discrete_distribution<int> next(nearest.begin(), nearest.end());
    pick = next(rng);
  }
  cv::Mat assigned;
  report("seeding", "words", p.words, p.words);
  int it = 0;
  for (; it < p.iterations; ++it) {
    report("k-majority", "rounds", it, p.iterations);
    const cv::Mat idx = nearestWords(d, v.m_words);
    if (!assigned.empty() && cv::countNonZero(idx != assigned) == 0) break;
    assigned = idx;
    // each centre becomes the bitwise majority of its members (ties: 0)
    std::vector<int> ones(static_cast<std::size_t>(p.words) * kBytes * 8, 0), members(p.words, 0);
    for (int i = 0; i < d.rows; ++i) {
      const int c = idx.at<int>(i);
      ++members[c];
      const std::uint8_t* row = d.ptr<std::uint8_t>(i);
      int* count = &ones[static_cast<std::size_t>(c) * kBytes * 8];
      for (int b = 0; b < kBytes * 8; ++b) count[b] += (row[b / 8] >> (b % 8)) & 1;
    }
    for (int k = 0; k < p.words; ++k) {
      std::uint8_t* w = v.m_words.ptr<std::uint8_t>(k);
      if (members[k] == 0) {  // an empty cluster restarts on a random descriptor
        d.row(any(rng)).copyTo(v.m_words.row(k));
        continue;
      }
      const int* count = &ones[static_cast<std::size_t>(k) * kBytes * 8];
      for (int byte = 0; byte < kBytes; ++byte) {
        std::uint8_t x = 0;
        for (int bit = 0; bit < 8; ++bit)
          if (2 * count[byte * 8 + bit] > members[k]) x |= static_cast<std::uint8_t>(1u << bit);
        w[byte] = x;
      }
    }
  }
  report("k-majority", "rounds", it, p.iterations);  // the rounds made: fewer if settled
  // inverse document frequency over the training images
  const cv::Mat idx = nearestWords(d, v.m_words);
  std::map<int, std::set<int>> images_of_word;
  std::set<int> images(image.begin(), image.end());
  for (int i = 0; i < d.rows; ++i) images_of_word[idx.at<int>(i)].insert(image[i]);
  v.m_idf.assign(p.words, 0.f);
  for (const auto& [k, in] : images_of_word)  // a word no descriptor took keeps idf 0
    v.m_idf[static_cast<std::size_t>(k)] =
        static_cast<float>(std::log(static_cast<double>(images.size()) / in.size()));
  if (*std::max_element(v.m_idf.begin(), v.m_idf.end()) <= 0)
    throw std::invalid_argument(
        "Vocabulary::train: every word is in every image: give images of different places");
  return v;
}

BowVector Vocabulary::transform(const cv::Mat& descriptors) const {
  checkDescriptors(descriptors, "Vocabulary::transform");
  if (descriptors.empty() || m_words.empty()) return {};
  const cv::Mat idx = nearestWords(descriptors, m_words);
  std::map<std::uint32_t, float> w;
  for (int i = 0; i < idx.rows; ++i) w[static_cast<std::uint32_t>(idx.at<int>(i))] += 1.f;
  BowVector out;
  double sum = 0;
  for (const auto& [word, count] : w) {
    const float weight = count * m_idf[word];  // tf-idf; the 1/n of tf goes with the normalising
    if (weight > 0) out.emplace_back(word, weight), sum += weight;
  }
  for (auto& [word, weight] : out) weight = static_cast<float>(weight / sum);
  return out;
}

void Vocabulary::save(const std::string& path) const {
  std::ostringstream s;
  s << kHeader << " 1 " << size() << "\n";
  for (int k = 0; k < m_words.rows; ++k) {
    const std::uint8_t* w = m_words.ptr<std::uint8_t>(k);
    for (int b = 0; b < kBytes; ++b)
      s << std::hex << std::setw(2) << std::setfill('0') << int(w[b]);
    s << std::dec << " " << std::setprecision(9) << m_idf[k] << "\n";
  }
  std::ofstream out(path, std::ios::binary);
  out << s.str();
  out.close();  // checked too: the last buffer is written there
  if (!out) throw std::runtime_error("cannot write the vocabulary " + path);
}

Vocabulary Vocabulary::load(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw std::runtime_error(path + " is a folder, not a vocabulary file");
  // read once, capped (a device such as /dev/zero is refused, a pipe read up to 64 MiB)
  std::istringstream in(readTextFile(path, "vocabulary"));
  auto fail = [&](std::size_t line, const std::string& why) -> std::runtime_error {
    return std::runtime_error("vocabulary " + path + ", line " + std::to_string(line) + ": " + why);
  };
  std::string line;
  std::getline(in, line);
  std::istringstream head(line);
  std::string magic;
  int version = 0;
  long words = 0;
  if (!(head >> magic >> version >> words) || !(head >> std::ws).eof() || magic != kHeader ||
      version != 1)
    throw fail(1, std::string("not a vocabulary (\"") + kHeader + " 1 <words>\" expected)");
  if (words < 2 || words > 1000000) throw fail(1, "word count out of range [2, 1000000]");
  Vocabulary v;
  v.m_words.create(static_cast<int>(words), kBytes, CV_8U);
  v.m_idf.resize(static_cast<std::size_t>(words));
  for (long k = 0; k < words; ++k) {
    const std::size_t n = static_cast<std::size_t>(k) + 2;
    if (!std::getline(in, line))
      throw fail(n, "ends after " + std::to_string(k) + " of " + std::to_string(words) + " words");
    std::istringstream ls(line);
    std::string hex;
    double idf = -1;
    if (!(ls >> hex >> idf) || !(ls >> std::ws).eof() || hex.size() != 2 * kBytes ||
        !(idf >= 0 && idf <= kMaxIdf))
      throw fail(n, "\"<64 hex digits> <idf in [0, 50]>\" expected");
    std::uint8_t* w = v.m_words.ptr<std::uint8_t>(static_cast<int>(k));
    for (int b = 0; b < kBytes; ++b) {
      const std::string byte = hex.substr(2 * b, 2);
      if (byte.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos)
        throw fail(n, "not a hex digit in \"" + byte + "\"");
      w[b] = static_cast<std::uint8_t>(std::stoi(byte, nullptr, 16));
    }
    v.m_idf[static_cast<std::size_t>(k)] = static_cast<float>(idf);
  }
  for (std::size_t n = static_cast<std::size_t>(words) + 2; std::getline(in, line); ++n)
    if (line.find_first_not_of(" \t\r") != std::string::npos)
      throw fail(n, "more words than the header's " + std::to_string(words));
  if (*std::max_element(v.m_idf.begin(), v.m_idf.end()) <= 0)
    throw std::runtime_error("vocabulary " + path +
                             ": every idf is 0, so it cannot tell images apart");
  return v;
}

}  // namespace hrgbd
