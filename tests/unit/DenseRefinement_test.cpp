// The dense refinement on rendered pairs with an exact relative pose: convergence from a few cm
// and degrees off, a correct estimate left in place, exact depth weighted by its own scale and
// Kinect-noisy depth by the model's, the better of two starts, starts that meet refined once, no
// evaluation spent on a converged estimate, only the reference's derivatives used, and no
// refinement without anything to refine with. The rolling shutter: DenseRollingShutter_test.cpp;
// the refinement after a registration (DenseRefined): DenseRefined_test.cpp.
#include "rgbd_odometry/DenseRefinement.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>

#include "DenseRenders.h"

using namespace hrgbd::test;  // NOLINT: the rendered pairs' helpers
using Eigen::Isometry3d;

TEST(DenseRefinement, ConvergesFromCentimetresAndDegreesOff) {
  const auto pair = renderPair("desk", kMotion);
  const Isometry3d start = perturbed(pair.truth, 0.02, 2.0);
  const auto [t0, r0] = error(start, pair.truth);
  ASSERT_GT(t0, 0.02);
  ASSERT_GT(r0, 2.0);
  const auto d = hrgbd::refineDense(pair.cur, pair.ref, {start}, hrgbd::DenseParams());
  ASSERT_TRUE(d.ok) << d.detail;
  const auto [t, r] = error(d.T, pair.truth);
  EXPECT_LT(t, 0.001);
  EXPECT_LT(r, 0.05);
}

TEST(DenseRefinement, EachTermAloneConvergesOnItsOwnCue) {
  for (const char* term : {"photometric", "geometric"}) {
    hrgbd::DenseParams p;
    (term == std::string("photometric") ? p.geometric_weight : p.photometric_weight) = 0;
    const auto pair = renderPair("desk", kMotion, p);
    const auto d = hrgbd::refineDense(pair.cur, pair.ref, {perturbed(pair.truth, 0.01, 1.0)}, p);
    ASSERT_TRUE(d.ok) << term << ": " << d.detail;
    EXPECT_LT(error(d.T, pair.truth).first, 0.002) << term;
    EXPECT_EQ(term == std::string("photometric") ? d.geometric_pairs : d.photometric_pairs, 0u)
        << term;
  }
}

TEST(DenseRefinement, LeavesACorrectEstimateInPlace) {
  const auto pair = renderPair("desk", kMotion);
  const auto d = hrgbd::refineDense(pair.cur, pair.ref, {pair.truth}, hrgbd::DenseParams());
  ASSERT_TRUE(d.ok) << d.detail;
  // exact renders: measured 0.014 mm and 0.0006 deg from the truth (the next test says why not 0)
  const auto [t, r] = error(d.T, pair.truth);
  EXPECT_LT(t, 0.0001);
  EXPECT_LT(r, 0.005);
}

// On exact renders the intensity term's fixed point lies off the truth (where bilinear samples
// straddle depth edges, an intensity comes from another surface than its depth): 0.47 mm with the
// depth model's weights. The point-to-plane residuals show the depth far cleaner than the model,
// and their own scale weights that term: the fixed point comes to the point-to-plane term's.
TEST(DenseRefinement, ExactDepthIsWeightedByItsOwnScale) {
  const auto pair = renderPair("desk", kMotion);
  hrgbd::DenseParams model;
  model.clean_depth_fraction = 0;
  const auto with_model = hrgbd::refineDense(pair.cur, pair.ref, {pair.truth}, model);
  const auto with_own = hrgbd::refineDense(pair.cur, pair.ref, {pair.truth}, hrgbd::DenseParams());
  ASSERT_TRUE(with_model.ok && with_own.ok);
  EXPECT_GT(error(with_model.T, pair.truth).first, 0.0003);
  EXPECT_LT(error(with_own.T, pair.truth).first, 0.0001);
}

