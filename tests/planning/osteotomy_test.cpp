// Virtual osteotomies on the phantom: every bone voxel ends up in exactly one segment, the
// segments hold the teeth they should, and cuts that miss the bone are refused.
#include <gtest/gtest.h>

#include <map>

#include "core/error.h"
#include "planning/osteotomy.h"
#include "planning/voxel_components.h"
#include "sample/phantom.h"

namespace maxillo::planning {
namespace {

const Phantom& phantom() {
  static const Phantom p = [] {
    PhantomSpec spec;
    spec.spacing_mm = 1.5;
    spec.noise_sigma_hu = 0;
    return make_phantom(spec);
  }();
  return p;
}

OsteotomyResult cut_all() {
  OsteotomyChoice choice;
  choice.bsso = true;
  choice.genioplasty = true;
  return cut_skeleton(phantom().labels, default_osteotomies(phantom().landmarks, choice));
}

// Voxels per (input tissue, segment) pair.
std::map<std::pair<int, int>, int64_t> cross_counts(const LabelVolume& tissues, const LabelVolume& segments) {
  std::map<std::pair<int, int>, int64_t> counts;
  for (size_t v = 0; v < tissues.labels.size(); ++v) ++counts[{tissues.labels[v], segments.labels[v]}];
  return counts;
}

int64_t count(const std::map<std::pair<int, int>, int64_t>& counts, Tissue tissue, Segment segment) {
  auto it = counts.find({int(tissue), int(segment)});
  return it == counts.end() ? 0 : it->second;
}

TEST(VoxelComponents, SeparatesRegionsThatTouchOnlyAlongAnEdge) {
  // Two 2x2x2 cubes sharing one edge (6-connectivity keeps them apart), and a lone voxel.
  const Eigen::Vector3i size(6, 6, 6);
  std::vector<uint8_t> mask(216, 0);
  auto set = [&](int i, int j, int k) { mask[size_t(i + 6 * (j + 6 * k))] = 1; };
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        set(i, j, k);
        set(i + 2, j + 2, k);
      }
  set(5, 5, 5);
  auto components = voxel_components(mask, size);
  ASSERT_EQ(components.count, 3);
  EXPECT_EQ(components.sizes[1], 8);
  EXPECT_EQ(components.sizes[2], 8);
  EXPECT_EQ(components.sizes[3], 1);
  EXPECT_NE(components.id[0], components.id[size_t(2 + 6 * 2)]);
}

TEST(Osteotomy, EveryBoneVoxelIsInExactlyOneSegment) {
  const auto result = cut_all();
  int64_t bone = 0;
  for (auto label : phantom().labels.labels) {
    auto t = Tissue(label);
    bone += t == Tissue::kBone || t == Tissue::kUpperTooth || t == Tissue::kLowerTooth || t == Tissue::kMandible;
  }
  int64_t segmented = 0, summed = 0;
  for (auto s : result.segments.labels) segmented += s != uint8_t(Segment::kNone);
  for (const auto& s : result.stats) summed += s.voxels;
  EXPECT_EQ(result.input_bone_voxels, bone);
  EXPECT_EQ(segmented, bone);                                 // nothing lost, nothing added
  EXPECT_EQ(summed, bone);                                    // the per-segment volumes add up
  EXPECT_EQ(result.stats.size(), size_t(kSegmentCount - 1));  // all six segments exist
}

TEST(Osteotomy, SegmentsHoldTheirTeethAndNothingElse) {
  const auto result = cut_all();
  const auto counts = cross_counts(phantom().labels, result.segments);
  // Every upper tooth moves with the Le Fort I segment; every lower tooth with the distal mandible.
  EXPECT_EQ(count(counts, Tissue::kUpperTooth, Segment::kCranium), 0);
  EXPECT_GT(count(counts, Tissue::kUpperTooth, Segment::kMaxilla), 0);
  EXPECT_GT(count(counts, Tissue::kLowerTooth, Segment::kMandible), 0);
  for (auto s : {Segment::kRamusRight, Segment::kRamusLeft, Segment::kChin, Segment::kCranium})
    EXPECT_EQ(count(counts, Tissue::kLowerTooth, s), 0) << segment_name(s);
  // The mandible never joins the maxilla or the cranium, and cranial bone never the mandible.
  EXPECT_EQ(count(counts, Tissue::kMandible, Segment::kMaxilla), 0);
  EXPECT_EQ(count(counts, Tissue::kMandible, Segment::kCranium), 0);
  EXPECT_EQ(count(counts, Tissue::kBone, Segment::kMandible), 0);
}

TEST(Osteotomy, MaxillaLiesBelowTheLeFortCutAndInFrontOfTheJunction) {
  const auto& landmarks = phantom().landmarks;
  const auto cuts = default_osteotomies(landmarks, {});
  const auto result = cut_skeleton(phantom().labels, cuts);
  const auto& g = result.segments.geometry;
  int64_t maxilla = 0;
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        if (result.segments.labels[size_t(g.index(i, j, k))] != uint8_t(Segment::kMaxilla)) continue;
        ++maxilla;
        const Eigen::Vector3d p = g.world(Eigen::Vector3d(i, j, k));
        ASSERT_GT(cuts.le_fort_i->side(p), 0);
        ASSERT_GT(cuts.pterygomaxillary->side(p), 0);
      }
  EXPECT_GT(maxilla, 1000);
  // The default cut: parallel to the palatal plane (ANS-PNS nearly level in the phantom), 5 mm above ANS.
  const Eigen::Vector3d ans = *find_landmark(landmarks, "ANS");
  EXPECT_NEAR(cuts.le_fort_i->side(ans), 5.0, 1e-9);
  EXPECT_NEAR(cuts.le_fort_i->side(*find_landmark(landmarks, "PNS")), 5.0, 1e-9);
}

