#pragma once
/** \file Vocabulary.h
 * A bag of binary words over ORB descriptors, to find loop candidates by appearance, as DBoW2
 * does. DBoW2 is not packaged in Debian and OpenCV's k-means clusters real vectors only, so the
 * few parts needed are written here: a flat vocabulary of binary words made by k-majority
 * clustering (k-means under the Hamming distance, each centre the bitwise majority of its
 * members), tf-idf weighted word histograms, and DBoW2's L1 score. Word look-up is OpenCV's
 * brute-force Hamming search (cv::batchDistance). */
#include <cstdint>
#include <functional>
#include <opencv2/core.hpp>
#include <string>
#include <utility>
#include <vector>

namespace hrgbd {

/** An image's words: (word, tf-idf weight) sorted by word, the weights summing to 1. */
using BowVector = std::vector<std::pair<std::uint32_t, float>>;

/** The vocabulary shipped with the product ([Slam] vocabulary = bundled): share/hrgbd/ beside
 * the running program's bin/, else in the configured install prefix, else config/ of the source
 * tree it was built from. Throws
 * std::runtime_error listing where it looked. */
std::string bundledVocabulary();

/** [0, 1] similarity: 1 - |a - b|_1 / 2 (DBoW2's L1 score); 0 if either is empty. */
double bowScore(const BowVector& a, const BowVector& b);

struct VocabularyTraining {
  int words = 1000;     //!< [count] clusters
  int iterations = 15;  //!< [count] k-majority rounds (fewer if the assignment settles)
  unsigned seed = 1;
  /** Called as the training goes (may be empty): the stage ("seeding", "k-majority"), the unit
   * counted ("words", "rounds"), done and total. It may throw (an interrupt) to stop it. */
  std::function<void(const std::string& stage, const std::string& unit, std::size_t done,
                     std::size_t total)>
      progress;
};

class Vocabulary {
 public:
  /** Clusters `descriptors` (CV_8U, 32 bytes a row, at least `p.words` distinct rows); `image[i]`
   * is the image row i came from, for the words' inverse document frequency (at least two
   * images). Throws std::invalid_argument when the data cannot make a useful vocabulary. */
  static Vocabulary train(const cv::Mat& descriptors, const std::vector<int>& image,
                          const VocabularyTraining& p);
  /** Reads a file save() wrote; throws std::runtime_error naming the file (and line) on any
   * fault, or when every idf is 0. */
  static Vocabulary load(const std::string& path);
  /** Text: a header line, then per word its 64 hex digits and its idf. Throws on failure. */
  void save(const std::string& path) const;

  /** The words of an image's ORB descriptors (CV_8U, 32 bytes a row). */
  BowVector transform(const cv::Mat& descriptors) const;
  std::size_t size() const { return m_idf.size(); }
  const cv::Mat& words() const { return m_words; }
  const std::vector<float>& idf() const { return m_idf; }

 private:
  cv::Mat m_words;           //!< CV_8U, one 32-byte word a row
  std::vector<float> m_idf;  //!< log(images / images holding the word)
};

}  // namespace hrgbd