// Depth as noisy as the model says (sigma = depth_noise z^2, as a Kinect's): the model's scale
// stays, and the result is that of the model alone. (Full resolution only: this noise is
// independent per pixel, and the coarser levels' 2x2 means would make it cleaner than the model
// there; a Kinect's is correlated over its 9x9 matching window.)
TEST(DenseRefinement, KinectNoisyDepthKeepsTheModelsScale) {
  const auto scene = hrgbd::sim::makeScene("desk", false);
  const auto ref_pose = referencePose();
  hrgbd::DenseParams p;
  p.levels = 1, p.finest_level = 0;
  std::mt19937 rng(7);
  auto noisy = [&](const mrpt::poses::CPose3D& pose) {
    auto f = render(scene, pose);
    std::normal_distribution<float> n(0, 1);
    // A serial loop: cv::Mat::forEach runs in parallel and would share the generator.
    for (auto it = f.depth.begin<float>(); it != f.depth.end<float>(); ++it)
      if (*it > 0) *it += static_cast<float>(p.depth_noise * *it * *it) * n(rng);
    return hrgbd::buildDensePyramid(f, p);
  };
  const auto ref = noisy(ref_pose), cur = noisy(ref_pose + kMotion);
  const Isometry3d truth = hrgbd::toIsometry(kMotion);
  hrgbd::DenseParams model = p;
  model.clean_depth_fraction = 0;
  const auto with_model = hrgbd::refineDense(cur, ref, {truth}, model);
  const auto with_rule = hrgbd::refineDense(cur, ref, {truth}, p);
  ASSERT_TRUE(with_model.ok && with_rule.ok);
  EXPECT_TRUE(with_rule.T.isApprox(with_model.T, 1e-12));
  EXPECT_LT(error(with_rule.T, truth).first, 0.002);
}

TEST(DenseRefinement, TheBetterStartWins) {
  const auto pair = renderPair("desk", kMotion);
  const Isometry3d wrong = perturbed(pair.truth, 0.15, 12.0);  // beyond the basin
  const Isometry3d near = perturbed(pair.truth, 0.01, 1.0);
  for (const auto& starts : {std::vector<Isometry3d>{wrong, near}, {near, wrong}}) {
    const auto d = hrgbd::refineDense(pair.cur, pair.ref, starts, hrgbd::DenseParams());
    ASSERT_TRUE(d.ok) << d.detail;
    EXPECT_TRUE(starts[d.start].isApprox(near));
    EXPECT_LT(error(d.T, pair.truth).first, 0.001);
    // the first start's own refinement is kept only where it lost (beyond the basin: far off)
    EXPECT_EQ(d.first_start_refined.has_value(), d.start != 0);
    if (d.first_start_refined) {
      EXPECT_GT(error(*d.first_start_refined, pair.truth).first, 0.05);
    }
  }
}

TEST(DenseRefinement, StartsThatMeetAreRefinedOnce) {
  const auto pair = renderPair("desk", kMotion);
  const Isometry3d first = perturbed(pair.truth, 0.01, 1.0);
  const Isometry3d second = perturbed(pair.truth, -0.005, -0.5);  // both in the basin
  const hrgbd::DenseParams p;
  const auto one = hrgbd::refineDense(pair.cur, pair.ref, {first}, p);
  const auto other = hrgbd::refineDense(pair.cur, pair.ref, {second}, p);
  const auto both = hrgbd::refineDense(pair.cur, pair.ref, {second, first}, p);
  ASSERT_TRUE(one.ok && other.ok && both.ok) << one.detail << other.detail << both.detail;
  // they meet after a coarse level: the later start, index 1, is dropped there and the earlier
  // one goes on alone, as it would on its own
  EXPECT_EQ(both.start, 0u);
  EXPECT_TRUE(both.T.isApprox(other.T));
  EXPECT_LT(both.iterations, one.iterations + other.iterations);
  EXPECT_GT(both.iterations, other.iterations);
  EXPECT_LT(error(both.T, pair.truth).first, 0.001);
}

// A tracked frame's pyramid is built without derivatives (they are added when it becomes a
// reference): a reference without them is refused, and the current frame's are never used.
TEST(DenseRefinement, OnlyTheReferenceNeedsItsDerivatives) {
  auto pair = renderPair("desk", kMotion);
  const Isometry3d start = perturbed(pair.truth, 0.01, 1.0);
  const hrgbd::DenseParams p;
  const auto eager = hrgbd::refineDense(pair.cur, pair.ref, {start}, p);
  ASSERT_TRUE(eager.ok) << eager.detail;
  for (auto& level : pair.ref.levels) hrgbd::dropDerivatives(level);
  const auto refused = hrgbd::refineDense(pair.cur, pair.ref, {start}, p);
  EXPECT_FALSE(refused.ok);
  EXPECT_NE(refused.detail.find("derivatives"), std::string::npos) << refused.detail;
  EXPECT_TRUE(refused.T.isApprox(start));
  for (auto& level : pair.ref.levels) hrgbd::addDerivatives(level, p);
  for (auto& level : pair.cur.levels) hrgbd::dropDerivatives(level);
  const auto lazy = hrgbd::refineDense(pair.cur, pair.ref, {start}, p);
  ASSERT_TRUE(lazy.ok) << lazy.detail;
  EXPECT_TRUE(lazy.T.isApprox(eager.T, 1e-12));
  EXPECT_EQ(lazy.iterations, eager.iterations);
}

