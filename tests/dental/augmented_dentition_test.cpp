// The augmented dentition on shapes whose answer is known (issue 30): a CT tooth, a cylinder of
// radius 4 mm from 10 mm below the gingival level to 5 mm above it, whose crown the scan shows
// 1 mm taller (as if a filling's streaks had eaten the CT's); a streak beside the crown, which
// the CT's threshold took for tooth; and a second tooth the scan does not hold. The dentition
// must be the CT's root up to the neck, the scan's crown above it, no streak, and the unscanned
// tooth whole.
#include <gtest/gtest.h>

#include <cmath>

#include "dental/augmented_dentition.h"
#include "geometry/mesh_transform.h"

namespace maxillo::dental {
namespace {

constexpr uint8_t kJaw = 3;
constexpr double kRadius = 4, kRootBottom = -10, kCtTop = 5, kScanTop = 6;

struct Scene {
  Volume ct;
  LabelVolume labels;
  TriangleMesh ct_teeth, scan;
};

// A CT at 0.5 mm of the two teeth and the streak, labelled kJaw there: 2960 HU inside and 40
// outside, so that the teeth threshold (1500 HU, interpolated between voxel centres) lies half-way,
// where the painted boundary is.
Scene make_scene() {
  Scene s;
  VolumeGeometry g;
  g.spacing = Eigen::Vector3d::Constant(0.5);
  g.origin = Eigen::Vector3d(-10, -10, -14);
  g.size = Eigen::Vector3i(70, 40, 46);
  s.ct = Volume{g, std::vector<int16_t>(size_t(g.voxel_count()), 40)};
  s.labels = LabelVolume{g, std::vector<uint8_t>(size_t(g.voxel_count()), 0)};
  auto in_cylinder = [](const Eigen::Vector3d& p, double x, double radius) {
    return std::hypot(p.x() - x, p.y()) <= radius && p.z() >= kRootBottom && p.z() <= kCtTop;
  };
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        const Eigen::Vector3d p = g.world(Eigen::Vector3d(i, j, k));
        const bool streak = p.x() >= 6 && p.x() <= 7.5 && std::abs(p.y()) <= 1 && p.z() >= 2 && p.z() <= 3.5;
        if (in_cylinder(p, 0, kRadius) || in_cylinder(p, 16, 2) || streak) {
          s.ct.hu[size_t(g.index(i, j, k))] = 2960;
          s.labels.labels[size_t(g.index(i, j, k))] = kJaw;
        }
      }
  // The CT's teeth as the case traces them: every tooth (the streak's few voxels are no surface
  // of their own here; they need none to be cut).
  const TriangleMesh scanned_tooth = cylinder_mesh({0, 0, kRootBottom}, {0, 0, kCtTop}, kRadius, 48);
  const TriangleMesh other_tooth = cylinder_mesh({16, 0, kRootBottom}, {16, 0, kCtTop}, 2, 48);
  s.ct_teeth = merged({&scanned_tooth, &other_tooth});
  // The scan: the crown from the neck (z = 0) up, its bottom cap left off (a scan sees no neck's
  // inside), outward normals.
  const TriangleMesh crown = cylinder_mesh({0, 0, 0}, {0, 0, kScanTop}, kRadius, 48);
  s.scan.vertices = crown.vertices;
  std::vector<Eigen::Vector3i> faces;
  for (Eigen::Index f = 0; f < crown.face_count(); ++f) {
    bool bottom = true;
    for (int c = 0; c < 3; ++c) bottom = bottom && std::abs(crown.vertices(crown.faces(f, c), 2)) < 1e-9;
    if (!bottom) faces.push_back(crown.faces.row(f).transpose());
  }
  s.scan.faces.resize(Eigen::Index(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f) s.scan.faces.row(Eigen::Index(f)) = faces[f].transpose();
  return s;
}

// The field at the voxel nearest p (the grid must hold p).
double field_at(const AugmentedDentition& d, const Eigen::Vector3d& p) {
  const Eigen::Vector3i v = d.field.geometry.continuous_index(p).array().round().cast<int>();
  EXPECT_TRUE(d.field.geometry.contains(v.x(), v.y(), v.z())) << p.transpose();
  return d.field.geometry.contains(v.x(), v.y(), v.z()) ? d.field.at(v.x(), v.y(), v.z()) : -kFieldSaturation;
}

bool inside(const AugmentedDentition& d, const Eigen::Vector3d& p) { return field_at(d, p) > 0; }

TEST(AugmentedDentition, TheScannedCrownOnTheCtRootAndNothingElse) {
  const Scene s = make_scene();
  const AugmentedDentition d = augmented_dentition(s.ct, s.labels, kJaw, s.ct_teeth, s.scan, Eigen::Vector3d::UnitZ());
  // The crown is the scan's: inside up to z = 6, not the CT's 5, and outside above it.
  EXPECT_TRUE(inside(d, {0, 0, 5.6}));
  EXPECT_FALSE(inside(d, {0, 0, 6.6}));
  EXPECT_GT(field_at(d, {0, 0, 5.75}), 0);  // the zero level between the voxels, at the scan's top
  EXPECT_LT(field_at(d, {0, 0, 6.25}), 0);
  // Filled below the crown's surface (the outside did not get under the shell at the neck), with
  // the CT's root below it.
  EXPECT_TRUE(inside(d, {0, 0, 3}));
  EXPECT_TRUE(inside(d, {0, 0, -8}));
  EXPECT_FALSE(inside(d, {0, 0, -11}));
  // The streak beside the crown is cut; the tooth the scan does not hold is kept whole.
  EXPECT_FALSE(inside(d, {6.75, 0, 2.75}));
  EXPECT_TRUE(inside(d, {16, 0, 4}));
  EXPECT_GT(d.ct_voxels_cut, 0);
  // Volume inside the field's zero level: the tooth from -10 to the scan's 6 mm, and the unscanned
  // one from -10 to 5 mm, to a few per cent (the grid's 0.25 mm voxels on radii of 2 and 4 mm).
  const double voxel = std::pow(d.field.geometry.spacing.x(), 3);
  double volume = 0;
  for (int16_t value : d.field.hu) volume += value > 0 ? voxel : 0;
  const double expected = M_PI * kRadius * kRadius * (kScanTop - kRootBottom) + M_PI * 4 * (kCtTop - kRootBottom);
  EXPECT_NEAR(volume / expected, 1.0, 0.05) << volume << " mm3 against " << expected;
  // Every scan vertex is on the crown (none lies below the neck).
  for (uint8_t c : d.crown_vertex) EXPECT_EQ(c, 1);
}

TEST(AugmentedDentition, AScanOffTheTeethIsAnError) {
  Scene s = make_scene();
  s.scan = transformed(s.scan, Eigen::Isometry3d(Eigen::Translation3d(0, 0, 40)));
  EXPECT_THROW(augmented_dentition(s.ct, s.labels, kJaw, s.ct_teeth, s.scan, Eigen::Vector3d::UnitZ()), Error);
}

}  // namespace
}  // namespace maxillo::dental
