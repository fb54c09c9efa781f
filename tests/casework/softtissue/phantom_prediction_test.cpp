// The whole soft tissue prediction on the phantom: a 6 mm Le Fort I advancement moves the upper
// lip and the nose base forward and leaves the forehead and the chin in place.
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <utility>

#include "core/error.h"

#include "mesh/surface_extraction.h"
#include "casework/softtissue/case_simulation.h"
#include "casework/softtissue/soft_tissue_prediction.h"
#include "planning/osteotomy.h"
#include "sample/phantom.h"

namespace maxillo::casework {
namespace {

struct Case {
  Phantom phantom;
  planning::OsteotomyResult cut;
  TriangleMesh skin;
};

const Case& phantom_case() {
  static const Case c = [] {
    PhantomSpec spec;
    spec.spacing_mm = 1.5;
    spec.noise_sigma_hu = 0;
    Case made{make_phantom(spec), {}, {}};
    made.cut = planning::cut_skeleton(made.phantom.labels, planning::default_osteotomies(made.phantom.landmarks, {}));
    SurfaceOptions surface;
    surface.target_triangles = 60000;
    made.skin = extract_surface(made.phantom.ct, -400, surface);
    return made;
  }();
  return c;
}

SoftTissuePrediction predict(softtissue::SoftTissueModel model, double advancement_mm, bool part_lips = false) {
  const auto& c = phantom_case();
  SoftTissueInput input{&c.phantom.labels, &c.cut.segments, &c.skin, c.phantom.landmarks, {}};
  input.moves[uint8_t(planning::Segment::kMaxilla)] = Eigen::Translation3d(0, -advancement_mm, 0);  // anterior = -y
  SoftTissueOptions options;
  options.model = model;
  options.part_lips = part_lips;
  options.meshing.cell_size_mm = 5;
  options.meshing.max_tets = 40000;
  return predict_soft_tissue(input, options);
}

// Anterior displacement (mm) of a soft tissue landmark.
double forward_at(const SoftTissuePrediction& p, const std::string& label) {
  VertexMatrix point(1, 3);
  point.row(0) = find_landmark(phantom_case().phantom.landmarks, label)->transpose();
  return -displacement_at(p, point, 4.0)(0, 1);
}

TEST(PhantomPrediction, AdvancementMovesLipAndNoseBaseButNotForeheadOrChin) {
  auto p = predict(softtissue::SoftTissueModel::kLinearFem, 6);
  EXPECT_LE(p.mesh.tet_count(), 40000);
  EXPECT_EQ(softtissue::count_non_positive_tets(p.mesh), 0);
  EXPECT_GT(p.quality.min_dihedral_deg, 3.0);
  EXPECT_GT(softtissue::count_nodes(p.bc, softtissue::NodeConstraint::kSliding), 50);  // on the moved maxilla
  const double lip = forward_at(p, "Ls"), subnasale = forward_at(p, "Sn");
  EXPECT_GT(lip, 3.0);
  EXPECT_LT(lip, 6.5);  // soft tissue follows the bone by less than 1:1 ... never more
  EXPECT_GT(subnasale, 2.0);
  EXPECT_LT(std::abs(forward_at(p, "NS")), 0.3);  // soft nasion lies above the region
  EXPECT_LT(std::abs(forward_at(p, "PogS")), 1.5);
  EXPECT_GT(p.skin_vertices_bound, 1000);
}

// The phantom's lips are closed: meshed as one block they are tied node to node. Parted at their
// cleft (between Ls and Li), the model gains the copies of the nodes parted, the upper lip follows
// the maxilla as before, and the skin of the two lips is told apart for the gradient.
TEST(PhantomPrediction, TheLipsArePartedAtTheirCleft) {
  const auto parted = predict(softtissue::SoftTissueModel::kLinearFem, 6, true);
  const auto tied = predict(softtissue::SoftTissueModel::kLinearFem, 6);
  ASSERT_TRUE(parted.lips);
  EXPECT_FALSE(tied.lips);
  EXPECT_GT(parted.lips_parted.faces, 20);
  EXPECT_EQ(parted.mesh.node_count(), tied.mesh.node_count() + parted.lips_parted.added_nodes);
  const auto& landmarks = phantom_case().phantom.landmarks;
  const double stomion = parted.lips->stomion.z();
  EXPECT_LT(stomion, find_landmark(landmarks, "Ls")->z());
  EXPECT_GT(stomion, find_landmark(landmarks, "Li")->z());
  EXPECT_NEAR(forward_at(parted, "Ls"), forward_at(tied, "Ls"), 1.0);
  int upper = 0, lower = 0;
  for (int8_t side : parted.skin_lip_side) (side > 0 ? upper : lower) += side != 0;
  EXPECT_GT(upper, 20);
  EXPECT_GT(lower, 20);
}

TEST(PhantomPrediction, ConvergedMassTensorMatchesLinearFem) {
  auto fem = predict(softtissue::SoftTissueModel::kLinearFem, 6);
  auto options = SoftTissueOptions{};
  options.model = softtissue::SoftTissueModel::kMassTensor;
  options.gradient_threshold_mm = 1e-6;
  auto mtm = resolve_soft_tissue(fem, phantom_case().skin, options);
  EXPECT_LT((mtm.node_displacement - fem.node_displacement).rowwise().norm().maxCoeff(), 0.01);
}

// A point-wise model stopped by its sweep limit while points still move is not an answer: the
// prediction is an error naming the model and how far from rest it was, never a face.
TEST(PhantomPrediction, AModelNotAtRestIsAnErrorNotAFace) {
  const auto fem = predict(softtissue::SoftTissueModel::kLinearFem, 6);
  for (auto [model, name] : {std::pair{softtissue::SoftTissueModel::kMassTensor, "mass tensor model"},
                             std::pair{softtissue::SoftTissueModel::kMassSpring, "mass-spring model"}}) {
    SoftTissueOptions options;
    options.model = model;
    options.max_sweeps = 2;
    try {
      resolve_soft_tissue(fem, phantom_case().skin, options);
      ADD_FAILURE() << name << ": no error";
    } catch (const Error& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(name), std::string::npos) << message;
      EXPECT_NE(message.find("did not come to rest: after 2 sweeps"), std::string::npos) << message;
    }
  }
}

// A move the tissue cannot follow without turning a tetrahedron inside out (the maxilla 70 mm
// forward, through the lip) is where the non-linear FEM stops, however short its load steps: the
// linear FEM then predicts the same face model, and the fallback says what was asked for and why.
TEST(PhantomPrediction, ANonlinearFemThatCannotFollowTheMoveFallsBackToTheLinearFem) {
  const auto& c = phantom_case();
  SoftTissueInput input{&c.phantom.labels, &c.cut.segments, &c.skin, c.phantom.landmarks, {}};
  input.moves[uint8_t(planning::Segment::kMaxilla)] = Eigen::Translation3d(0, -70, 0);
  SoftTissueOptions options;
  options.model = softtissue::SoftTissueModel::kNonlinearFem;
  options.meshing.cell_size_mm = 5;
  options.meshing.max_tets = 40000;
  std::optional<records::SimulationSummary::ModelFallback> fallback;
  const auto p = predict_face(input, options, nullptr, fallback);
  EXPECT_EQ(p.model, softtissue::SoftTissueModel::kLinearFem);
  ASSERT_TRUE(fallback);
  EXPECT_EQ(fallback->requested, "nfem");
  EXPECT_NE(fallback->reason.find("Newton's method did not converge: it stopped at"), std::string::npos)
      << fallback->reason;
  EXPECT_NE(fallback->reason.find("of the bone's move"), std::string::npos) << fallback->reason;
}

}  // namespace
}  // namespace maxillo::casework