// The refinement reads a reference's grey levels and gradients from one interleaved image: it
// holds the level's own grey and central differences, is made anew (never written into a copy's
// buffer: the SLAM module keeps copies of pyramids), and goes with the other derivatives.
TEST(DenseRefinement, TheReferenceSamplesAreItsGreyAndGradients) {
  auto pair = renderPair("desk", kMotion);
  const hrgbd::DenseParams p;
  for (auto& level : pair.ref.levels) {
    ASSERT_EQ(level.samples.type(), CV_32FC4);
    ASSERT_EQ(level.samples.size(), level.grey.size());
    const cv::Mat& g = level.grey;
    double strongest = 0;
    for (int v = 1; v + 1 < g.rows; ++v)
      for (int u = 1; u + 1 < g.cols; ++u) {
        const cv::Vec4f s = level.samples.at<cv::Vec4f>(v, u);
        const float gx = (g.at<float>(v, u + 1) - g.at<float>(v, u - 1)) / 2,
                    gy = (g.at<float>(v + 1, u) - g.at<float>(v - 1, u)) / 2;
        ASSERT_EQ(s[0], g.at<float>(v, u)) << u << ", " << v;
        ASSERT_NEAR(s[1], gx, 1e-4) << u << ", " << v;
        ASSERT_NEAR(s[2], gy, 1e-4) << u << ", " << v;
        ASSERT_EQ(s[3], 0);
        strongest = std::max<double>(strongest, std::abs(gx) + std::abs(gy));
      }
    EXPECT_GT(strongest, 10);              // a textured render: gradients to compare
    const hrgbd::DenseLevel copy = level;  // shares the buffers
    const cv::Mat before = copy.samples.clone();
    level.grey = level.grey + 1;  // new data
    hrgbd::addDerivatives(level, p);
    EXPECT_EQ(cv::norm(copy.samples, before, cv::NORM_INF), 0);
    EXPECT_EQ(level.samples.at<cv::Vec4f>(1, 1)[0], copy.samples.at<cv::Vec4f>(1, 1)[0] + 1);
    hrgbd::dropDerivatives(level);
    EXPECT_TRUE(level.samples.empty());
    EXPECT_FALSE(hrgbd::hasDerivatives(level));
  }
}

// Depths in wrong units: a scene of micrometres is refined like the same scene in metres (the
// normal equations' float sums hold it); one of nanometres overflows them, and the refinement
// answers not ok instead of leaving its start in place as a result.
TEST(DenseRefinement, AMicrometreSceneIsRefinedANanometreSceneRefused) {
  for (const double k : {1e-6, 1e-9}) {
    auto pair = renderPair("desk", kMotion);
    hrgbd::DenseParams p;
    p.max_depth_difference *= k;
    for (auto* pyramid : {&pair.cur, &pair.ref})
      for (auto& level : pyramid->levels) {
        level.depth = level.depth * k;  // new data
        hrgbd::dropDerivatives(level);
        hrgbd::addDerivatives(level, p);
      }
    Isometry3d truth = pair.truth;
    truth.translation() *= k;
    const Isometry3d start = perturbed(truth, 0.01 * k, 1.0);
    const auto d = hrgbd::refineDense(pair.cur, pair.ref, {start}, p);
    if (k == 1e-9) {
      EXPECT_FALSE(d.ok);
      EXPECT_NE(d.detail.find("not finite"), std::string::npos) << d.detail;
      continue;
    }
    ASSERT_TRUE(d.ok) << d.detail;
    // (the start is 15 "mm" and 1.4 deg off; the depth noise model, sigma ~ z^2, is not
    // scale-free, so this scene's point-to-plane term outweighs the intensity's)
    const auto [t, r] = error(d.T, truth);
    EXPECT_LT(t, 0.005 * k);
    EXPECT_LT(r, 0.05);
  }
}

