// The dense refinement after a registration (DenseRefined) on rendered frames: a result of the
// prediction alone is no sparse fit, and it must explain the reference's depth (the depth check,
// DepthAgreement.h) unless the reference has none.
#include <gtest/gtest.h>

#include <cmath>

#include "DenseRenders.h"
#include "rgbd_odometry/DepthAgreement.h"
#include "rgbd_odometry/FeatureRegistration.h"

using namespace hrgbd::test;  // NOLINT: the rendered frames' helpers
using Eigen::Isometry3d;

namespace {

// The desk (or another scene) rendered from the reference pose and `motion` from it.
struct Frames {
  explicit Frames(const mrpt::poses::CPose3D& motion, const std::string& scene_type = "desk")
      : truth(hrgbd::toIsometry(motion)) {
    const auto scene = hrgbd::sim::makeScene(scene_type, false);
    // the desk's pairs from above the desk; other scenes from where their sweeps look
    const auto from =
        scene_type == "desk"
            ? referencePose()
            : hrgbd::sim::lookAt(scene.look_at + scene.view_dir.normalized() * scene.distance,
                                 scene.look_at);
    cur.image = render(scene, from + motion);
    ref.image = render(scene, from);
  }
  hrgbd::Frame cur, ref;
  Isometry3d truth;
};

// `sparse` (scripted) and the dense refinement of the frames, from `guess` as the prediction;
// `checked_depth`, when given, replaces the current frame's depth after its pyramid is made: the
// depth check alone sees it.
hrgbd::RegistrationResult refined(Frames& f, const hrgbd::RegistrationResult& sparse,
                                  const Isometry3d& guess, const hrgbd::DenseParams& p = {},
                                  const cv::Mat& checked_depth = {}) {
  hrgbd::DenseRefined dense(std::make_unique<ScriptedSparse>(sparse), p);
  f.cur.dense.reset(), f.ref.dense.reset();
  dense.prepare(f.cur);
  dense.prepare(f.ref);
  if (!checked_depth.empty()) f.cur.image.depth = checked_depth;
  f.cur.guess = guess;
  return dense.align(f.cur, f.ref);
}

hrgbd::RegistrationResult failedFit() {
  hrgbd::RegistrationResult r;
  r.status = hrgbd::FrameResult::Status::TooFewMatches;
  return r;
}

}  // namespace

TEST(DenseRefined, AResultOfThePredictionAloneIsNotASparseFit) {
  // The SLAM mode accepts a loop only on a sparse fit that succeeded: the refinement from the
  // prediction alone must say that it is not one, though it registers.
  Frames f(kMotion);
  for (const bool sparse : {false, true}) {
    hrgbd::RegistrationResult s = failedFit();
    if (sparse) s.status = hrgbd::FrameResult::Status::Ok;
    s.sparse_ok = sparse;
    s.inliers = 150;  // a failed fit may still count inliers
    s.T = perturbed(f.truth, 0.01, 1.0);
    s.seen.path.sparse = hrgbd::FramePath::Sparse::Photometric;
    const auto r = refined(f, s, perturbed(f.truth, 0.02, -1.5));
    ASSERT_TRUE(r.ok()) << r.detail;
    EXPECT_LT(error(r.T, f.truth).first, 0.002);
    EXPECT_EQ(r.sparse_ok, sparse);
    if (!sparse) {
      EXPECT_EQ(hrgbd::toString(r.seen.path), "photometric+dense(prediction)");
    }
  }
}

TEST(DenseRefined, WithAnInlierFloorOnlyFitsOnEnoughInliersAreRefined) {
  // the SLAM mode's loop verification needs loop_min_inliers sparse inliers: a fit on fewer, or
  // none, is returned as the sparse stage gave it, unrefined; a fit on enough is refined
  Frames f(kMotion);
  const Isometry3d start = perturbed(f.truth, 0.01, 1.0);
  for (const std::size_t inliers : {0u, 99u, 100u}) {
    hrgbd::RegistrationResult s = inliers == 0 ? failedFit() : hrgbd::RegistrationResult();
    if (inliers > 0) s.status = hrgbd::FrameResult::Status::Ok, s.sparse_ok = true;
    s.inliers = inliers;
    s.T = start;
    hrgbd::DenseRefined dense(std::make_unique<ScriptedSparse>(s), hrgbd::DenseParams(), 100);
    f.cur.dense.reset(), f.ref.dense.reset();
    dense.prepare(f.cur);
    dense.prepare(f.ref);
    f.cur.guess = f.truth;
    const auto r = dense.align(f.cur, f.ref);
    if (inliers < 100) {
      EXPECT_EQ(r.seen.path.refined, hrgbd::FramePath::Refined::None) << inliers;
      EXPECT_EQ(r.ok(), inliers > 0);
      EXPECT_TRUE(r.T.isApprox(start)) << inliers;
    } else {
      ASSERT_TRUE(r.ok()) << r.detail;
      EXPECT_NE(r.seen.path.refined, hrgbd::FramePath::Refined::None);
      EXPECT_LT(error(r.T, f.truth).first, 0.002);
    }
  }
}

