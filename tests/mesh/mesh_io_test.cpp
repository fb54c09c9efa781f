// Mesh files: round trips through every format, and the errors that name the file.
#include "mesh/mesh_io.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "geometry/mesh_measures.h"
#include "mesh/surface_extraction.h"
#include "support/temporary_folder.h"
#include "support/test_shapes.h"

namespace maxillo {
namespace {

TriangleMesh sample_mesh() {
  // A sphere placed at realistic LPS coordinates (far from 0), a few thousand triangles.
  return extract_surface(
      testing::sphere_volume(24, {11.5, 11.5, 11.5}, 8, Eigen::Matrix3d::Identity(), {-90.25, 120.5, -310}), 0,
      {.smoothing_iterations = 5});
}

class MeshRoundTrip : public ::testing::TestWithParam<const char*> {};

TEST_P(MeshRoundTrip, GivesBackTheSameTriangles) {
  TemporaryFolder folder("mesh-io");
  const TriangleMesh mesh = sample_mesh();
  const auto path = folder / (std::string("surface.") + GetParam());
  write_mesh(mesh, path);
  const TriangleMesh back = read_mesh(path);
  ASSERT_EQ(back.face_count(), mesh.face_count());
  ASSERT_EQ(back.vertex_count(), mesh.vertex_count());
  // STL stores 32-bit floats: ~1e-5 mm at 300 mm; the other formats keep at least that.
  EXPECT_LT((back.vertices - mesh.vertices).cwiseAbs().maxCoeff(), 1e-4);
  EXPECT_EQ(back.faces, mesh.faces);
  EXPECT_NEAR(signed_volume(back), signed_volume(mesh), 1e-3);
  EXPECT_TRUE(is_watertight(back));
}

INSTANTIATE_TEST_SUITE_P(Formats, MeshRoundTrip, ::testing::Values("stl", "ply", "obj", "vtp", "STL"));

ErrorCode code_of(auto action, const std::filesystem::path& path) {
  try {
    action();
  } catch (const Error& e) {
    EXPECT_EQ(e.subject(), path.string());
    return e.code();
  }
  ADD_FAILURE() << path << ": no error";
  return ErrorCode::kProcessing;
}

TEST(MeshIo, ErrorsNameTheFile) {
  TemporaryFolder folder("mesh-io-errors");
  const TriangleMesh mesh = testing::cube(1);
  const auto unknown = folder / "surface.off";
  EXPECT_EQ(code_of([&] { write_mesh(mesh, unknown); }, unknown), ErrorCode::kUsage);
  EXPECT_EQ(code_of([&] { read_mesh(unknown); }, unknown), ErrorCode::kUsage);
  const auto nowhere = folder / "no-such-folder" / "surface.stl";
  EXPECT_EQ(code_of([&] { write_mesh(mesh, nowhere); }, nowhere), ErrorCode::kWriteFailed);
  const auto absent = folder / "absent.ply";
  EXPECT_EQ(code_of([&] { read_mesh(absent); }, absent), ErrorCode::kFileNotFound);
  const auto garbage = folder / "garbage.vtp";
  std::ofstream(garbage) << "this is not XML";
  EXPECT_EQ(code_of([&] { read_mesh(garbage); }, garbage), ErrorCode::kBadValue);
  EXPECT_TRUE(std::filesystem::is_empty(folder / ".") || !std::filesystem::exists(folder / "surface.off"));
}

// One tooth per file: the folder's meshes come in the order of their names, whatever the file
// system's order, and files that are no mesh are left alone.
TEST(MeshIo, AFoldersMeshesComeInTheOrderOfTheirNames) {
  TemporaryFolder folder("mesh-io-folder");
  write_mesh(testing::cube(3), folder / "tooth_2.stl");
  write_mesh(testing::cube(1), folder / "tooth_10.ply");
  write_mesh(testing::cube(2), folder / "tooth_1.obj");
  std::ofstream(folder / "axes.json") << "{}";
  const auto meshes = read_meshes_in(folder.path());
  ASSERT_EQ(meshes.size(), 3u);
  EXPECT_NEAR(signed_volume(meshes[0]), 8, 1e-4);   // tooth_1
  EXPECT_NEAR(signed_volume(meshes[1]), 1, 1e-4);   // tooth_10
  EXPECT_NEAR(signed_volume(meshes[2]), 27, 1e-4);  // tooth_2
  const auto absent = folder / "no-such-folder";
  EXPECT_EQ(code_of([&] { read_meshes_in(absent); }, absent), ErrorCode::kFileNotFound);
}

}  // namespace
}  // namespace maxillo