// Normal equations that are not finite (here infinite grey levels in a block of the reference's
// samples: their residuals' Huber weights are 0, times infinity) give no step: the refinement
// answers not ok, never its start as a result.
TEST(DenseRefinement, NormalEquationsThatAreNotFiniteGiveNoResult) {
  auto pair = renderPair("desk", kMotion);
  for (auto& level : pair.ref.levels)  // a block: the noise scales (medians) stay finite
    level
        .samples(cv::Rect(level.samples.cols / 4, level.samples.rows / 4, level.samples.cols / 4,
                          level.samples.rows / 4))
        .setTo(cv::Scalar(std::numeric_limits<float>::infinity(), 100, 100, 0));
  const Isometry3d start = perturbed(pair.truth, 0.01, 1.0);
  const auto d = hrgbd::refineDense(pair.cur, pair.ref, {start}, hrgbd::DenseParams());
  EXPECT_FALSE(d.ok);
  EXPECT_NE(d.detail.find("not finite"), std::string::npos) << d.detail;
  EXPECT_TRUE(d.T.isApprox(start));
}

TEST(DenseRefinement, NothingToRefineWithIsNotOk) {
  auto pair = renderPair("desk", kMotion);
  for (auto& level : pair.cur.levels) level.depth.setTo(std::nanf(""));  // no depth at all
  const Isometry3d start = perturbed(pair.truth, 0.01, 1.0);
  const auto d = hrgbd::refineDense(pair.cur, pair.ref, {start}, hrgbd::DenseParams());
  EXPECT_FALSE(d.ok);
  EXPECT_NE(d.detail.find("min_pixels"), std::string::npos) << d.detail;
  EXPECT_TRUE(d.T.isApprox(start));
}

TEST(DenseRefinement, UnknownDepthNeverBlendsIntoTheCoarserLevels) {
  hrgbd::RgbdImage f;
  f.grey = cv::Mat(8, 8, CV_8U, cv::Scalar(100));
  f.depth = cv::Mat(8, 8, CV_32F, cv::Scalar(2.0f));
  f.depth(cv::Rect(0, 0, 2, 2)).setTo(0);     // a hole: one whole block at level 1
  f.depth.at<float>(4, 4) = 0;                // one unknown pixel of a block
  f.depth(cv::Rect(6, 6, 2, 2)).setTo(1.0f);  // a nearer surface ...
  f.depth.at<float>(7, 7) = 3.0f;             // ... with one far pixel behind it
  f.cam = {4, 4, 3.5, 3.5, 8, 8};
  hrgbd::DenseParams p;
  p.levels = 2, p.finest_level = 0;
  const auto pyr = hrgbd::buildDensePyramid(f, p);
  ASSERT_EQ(pyr.levels.size(), 2u);
  const cv::Mat& half = pyr.levels[1].depth;
  EXPECT_TRUE(std::isnan(half.at<float>(0, 0)));
  EXPECT_FLOAT_EQ(half.at<float>(2, 2), 2.0f);
  EXPECT_FLOAT_EQ(half.at<float>(3, 3), 1.0f);  // the nearest surface, not a blend with 3 m
  EXPECT_TRUE(std::isnan(pyr.levels[0].depth.at<float>(4, 4)));
  const auto bare = hrgbd::buildDensePyramid(f, p, false);  // a tracked frame's
  ASSERT_EQ(bare.levels.size(), 2u);
  EXPECT_TRUE(hrgbd::hasDerivatives(pyr.levels[1]));
  EXPECT_FALSE(hrgbd::hasDerivatives(bare.levels[1]));
  EXPECT_EQ(cv::norm(bare.levels[1].grey, pyr.levels[1].grey, cv::NORM_INF), 0);
}

TEST(DenseRefinement, TinyImagesGiveFewerLevelsAndNoRefinement) {
  hrgbd::RgbdImage f;
  f.grey = cv::Mat(3, 3, CV_8U, cv::Scalar(100));
  f.depth = cv::Mat(3, 3, CV_32F, cv::Scalar(1.0f));
  f.cam = {2, 2, 1, 1, 3, 3};
  const auto pyr = hrgbd::buildDensePyramid(f, hrgbd::DenseParams());  // finest level 1 of 4
  EXPECT_TRUE(pyr.levels.empty());
  const auto d = hrgbd::refineDense(pyr, pyr, {Isometry3d::Identity()}, hrgbd::DenseParams());
  EXPECT_FALSE(d.ok);
  hrgbd::DenseParams p;
  p.finest_level = 0;
  const auto one = hrgbd::buildDensePyramid(f, p);
  ASSERT_EQ(one.levels.size(), 1u);
  EXPECT_FALSE(hrgbd::refineDense(one, one, {Isometry3d::Identity()}, p).ok);  // 9 < min_pixels
}