// The depth check as DenseRefined calls it: the motion that made the frames explains the
// reference's depth, a motion 20 cm and 10 deg off does not, nor one that puts every point behind
// the reference camera (none lands on known depth).
TEST(DenseRefined, TheDepthAgreesWithTheTrueMotionNotAWrongOne) {
  const Frames f(kMotion);
  const auto& cur = f.cur.image;
  const hrgbd::DepthTolerance within{0, 3 * std::sqrt(2.0) * hrgbd::DenseParams().depth_noise};
  const auto right = hrgbd::depthAgreement(cur, f.ref.image, f.truth, within, 2);
  EXPECT_GT(right.compared, cur.depth.total() / 8);  // most of every 4th pixel
  EXPECT_GT(right.share(), 0.95);
  const auto wrong = perturbed(f.truth, 0.2, 10.0);
  EXPECT_LT(hrgbd::depthAgreement(cur, f.ref.image, wrong, within, 2).share(), 0.3);
  Isometry3d behind = Isometry3d::Identity();
  behind.translation().z() = -20;
  const auto none = hrgbd::depthAgreement(cur, f.ref.image, behind, within, 2);
  EXPECT_EQ(none.compared, 0u);
  EXPECT_EQ(none.share(), 0.0);
}

// Frames out of order: 31 cm and 19 deg apart, no sparse fit, and the refinement from a
// prediction of no motion stops in a local minimum next to it (measured 31 cm from the truth)
// that pairs enough pixels but does not explain the reference's depth. Flagged, with the reason;
// without the check (min_depth_agreement = 0) it was accepted.
TEST(DenseRefined, ARefinementAloneThatDoesNotExplainTheDepthIsRefused) {
  Frames f(mrpt::poses::CPose3D(0.3, 0.03, 0.06, mrpt::DEG2RAD(18.0), mrpt::DEG2RAD(6.0), 0));
  for (const double min_agreement : {hrgbd::DenseParams().min_depth_agreement, 0.0}) {
    hrgbd::DenseParams p;
    p.min_depth_agreement = min_agreement;
    const auto r = refined(f, failedFit(), Isometry3d::Identity(), p);
    if (min_agreement > 0) {
      EXPECT_FALSE(r.ok());
      EXPECT_NE(r.detail.find("agree with the reference depth"), std::string::npos) << r.detail;
    } else {
      ASSERT_TRUE(r.ok()) << r.detail;
      EXPECT_GT(error(r.T, f.truth).first, 0.1);  // and wrong
    }
  }
}

// A reference without depth gives the depth check nothing to judge by: a refinement alone on the
// intensity pairs stands, as without the check.
TEST(DenseRefined, AReferenceWithoutDepthIsNotJudgedByIt) {
  Frames f(kMotion);
  f.ref.image.depth.setTo(0);
  const auto r = refined(f, failedFit(), perturbed(f.truth, 0.005, 0.5));
  EXPECT_TRUE(r.ok()) << r.detail;
  EXPECT_EQ(r.detail.find("agree with the reference depth"), std::string::npos) << r.detail;
}

