// The transfer model: a watertight midface with an open bore along each screw axis.
#include <gtest/gtest.h>

#include "geometry/mesh_measures.h"
#include "planning/osteotomy.h"
#include "casework/plan/transfer_model.h"
#include "sample/phantom.h"

namespace maxillo::casework {
namespace {

struct Fixture {
  Phantom phantom;
  planning::OsteotomyResult cut;
  std::vector<ScrewAxis> screws;
};

const Fixture& fixture() {
  static const Fixture fixture = [] {
    PhantomSpec spec;
    spec.spacing_mm = 1.5;
    spec.noise_sigma_hu = 0;
    Fixture f{make_phantom(spec), {}, {}};
    f.cut = planning::cut_skeleton(f.phantom.labels, planning::default_osteotomies(f.phantom.landmarks, {}));
    // Screws from the anterior maxillary wall backwards through each sinus (x = -/+ 22 mm).
    for (double x : {-22.0, 22.0})
      f.screws.push_back({x < 0 ? "right" : "left", Eigen::Vector3d(x, -58, -18), Eigen::Vector3d(0, 1, 0), 26});
    return f;
  }();
  return fixture;
}

TEST(TransferModel, IsOneWatertightPieceWithPositiveVolume) {
  TransferModelOptions options;
  options.voxel_mm = 0.75;
  auto model = make_transfer_model(fixture().cut.segments, fixture().screws, options);
  EXPECT_TRUE(model.watertight);
  EXPECT_TRUE(is_watertight(model.mesh));
  EXPECT_EQ(connected_components(model.mesh).face_counts.size(), 1u);
  EXPECT_GT(model.volume_ml, 5.0);
}

TEST(TransferModel, TheBoreIsOpenAndTheWallSurroundsIt) {
  TransferModelOptions options;
  options.voxel_mm = 0.5;
  auto model = make_transfer_model(fixture().cut.segments, fixture().screws, options);
  std::vector<Eigen::Vector3d> vertices(size_t(model.mesh.vertex_count()));
  for (size_t v = 0; v < vertices.size(); ++v) vertices[v] = model.mesh.vertices.row(Eigen::Index(v)).transpose();
  for (const auto& screw : fixture().screws) {
    for (double t : {0.0, 8.0, 16.0}) {
      const Eigen::Vector3d axis_point = screw.entry + t * screw.direction;
      // No surface vertex inside the bore (the screw passes), and the bore's wall is near:
      // the closest vertex lies at about the bore radius from the axis.
      double nearest = 1e9;
      for (const auto& p : vertices) nearest = std::min(nearest, (p - axis_point).norm());
      EXPECT_GT(nearest, options.bore_radius_mm - options.voxel_mm) << screw.side << " t=" << t;
      EXPECT_LT(nearest, options.bore_radius_mm + options.voxel_mm) << screw.side << " t=" << t;
    }
  }
}

}  // namespace
}  // namespace maxillo::casework
