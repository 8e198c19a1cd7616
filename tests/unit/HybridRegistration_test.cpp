// The hybrid policy (paper III-A plus the fallback and the min-inliers hand-over) with two fake
// paths that return scripted results: which path is asked, which result stands, whose times add.
#include <gtest/gtest.h>

#include "rgbd_odometry/FeatureRegistration.h"

using Status = hrgbd::FrameResult::Status;

namespace {

// A path that gives each frame `orb` ORB features (photometric) or none (geometric) and
// answers align() with a fixed result; counts its calls.
class FakePath : public hrgbd::Registration {
 public:
  FakePath(hrgbd::FramePath::Sparse path, int orb, Status status, std::size_t inliers, double ms)
      : m_path{path}, m_orb(orb) {
    m_result.status = status;
    m_result.inliers = inliers;
    m_result.seen.path = m_path;
    m_result.seen.ms.matching = ms;
  }
  hrgbd::FrameFeatures prepare(hrgbd::Frame& f) override {
    ++prepared;
    if (m_orb >= 0 && !f.orb)
      f.orb = hrgbd::FeatureSet{{}, {}, std::vector<Eigen::Vector3d>(m_orb)};
    hrgbd::FrameFeatures seen;
    seen.path = m_path;
    seen.orb_features = f.orb ? f.orb->size() : 0;
    return seen;
  }
  hrgbd::RegistrationResult align(hrgbd::Frame&, hrgbd::Frame&) override {
    ++aligned;
    return m_result;
  }
  int prepared = 0, aligned = 0;

 private:
  hrgbd::FramePath m_path;
  int m_orb;
  hrgbd::RegistrationResult m_result;
};

struct Case {
  FakePath* photometric;
  FakePath* geometric;
  std::unique_ptr<hrgbd::HybridRegistration> hybrid;
};

// Photometric path with `orb` features answering (status, inliers) in 2 ms; geometric path
// answering `geometric_status` with 40 inliers in 5 ms.
Case make(int orb, Status status, std::size_t inliers, Status geometric_status,
          bool fallback = true) {
  auto p =
      std::make_unique<FakePath>(hrgbd::FramePath::Sparse::Photometric, orb, status, inliers, 2.0);
  auto g = std::make_unique<FakePath>(hrgbd::FramePath::Sparse::Geometric, -1, geometric_status, 40,
                                      5.0);
  Case c{p.get(), g.get(), nullptr};
  c.hybrid = std::make_unique<hrgbd::HybridRegistration>(std::move(p), std::move(g),
                                                         hrgbd::HybridPolicy{50, 30, fallback});
  return c;
}

hrgbd::RegistrationResult run(Case& c) {
  hrgbd::Frame ref, cur;
  c.hybrid->prepare(ref);
  c.hybrid->prepare(cur);
  return c.hybrid->align(cur, ref);
}

}  // namespace

TEST(HybridRegistration, FewOrbFeaturesTakeTheGeometricPathOnly) {
  auto c = make(49, Status::Ok, 500, Status::Ok);
  hrgbd::Frame f;
  EXPECT_EQ(hrgbd::toString(c.hybrid->prepare(f).path), "geometric");
  const auto r = run(c);
  EXPECT_EQ(hrgbd::toString(r.seen.path), "geometric");
  EXPECT_EQ(c.photometric->aligned, 0);
  EXPECT_EQ(c.geometric->aligned, 1);
}

TEST(HybridRegistration, EnoughPhotometricInliersStand) {
  auto c = make(50, Status::Ok, 30, Status::Ok);
  hrgbd::Frame f;
  EXPECT_EQ(hrgbd::toString(c.hybrid->prepare(f).path), "photometric");
  const auto r = run(c);
  EXPECT_EQ(hrgbd::toString(r.seen.path), "photometric");
  EXPECT_EQ(r.inliers, 30u);
  EXPECT_EQ(c.geometric->aligned, 0);
}

TEST(HybridRegistration, FewPhotometricInliersHandOverWhenTheGeometricPathRegisters) {
  auto c = make(500, Status::Ok, 29, Status::Ok);
  const auto r = run(c);
  EXPECT_EQ(hrgbd::toString(r.seen.path), "geometric");
  EXPECT_EQ(r.inliers, 40u);
  EXPECT_DOUBLE_EQ(r.seen.ms.matching, 7.0);  // both attempts are counted
  auto d = make(500, Status::Ok, 29, Status::TooFewInliers);
  const auto kept = run(d);
  EXPECT_EQ(hrgbd::toString(kept.seen.path), "photometric");  // the weak photometric fit stands
  EXPECT_EQ(kept.status, Status::Ok);
  EXPECT_DOUBLE_EQ(kept.seen.ms.matching, 7.0);
}

TEST(HybridRegistration, PhotometricFailuresFallBackOnlyWhenAllowed) {
  auto c = make(500, Status::TooFewMatches, 0, Status::LargeResiduals);
  const auto r = run(c);
  EXPECT_EQ(hrgbd::toString(r.seen.path), "geometric");  // the geometric result, whatever it is
  EXPECT_EQ(r.status, Status::LargeResiduals);
  auto d = make(500, Status::TooFewMatches, 0, Status::Ok, false);
  const auto no = run(d);
  EXPECT_EQ(hrgbd::toString(no.seen.path), "photometric");
  EXPECT_EQ(no.status, Status::TooFewMatches);
  EXPECT_EQ(d.geometric->aligned, 0);
}