// Where the motion prediction's refinement fits better than the sparse fit's, the depth decides
// too. Frames 31 cm and 19 deg apart, the sparse fit no motion (wrong) and the prediction near the
// truth: the refinements end apart (the sparse fit's in a local minimum), and the prediction's
// wins. The current frame's depth is then rendered again from three poses: the truth (the
// prediction's refinement stands), where the sparse fit's refinement ended (that one is taken),
// and 20 cm / 10 deg from both (neither explains it: the frame is refused).
TEST(DenseRefined, APredictionThatDoesNotExplainTheDepthGivesWayToTheSparseFit) {
  const mrpt::poses::CPose3D motion(0.3, 0.03, 0.06, mrpt::DEG2RAD(18.0), mrpt::DEG2RAD(6.0), 0);
  Frames f(motion);
  hrgbd::RegistrationResult s;
  s.status = hrgbd::FrameResult::Status::Ok;
  s.sparse_ok = true;
  s.T = Isometry3d::Identity();
  s.seen.path.sparse = hrgbd::FramePath::Sparse::Photometric;
  const Isometry3d guess = perturbed(f.truth, 0.005, 0.5);
  // where the two refinements end, the same refinement as DenseRefined's
  const hrgbd::DenseParams p;
  const auto d = hrgbd::refineDense(hrgbd::buildDensePyramid(f.cur.image, p),
                                    hrgbd::buildDensePyramid(f.ref.image, p), {s.T, guess}, p);
  ASSERT_TRUE(d.ok) << d.detail;
  ASSERT_EQ(d.start, 1u);
  ASSERT_TRUE(d.first_start_refined.has_value());
  const Isometry3d sparse_end = *d.first_start_refined;
  ASSERT_GT(error(sparse_end, f.truth).first, 0.1);

  const auto scene = hrgbd::sim::makeScene("desk", false);
  const auto depthSeenFrom = [&](const Isometry3d& T) {
    return render(scene, referencePose() + hrgbd::toPose(T)).depth;
  };
  {
    const auto r = refined(f, s, guess);
    ASSERT_TRUE(r.ok()) << r.detail;
    EXPECT_EQ(hrgbd::toString(r.seen.path), "photometric+dense(prediction)");
    EXPECT_LT(error(r.T, f.truth).first, 0.002);
  }
  {
    Frames g(motion);  // refined() leaves the depth it is given in the frame
    const auto r = refined(g, s, guess, p, depthSeenFrom(sparse_end));
    ASSERT_TRUE(r.ok()) << r.detail;
    EXPECT_EQ(hrgbd::toString(r.seen.path), "photometric+dense");
    EXPECT_LT(error(r.T, sparse_end).first, 1e-9);
  }
  {
    Frames g(motion);
    const auto r = refined(g, s, guess, p, depthSeenFrom(perturbed(f.truth, 0.2, 10.0)));
    EXPECT_EQ(r.status, hrgbd::FrameResult::Status::LargeResiduals);
    EXPECT_NE(r.detail.find("neither motion explains it"), std::string::npos) << r.detail;
    EXPECT_EQ(hrgbd::toString(r.seen.path), "photometric+dense(refused)");
  }
}

TEST(DenseRefined, AMotionTheSceneDoesNotConstrainIsFlaggedDegenerate) {
  // The camera moving 3 cm where the scene does not tell (along the stripes of a wall, along a
  // plain wall, along a corridor): the sparse fit and its refinement are flagged whatever they
  // say; the desk registers.
  for (const std::string scene : {"stripes", "wall", "corridor", "desk"}) {
    // optical y (down in the image: along the stripes), optical z (along the corridor)
    const mrpt::poses::CPose3D along(0, scene == "corridor" ? 0 : 0.03,
                                     scene == "corridor" ? 0.03 : 0, 0, 0, 0);
    Frames f(along, scene);
    hrgbd::RegistrationResult s;
    s.status = hrgbd::FrameResult::Status::Ok;
    s.sparse_ok = true;
    s.inliers = 20;
    s.T = Isometry3d::Identity();  // what a fit on the stripes finds: no motion
    s.seen.path.sparse = hrgbd::FramePath::Sparse::Geometric;
    const auto r = refined(f, s, Isometry3d::Identity());
    if (scene == "desk") {
      EXPECT_TRUE(r.ok()) << r.detail;
      continue;
    }
    EXPECT_EQ(r.status, hrgbd::FrameResult::Status::Degenerate) << scene << ": " << r.detail;
    EXPECT_NE(r.detail.find("does not constrain the motion"), std::string::npos) << r.detail;
  }
}

TEST(DenseRefined, ASparseFitOnFramesOfNoiseIsRefused) {
  // Random grey levels and depths (1-4 m): features match by chance, and a sparse fit found on
  // them must not pass as a motion; the desk's does.
  for (const bool noise : {true, false}) {
    Frames f(kMotion);
    if (noise) {
      cv::RNG rng(7);
      for (auto* image : {&f.cur.image, &f.ref.image}) {
        rng.fill(image->grey, cv::RNG::UNIFORM, 0, 255);
        rng.fill(image->depth, cv::RNG::UNIFORM, 1.0, 4.0);
      }
    }
    hrgbd::RegistrationResult s;
    s.status = hrgbd::FrameResult::Status::Ok;
    s.sparse_ok = true;
    s.inliers = 20;
    s.T = noise ? Isometry3d(Eigen::Translation3d(0.02, 0, 0)) : f.truth;
    s.seen.path.sparse = hrgbd::FramePath::Sparse::Geometric;
    const auto r = refined(f, s, s.T);
    if (!noise) {
      EXPECT_TRUE(r.ok()) << r.detail;
      continue;
    }
    EXPECT_EQ(r.status, hrgbd::FrameResult::Status::LargeResiduals) << r.detail;
    EXPECT_NE(r.detail.find("does not explain it"), std::string::npos) << r.detail;
  }
}
