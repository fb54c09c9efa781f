// Soft tissue shut in by bone (imaging/enclosed_tissue.h) on a synthetic head whose answer is
// known by construction: a brain inside a skull joined to the face through a foramen, a sinus
// whose air meets the brain through a gap in the bone and reaches the outside through a narrow
// ostium, and a thin flap of the face standing out into the air (a nose's wall).
#include <gtest/gtest.h>

#include <functional>

#include "core/error.h"
#include "imaging/enclosed_tissue.h"

namespace maxillo {
namespace {

constexpr uint8_t kAir = 0, kSoft = 1, kBone = 3;
const Eigen::Vector3d kBrainCentre(46, 45, 45);  // off the grid's middle: the mirror image differs
constexpr double kBrainRadius = 15, kSkullRadius = 18;

struct HeadShape {
  double foramen_radius = 2;  // the tissue's neck through the skull towards the face (-y)
  bool sinus_gap = true;      // the sinus's air touches the brain through a gap in the bone
};

bool in_box(const Eigen::Vector3d& p, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  return (p.array() >= lo.array()).all() && (p.array() < hi.array()).all();
}

uint8_t head_label(const Eigen::Vector3d& p, const HeadShape& shape) {
  const Eigen::Vector3d& c = kBrainCentre;
  const Eigen::Vector3d sinus(c.x(), c.y(), 69);
  const double from_axis_z = std::hypot(p.x() - c.x(), p.y() - c.y()),
               from_axis_y = std::hypot(p.x() - c.x(), p.z() - c.z());
  const double r = (p - kBrainCentre).norm();
  if ((p - sinus).norm() <= 5) return kAir;         // the sinus
  if (from_axis_z <= 1 && p.z() > 69) return kAir;  // its ostium, 2 mm wide, up to the outside
  if (shape.sinus_gap && from_axis_z <= 2 && p.z() > c.z() && r > kBrainRadius - 0.5 && r <= kSkullRadius + 1)
    return kAir;  // the gap: sinus air against the brain
  if (from_axis_y <= shape.foramen_radius && p.y() < c.y() && r <= kSkullRadius + 0.5) return kSoft;  // foramen
  if (r <= kBrainRadius) return kSoft;                                                                // the brain
  if (r <= kSkullRadius) return kBone;                                                                // the skull
  if (in_box(p, {10, 10, 5}, {90, 70, 90})) return kSoft;  // the face around it
  if (in_box(p, {55, 2, 20}, {57, 10, 40})) return kSoft;  // a thin flap standing out in front
  return kAir;
}

LabelVolume synthetic_head(const HeadShape& shape, bool mirrored = false) {
  LabelVolume labels;
  labels.geometry.size = Eigen::Vector3i(100, 80, 100);
  labels.geometry.spacing = Eigen::Vector3d(1, 1, 1);
  const auto& g = labels.geometry;
  labels.labels.resize(size_t(g.voxel_count()));
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        Eigen::Vector3d p = g.world(Eigen::Vector3d(i, j, k)) + Eigen::Vector3d::Constant(0.5);
        if (mirrored) p.x() = 100 - p.x();
        labels.labels[size_t(g.index(i, j, k))] = head_label(p, shape);
      }
  return labels;
}

LabelVolume soft_of(const LabelVolume& labels) {
  LabelVolume soft = labels;
  for (auto& l : soft.labels) l = l == kSoft ? 1 : 0;
  return soft;
}

int64_t count_where(const LabelVolume& labels, const LabelVolume& mask, uint8_t mask_value,
                    const std::function<bool(const Eigen::Vector3d&)>& where) {
  int64_t n = 0;
  const auto& g = labels.geometry;
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        const auto v = size_t(g.index(i, j, k));
        if (mask.labels[v] == mask_value && labels.labels[v] == kSoft &&
            where(g.world(Eigen::Vector3d(i, j, k)) + Eigen::Vector3d::Constant(0.5)))
          ++n;
      }
  return n;
}