TEST(Osteotomy, AHigherCutMovesBoneFromCraniumToMaxillaOnly) {
  const auto low = cut_skeleton(phantom().labels, default_osteotomies(phantom().landmarks, {}));
  OsteotomyChoice high_choice;
  high_choice.le_fort_variant = LeFortVariant::High;
  const auto high = cut_skeleton(phantom().labels, default_osteotomies(phantom().landmarks, high_choice));
  int64_t gained = 0;
  for (size_t v = 0; v < low.segments.labels.size(); ++v) {
    if (low.segments.labels[v] == high.segments.labels[v]) continue;
    ASSERT_EQ(low.segments.labels[v], uint8_t(Segment::kCranium));
    ASSERT_EQ(high.segments.labels[v], uint8_t(Segment::kMaxilla));
    ++gained;
  }
  EXPECT_GT(gained, 0);
}

TEST(Osteotomy, ACutAboveTheSkullIsRefusedWithItsReason) {
  Osteotomies cuts;
  cuts.le_fort_i = CutPlane{Eigen::Vector3d(0, 0, 400), -Eigen::Vector3d::UnitZ()};
  cuts.le_fort_i->normal = Eigen::Vector3d::UnitZ();  // "below" is now above the head: no teeth there
  try {
    cut_skeleton(phantom().labels, cuts);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kEmptyResult);
    EXPECT_EQ(e.subject(), "Le Fort I");
    EXPECT_NE(e.reason().find("maxilla"), std::string::npos);
  }
}

TEST(Osteotomy, DefaultCutsNameTheMissingLandmark) {
  LandmarkSet only_ans{{"ANS", Eigen::Vector3d(0, -70, -24)}};
  try {
    default_le_fort_i(only_ans, LeFortVariant::Low);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(e.reason().find("PNS"), std::string::npos);
  }
}

TEST(Osteotomy, SegmentNamesRoundTrip) {
  for (int s = 0; s < kSegmentCount; ++s) EXPECT_EQ(parse_segment(segment_name(Segment(s))), Segment(s));
  EXPECT_FALSE(parse_segment("femur"));
}

}  // namespace
}  // namespace maxillo::planning
