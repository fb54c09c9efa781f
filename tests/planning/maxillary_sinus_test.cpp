// The maxillary sinus found open to the nose (planning/maxillary_sinus.h), on the phantom whose
// sinuses are opened into its nasal cavity as the cadaver head's are at 2 mm slices: the medial
// wall removed along every row where the nose's air lies beside the sinus, and the sinus air
// labelled as the outside's. The reading must find the same sinus, not the nose beside it.
#include <gtest/gtest.h>

#include <algorithm>

#include "planning/distractor_checks.h"
#include "planning/maxillary_sinus.h"
#include "planning/voxel_components.h"
#include "sample/phantom.h"

namespace maxillo::planning {
namespace {

using Eigen::Vector3d;

constexpr uint8_t kAir = 0, kBone = 2, kSinusAir = 4;
constexpr int kWallVoxels = 4;  // the widest medial wall opened (8 mm at 2 mm voxels)

const Phantom& phantom_at_2mm() {
  static const Phantom p = make_phantom({.spacing_mm = 2.0, .noise_sigma_hu = 0});
  return p;
}

// Along each row (x), from the sinus's most medial voxel towards the midline: the bone between
// it and the nose's air, when no thicker than kWallVoxels, becomes air. Returns the rows opened.
int open_medial_walls(LabelVolume& labels) {
  const VolumeGeometry& g = labels.geometry;
  const double midline = g.world(Vector3d((g.size.x() - 1) / 2.0, 0, 0)).x();
  int opened = 0;
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 1; i + 1 < g.size.x(); ++i) {
        if (labels.labels[g.index(i, j, k)] != kSinusAir) continue;
        const int medial = g.world(Vector3d(i, j, k)).x() > midline ? -1 : 1;
        if (labels.labels[g.index(i + medial, j, k)] == kSinusAir) continue;  // not the sinus's medial edge
        int wall = 0;
        while (wall < kWallVoxels && labels.labels[g.index(i + medial * (wall + 1), j, k)] == kBone) ++wall;
        if (wall == 0 || labels.labels[g.index(i + medial * (wall + 1), j, k)] != kAir) continue;
        for (int w = 1; w <= wall; ++w) labels.labels[g.index(i + medial * w, j, k)] = kAir;
        ++opened;
      }
  return opened;
}

struct OpenSinuses {
  LabelVolume labels;          // sinus air as the outside's, medial walls opened
  std::vector<uint8_t> truth;  // 1 where the phantom's sinus air was
  int rows_opened = 0;
};

const OpenSinuses& open_sinuses() {
  static const OpenSinuses open = [] {
    OpenSinuses o;
    o.labels = phantom_at_2mm().labels;
    o.rows_opened = open_medial_walls(o.labels);
    o.truth.resize(o.labels.labels.size());
    for (size_t v = 0; v < o.labels.labels.size(); ++v) {
      o.truth[v] = phantom_at_2mm().labels.labels[v] == kSinusAir;
      if (o.truth[v]) o.labels.labels[v] = kAir;
    }
    return o;
  }();
  return open;
}

TEST(OpenMaxillarySinus, TheOpenedPhantomsSinusesJoinItsNasalAir) {
  const OpenSinuses& open = open_sinuses();
  EXPECT_GT(open.rows_opened, 20);
  // The test's premise: the sinus air and the nose's are one region of open air now.
  std::vector<uint8_t> air(open.labels.labels.size());
  for (size_t v = 0; v < air.size(); ++v) air[v] = open.labels.labels[v] == kAir;
  const VoxelComponents components = voxel_components(air, open.labels.geometry.size);
  const VolumeGeometry& g = open.labels.geometry;
  const LandmarkSet& marks = phantom_at_2mm().landmarks;
  const Vector3d nose_air = (*find_landmark(marks, "ANS") + *find_landmark(marks, "PNS")) / 2 + Vector3d(6, 0, 6);
  const Vector3d c = g.continuous_index(nose_air);
  const int32_t nose =
      components.id[g.index(int(std::lround(c.x())), int(std::lround(c.y())), int(std::lround(c.z())))];
  ASSERT_NE(nose, 0) << "no air above the palate in the phantom's nose";
  int64_t sinus_voxels_with_the_nose = 0, sinus_voxels = 0;
  for (size_t v = 0; v < air.size(); ++v)
    if (open.truth[v]) ++sinus_voxels, sinus_voxels_with_the_nose += components.id[v] == nose;
  EXPECT_GT(sinus_voxels_with_the_nose, 0.9 * sinus_voxels);
}

TEST(OpenMaxillarySinus, IsFoundWhereTheClosedOneWasAndNotInTheNose) {
  const OpenSinuses& open = open_sinuses();
  const PlanningFrame frame = planning_frame(phantom_at_2mm().landmarks);
  SinusAirReading reading;
  const LabelVolume found = with_open_sinus_air(open.labels, frame, {}, phantom_at_2mm().landmarks, reading);
  ASSERT_EQ(reading.notes.size(), 2u);
  EXPECT_NE(reading.notes[0].find("open to the nasal cavity"), std::string::npos) << reading.notes[0];
  int64_t taken = 0, taken_in_sinus = 0, sinus = 0;
  for (size_t v = 0; v < found.labels.size(); ++v) {
    const bool is_taken = found.labels[v] == kSinusAir;
    taken += is_taken;
    sinus += open.truth[v];
    taken_in_sinus += is_taken && open.truth[v];
  }
  EXPECT_GT(taken_in_sinus, 0.8 * sinus) << taken_in_sinus << " of " << sinus;  // most of each sinus
  EXPECT_GT(taken_in_sinus, 0.9 * taken) << taken_in_sinus << " of " << taken;  // little else
  // The distractors enter where they did through the closed sinuses.
  const EntryPoints closed = find_entry_points(phantom_at_2mm().labels, frame, {}, phantom_at_2mm().landmarks);
  const EntryPoints opened = find_entry_points(found, frame, {}, phantom_at_2mm().landmarks);
  EXPECT_LT((closed.right - opened.right).norm(), 2.0);
  EXPECT_LT((closed.left - opened.left).norm(), 2.0);
}

TEST(OpenMaxillarySinus, ClosedSinusesAreLeftAsTheyAre) {
  SinusAirReading reading;
  const LabelVolume same = with_open_sinus_air(phantom_at_2mm().labels, planning_frame(phantom_at_2mm().landmarks), {},
                                               phantom_at_2mm().landmarks, reading);
  EXPECT_TRUE(reading.notes.empty());
  EXPECT_EQ(same.labels, phantom_at_2mm().labels.labels);
}

TEST(OpenMaxillarySinus, TheNoseAloneIsNoSinus) {
  // No sinus at all (its air filled with bone): neither the nose's air nor the air beside the
  // cheeks is taken for one, and the plan is refused as before.
  LabelVolume no_sinus = phantom_at_2mm().labels;
  std::replace(no_sinus.labels.begin(), no_sinus.labels.end(), kSinusAir, kBone);
  const PlanningFrame frame = planning_frame(phantom_at_2mm().landmarks);
  SinusAirReading reading;
  const LabelVolume found = with_open_sinus_air(no_sinus, frame, {}, phantom_at_2mm().landmarks, reading);
  EXPECT_EQ(std::count(found.labels.begin(), found.labels.end(), kSinusAir), 0);
  EXPECT_TRUE(reading.notes.empty());
}

TEST(OpenMaxillarySinus, WithoutThePalateAndOrbitsNothingIsTaken) {
  const OpenSinuses& open = open_sinuses();
  LandmarkSet without_orbitales;
  for (const auto& l : phantom_at_2mm().landmarks)
    if (!l.label.starts_with("Or")) without_orbitales.push_back(l);
  SinusAirReading reading;
  const LabelVolume same =
      with_open_sinus_air(open.labels, planning_frame(without_orbitales), {}, without_orbitales, reading);
  EXPECT_TRUE(reading.notes.empty());
  EXPECT_EQ(same.labels, open.labels.labels);
}

}  // namespace
}  // namespace maxillo::planning