bool in_brain(const Eigen::Vector3d& p) { return (p - kBrainCentre).norm() <= kBrainRadius; }
bool outside_skull(const Eigen::Vector3d& p) { return (p - kBrainCentre).norm() > kSkullRadius + 1; }

TEST(EnclosedTissue, TheBrainBehindANarrowForamenIsLeftOutAndTheFaceKeptWhole) {
  const auto labels = synthetic_head({});
  const auto result = without_enclosed_tissue(soft_of(labels), labels, kAir, 4);
  const int64_t brain = count_where(labels, soft_of(labels), 1, in_brain);
  const int64_t brain_kept = count_where(labels, result.kept, 1, in_brain);
  EXPECT_GT(brain, 10000);
  EXPECT_LT(double(brain_kept), 0.02 * double(brain)) << "the brain is shut in: its air is a sinus's";
  // Everything outside the skull is the face's, the 2 mm flap in front included.
  EXPECT_EQ(count_where(labels, result.kept, 0, outside_skull), 0);
  EXPECT_EQ(count_where(labels, result.kept, 1, [](const Eigen::Vector3d& p) { return p.y() < 10; }), 2 * 8 * 20);
  const auto everywhere = [](const Eigen::Vector3d&) { return true; };
  EXPECT_EQ(result.enclosed_voxels + result.loose_voxels, count_where(labels, result.kept, 0, everywhere));
}

TEST(EnclosedTissue, TissueThatOpensWideOntoTheFaceIsTheFaces) {
  // A foramen 16 mm wide is no neck for a 4 mm ball: the tissue behind it reaches the face's
  // skin as the face's own does.
  HeadShape wide;
  wide.foramen_radius = 8;
  const auto labels = synthetic_head(wide);
  const auto result = without_enclosed_tissue(soft_of(labels), labels, kAir, 4);
  EXPECT_EQ(count_where(labels, result.kept, 0, [](const Eigen::Vector3d&) { return true; }), 0);  // nothing left out
  EXPECT_EQ(result.enclosed_voxels + result.loose_voxels, 0);
}

TEST(EnclosedTissue, ASinusDrainingThroughANarrowOstiumIsNotTheAirAroundTheHead) {
  // Without the gap the brain meets no air; with it, the sinus's air. Both leave it out.
  HeadShape closed;
  closed.sinus_gap = false;
  for (const auto& shape : {closed, HeadShape{}}) {
    const auto labels = synthetic_head(shape);
    const auto result = without_enclosed_tissue(soft_of(labels), labels, kAir, 4);
    EXPECT_LT(count_where(labels, result.kept, 1, in_brain), 200) << "sinus gap " << shape.sinus_gap;
  }
}

TEST(EnclosedTissue, AMirroredHeadGivesTheMirroredAnswer) {
  const auto labels = synthetic_head({}), mirrored = synthetic_head({}, true);
  const auto result = without_enclosed_tissue(soft_of(labels), labels, kAir, 4);
  const auto mirrored_result = without_enclosed_tissue(soft_of(mirrored), mirrored, kAir, 4);
  const auto& g = labels.geometry;
  int64_t differ = 0;
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i)
        differ += result.kept.labels[size_t(g.index(i, j, k))] !=
                  mirrored_result.kept.labels[size_t(g.index(g.size.x() - 1 - i, j, k))];
  EXPECT_EQ(differ, 0);
  EXPECT_EQ(result.enclosed_voxels, mirrored_result.enclosed_voxels);
}

TEST(EnclosedTissue, TissueOnAnotherGridIsAnError) {
  const auto labels = synthetic_head({});
  LabelVolume other = soft_of(labels);
  other.geometry.size.x() -= 1;
  other.labels.resize(size_t(other.geometry.voxel_count()));
  EXPECT_THROW(without_enclosed_tissue(other, labels, kAir, 4), Error);
}

}  // namespace
}  // namespace maxillo