// A step below the convergence threshold (converged_px) is taken without an evaluation of
// its own: refining a converged estimate again on one level costs no evaluation (the old rule
// spent at least one on every call). Refined again from each result until then, at most 5 times:
// a level may also end on a refused uphill step, which the next call evaluates again.
TEST(DenseRefinement, AConvergedEstimateCostsNoFurtherEvaluation) {
  hrgbd::DenseParams p;
  p.levels = 2, p.finest_level = 1, p.iterations = 50;  // one level, run to convergence
  const auto pair = renderPair("desk", kMotion, p);
  auto d = hrgbd::refineDense(pair.cur, pair.ref, {perturbed(pair.truth, 0.003, 0.3)}, p);
  ASSERT_TRUE(d.ok) << d.detail;
  EXPECT_GT(d.iterations, 1);
  EXPECT_LT(error(d.T, pair.truth).first, 0.002);
  int calls = 1;
  for (; calls <= 5 && d.iterations > 0; ++calls) {
    const auto again = hrgbd::refineDense(pair.cur, pair.ref, {d.T}, p);
    ASSERT_TRUE(again.ok) << again.detail;
    EXPECT_LT(error(again.T, d.T).first, 0.001);
    d = again;
  }
  EXPECT_EQ(d.iterations, 0) << "after " << calls << " calls";  // measured: the 2nd call
}

// The cells whose corners all have a gradient below min_gradient are skipped before sampling
// (DenseLevel::textured): a shortcut that must give the same result as sampling every cell.
TEST(DenseRefinement, SkippingUntexturedCellsChangesNothing) {
  hrgbd::DenseParams p;
  p.min_gradient = 8;  // many cells below it on the desk renders
  const auto pair = renderPair("desk", kMotion, p);
  hrgbd::DensePyramid every_cell = pair.ref;
  std::size_t skipped = 0;
  for (auto& level : every_cell.levels) {
    skipped += level.textured.total() - static_cast<std::size_t>(cv::countNonZero(level.textured));
    level.textured = cv::Mat(level.textured.size(), CV_8U, cv::Scalar(1));  // new data
  }
  ASSERT_GT(skipped, every_cell.levels.front().textured.total() / 10);
  // a cell is skipped when none of its 4 corners reaches min_gradient (less the mask's margin
  // of 0.01 % for rounding), and only then
  const double t2 = p.min_gradient * p.min_gradient;
  for (const auto& l : pair.ref.levels)
    for (int v = 0; v + 1 < l.grey.rows; ++v)
      for (int u = 0; u + 1 < l.grey.cols; ++u) {
        double strongest = 0;
        for (int k = 0; k < 4; ++k) {
          const cv::Vec4f s = l.samples.at<cv::Vec4f>(v + k / 2, u + k % 2);  // grey, gx, gy
          const double gx = s[1], gy = s[2];
          strongest = std::max(strongest, gx * gx + gy * gy);
        }
        const bool textured = l.textured.at<uchar>(v, u) != 0;
        if (strongest >= t2) {
          ASSERT_TRUE(textured) << "cell " << u << ", " << v;
        }
        if (textured) {
          ASSERT_GE(strongest, t2 * (1 - 1e-4)) << "cell " << u << ", " << v;
        }
      }
  // refined with `params` on the mask and on every cell: the same pose and pairs
  const Isometry3d start = perturbed(pair.truth, 0.01, 1.0);
  auto bothWays = [&](const hrgbd::DenseParams& params) {
    const auto masked = hrgbd::refineDense(pair.cur, pair.ref, {start}, params);
    const auto every = hrgbd::refineDense(pair.cur, every_cell, {start}, params);
    EXPECT_TRUE(masked.T.matrix() == every.T.matrix());
    EXPECT_EQ(masked.photometric_pairs, every.photometric_pairs);
    return std::make_pair(masked, every);
  };
  const auto [a, b] = bothWays(p);
  ASSERT_TRUE(a.ok) << a.detail;
  EXPECT_EQ(a.iterations, b.iterations);

  // refined with a lower min_gradient than the cells were made for, none is skipped
  hrgbd::DenseParams lower = p;
  lower.min_gradient = 2;
  const auto c = bothWays(lower).first;
  ASSERT_TRUE(c.ok) << c.detail;
  EXPECT_GT(c.photometric_pairs, a.photometric_pairs);
}
