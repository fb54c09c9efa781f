// Known answers of the phantom's design: cephalometric angles and distances computed here
// with plain Eigen in the mid-sagittal plane (y, z), and the Class II/III knobs.
#include <Eigen/Geometry>
#include <numbers>

#include "phantom_probe.h"

namespace maxillo::test {
namespace {

Eigen::Vector2d sagittal(const Eigen::Vector3d& p) { return {p.y(), p.z()}; }

double angle_deg(const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
  return std::acos(std::clamp(u.normalized().dot(v.normalized()), -1.0, 1.0)) * 180 / std::numbers::pi;
}

// Angle at vertex between the rays to a and b (mid-sagittal projection).
double angle_at(const Phantom& ph, const char* a, const char* vertex, const char* b) {
  Eigen::Vector2d v = sagittal(landmark(ph, vertex));
  return angle_deg(sagittal(landmark(ph, a)) - v, sagittal(landmark(ph, b)) - v);
}

// Landmarks of a phantom on a coarse grid: they are analytic, the grid does not matter.
Phantom coarse_phantom(SkeletalClass c) {
  PhantomSpec spec = phantom_spec_for_class(c);
  spec.spacing_mm = 3;
  return make_phantom(spec);
}

TEST(PhantomCephalometry, EveryLandmarkPresentOnce) {
  const char* expected[] = {"S",   "N",   "OrR", "OrL", "PoR", "PoL", "A",   "B",    "ANS", "PNS",
                            "Pog", "Me",  "Gn",  "GoR", "GoL", "ArR", "ArL", "U1",   "L1",  "U6R",
                            "U6L", "L6R", "L6L", "Prn", "Sn",  "Ls",  "Li",  "PogS", "NS"};
  const Phantom& ph = default_phantom();
  EXPECT_EQ(ph.landmarks.size(), std::size(expected));
  for (const char* label : expected) EXPECT_TRUE(find_landmark(ph.landmarks, label).has_value()) << label;
}

TEST(PhantomCephalometry, DefaultIsClassOne) {
  const Phantom& ph = default_phantom();
  double sna = angle_at(ph, "S", "N", "A"), snb = angle_at(ph, "S", "N", "B");
  EXPECT_NEAR(sna, 82, 0.5);
  EXPECT_NEAR(snb, 80, 0.5);
  EXPECT_NEAR(sna - snb, 2, 0.5);
}

TEST(PhantomCephalometry, SellaNasionAndFrankfort) {
  const Phantom& ph = default_phantom();
  EXPECT_NEAR((landmark(ph, "N") - landmark(ph, "S")).norm(), 70, 1);
  Eigen::Vector2d po = (sagittal(landmark(ph, "PoR")) + sagittal(landmark(ph, "PoL"))) / 2;
  Eigen::Vector2d orb = (sagittal(landmark(ph, "OrR")) + sagittal(landmark(ph, "OrL"))) / 2;
  Eigen::Vector2d sn = sagittal(landmark(ph, "N")) - sagittal(landmark(ph, "S"));
  EXPECT_NEAR(angle_deg(sn, orb - po), 7, 1);
  // Frankfort horizontal is z = 0 and both sides agree (symmetry).
  for (const char* label : {"PoR", "PoL", "OrR", "OrL"}) EXPECT_NEAR(landmark(ph, label).z(), 0, 1e-6) << label;
}

TEST(PhantomCephalometry, AdultProportions) {
  const Phantom& ph = default_phantom();
  double anterior_face = (landmark(ph, "N") - landmark(ph, "Me")).norm();
  double upper_face = landmark(ph, "N").z() - landmark(ph, "ANS").z();
  EXPECT_GT(anterior_face, 110);
  EXPECT_LT(anterior_face, 135);
  EXPECT_NEAR(upper_face / (landmark(ph, "N").z() - landmark(ph, "Me").z()), 0.45, 0.04);
  EXPECT_NEAR((landmark(ph, "ANS") - landmark(ph, "PNS")).norm(), 52, 4);
  EXPECT_NEAR(std::abs(landmark(ph, "GoL").x() - landmark(ph, "GoR").x()), 95, 8);  // bigonial width
  double overjet = landmark(ph, "L1").y() - landmark(ph, "U1").y();                 // U1 anterior of L1
  double overbite = landmark(ph, "L1").z() - landmark(ph, "U1").z();
  EXPECT_GT(overjet, 1.5);
  EXPECT_LT(overjet, 4.5);
  EXPECT_GT(overbite, 1.5);
  EXPECT_LT(overbite, 4);
}

TEST(PhantomCephalometry, ClassKnobsChangeAnb) {
  Phantom class2 = coarse_phantom(SkeletalClass::II);
  Phantom class3 = coarse_phantom(SkeletalClass::III);
  double anb2 = angle_at(class2, "S", "N", "A") - angle_at(class2, "S", "N", "B");
  double anb3 = angle_at(class3, "S", "N", "A") - angle_at(class3, "S", "N", "B");
  EXPECT_GT(anb2, 4);
  EXPECT_LT(anb3, 0);
  // The knobs move the jaws, not the cranial base.
  EXPECT_EQ(landmark(class3, "S"), landmark(default_phantom(), "S"));
  EXPECT_EQ(landmark(class3, "N"), landmark(default_phantom(), "N"));
}

TEST(PhantomCephalometry, LandmarksDoNotDependOnSpacing) {
  Phantom coarse = coarse_phantom(SkeletalClass::I);
  const Phantom& fine = default_phantom();
  ASSERT_EQ(coarse.landmarks.size(), fine.landmarks.size());
  for (size_t i = 0; i < fine.landmarks.size(); ++i)
    EXPECT_LT((coarse.landmarks[i].position - fine.landmarks[i].position).norm(), 1e-3) << fine.landmarks[i].label;
}

TEST(PhantomCephalometry, LandmarksMirrorAcrossMidSagittalPlane) {
  const Phantom& ph = default_phantom();
  for (auto [right, left] :
       {std::pair{"OrR", "OrL"}, {"PoR", "PoL"}, {"GoR", "GoL"}, {"ArR", "ArL"}, {"U6R", "U6L"}, {"L6R", "L6L"}}) {
    Eigen::Vector3d r = landmark(ph, right), l = landmark(ph, left);
    EXPECT_LT(r.x(), 0) << right << " is on the patient's right (-x)";
    EXPECT_NEAR(r.x(), -l.x(), 1e-9);
    EXPECT_NEAR(r.y(), l.y(), 1e-9);
    EXPECT_NEAR(r.z(), l.z(), 1e-9);
  }
  for (const char* mid : {"S", "N", "A", "B", "ANS", "PNS", "Pog", "Me", "Gn", "Prn", "Sn", "Ls", "Li", "PogS", "NS"})
    EXPECT_EQ(landmark(ph, mid).x(), 0) << mid;
}

}  // namespace
}  // namespace maxillo::test
