// A case's skin and bone surfaces: traced in a segmentation made earlier they are the surfaces that segmenting again
// gives; stored, they come back from the archive unchanged.
#include <gtest/gtest.h>

#include "casework/phantom_case.h"
#include "casework/surfaces/case_surfaces.h"
#include "casework/surfaces/case_tissues.h"
#include "sample/phantom.h"

namespace maxillo::casework {
namespace {

using testing::TemporaryFolder;

void expect_same_mesh(const TriangleMesh& a, const TriangleMesh& b, const std::string& what) {
  ASSERT_GT(a.face_count(), 1000) << what;
  EXPECT_EQ(a.faces, b.faces) << what;
  EXPECT_EQ(a.vertices, b.vertices) << what;
}

TEST(CaseSurfaces, TracedInTheCaseTissuesLabelsTheyAreTheSurfacesOfANewSegmentation) {
  PhantomSpec spec;
  spec.spacing_mm = 2.0;
  const Phantom phantom = make_phantom(spec);
  const CaseTissues tissues = segment_case_tissues(phantom.ct, phantom.landmarks);
  const SurfaceRecipe recipe;
  const LabelVolume* labels = tissues.ct_labels_for(recipe.segmentation);
  ASSERT_NE(labels, nullptr);
  const CaseSurfaces reused = extract_case_surfaces(phantom.ct, recipe, nullptr, labels);
  const CaseSurfaces fresh = extract_case_surfaces(phantom.ct, recipe);
  expect_same_mesh(reused.skin, fresh.skin, "skin");
  expect_same_mesh(reused.bone, fresh.bone, "bone");
}

TEST(CaseSurfaces, LabelsOfOtherSegmentationOptionsAreNotOffered) {
  PhantomSpec spec;
  spec.spacing_mm = 3.0;
  const CaseTissues tissues = segment_case_tissues(make_phantom(spec).ct, make_phantom_landmarks(spec));
  SegmentationOptions other;
  other.bone_hu = 250;
  EXPECT_EQ(tissues.ct_labels_for(other), nullptr);
  EXPECT_EQ(CaseTissues{}.ct_labels_for(SegmentationOptions{}), nullptr);
}

TEST(CaseSurfaces, StoredOnceTheyComeBackFromTheArchive) {
  TemporaryFolder folder;
  auto [archive, case_id] = testing_support::archived_phantom(folder.path(), 3.0);
  const int64_t series = archive.case_contents(case_id).series.front().series.id;
  EXPECT_FALSE(stored_case_surfaces(archive, case_id, series).has_value());

  const CaseSurfaces first = case_surfaces(archive, case_id, series);
  EXPECT_FALSE(first.reused);
  const auto stored = stored_case_surfaces(archive, case_id, series);
  ASSERT_TRUE(stored.has_value());
  EXPECT_TRUE(stored->reused);
  EXPECT_EQ(stored->key, first.key);
  EXPECT_EQ(stored->skin.faces, first.skin.faces);
  EXPECT_TRUE(stored->skin.vertices.isApprox(first.skin.vertices, 1e-6));
  EXPECT_EQ(stored->bone.faces, first.bone.faces);
}

}  // namespace
}  // namespace maxillo::casework
