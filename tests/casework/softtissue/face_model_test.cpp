// The face's tet model built once for a case (issue 16: the demo meshed the same face three
// times): a prediction from the case's shared model is the prediction that meshes its own, and a
// model built from other inputs is refused, not silently used.
#include <gtest/gtest.h>

#include "casework/phantom_case.h"
#include "casework/softtissue/soft_tissue_prediction.h"

namespace maxillo::casework {
namespace {

using testing::TemporaryFolder;

TEST(FaceModel, ASharedModelGivesTheSamePredictionAndOtherInputsAreRefused) {
  TemporaryFolder folder;
  const PlannedCase planned = testing_support::planned_phantom(folder.path(), 2.0, 6);
  const SoftTissueOptions options;
  const SoftTissueInput input{&planned.tissues.jaws, &planned.cut.segments, &planned.skin, planned.landmarks,
                              planned.planned_moves};

  const auto model = planned.face_model(options);
  EXPECT_EQ(planned.face_model(options), model) << "built once, then shared";
  const SoftTissuePrediction own = predict_soft_tissue(input, options);
  const SoftTissuePrediction shared = predict_soft_tissue(input, options, model.get());
  ASSERT_GT(own.mesh.tets.rows(), 1000);
  EXPECT_EQ(shared.mesh.tets, own.mesh.tets);
  EXPECT_EQ(shared.node_displacement, own.node_displacement);
  EXPECT_EQ(shared.skin_after.vertices, own.skin_after.vertices);
  EXPECT_GT(own.skin_displacement.rowwise().norm().maxCoeff(), 1.0) << "the face moved";
  EXPECT_EQ(shared.seconds.meshing, 0.0) << "nothing meshed";

  SoftTissueOptions coarser = options;
  coarser.meshing.max_tets = 20000;
  EXPECT_NE(planned.face_model(coarser), model);
  EXPECT_THROW(predict_soft_tissue(input, coarser, model.get()), Error);
  LandmarkSet moved = planned.landmarks;  // menton 5 mm lower moves the region's lower plane
  auto menton = std::find_if(moved.begin(), moved.end(), [](const Landmark& l) { return l.label == "Me"; });
  ASSERT_NE(menton, moved.end());
  menton->position.z() -= 5;
  EXPECT_NE(face_model_key(planned.tissues.jaws, moved, options), model->key);
}

}  // namespace
}  // namespace maxillo::casework
