#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/temporary_folder.h"
#include "softtissue/cube_benchmark.h"
#include "softtissue/vtu_writer.h"

namespace maxillo::softtissue {
namespace {

TEST(VtuWriter, WritesMeshDisplacementAndConditions) {
  CubeSpec spec{30.0, 3, HexSplit::kSixTets};
  TetMesh mesh = make_cube_mesh(spec);
  BoundaryConditions bc = cube_benchmark_conditions(mesh, spec, {6.0, 10.0});
  Eigen::MatrixX3d u = initial_displacement(bc);
  TemporaryFolder folder;
  auto path = folder.path() / "cube.vtu";
  write_vtu(path, mesh, u, bc);
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string xml = text.str();
  EXPECT_NE(xml.find("NumberOfPoints=\"64\" NumberOfCells=\"162\""), std::string::npos);
  EXPECT_NE(xml.find("Name=\"displacement\" NumberOfComponents=\"3\""), std::string::npos);
  EXPECT_NE(xml.find("Name=\"bc\""), std::string::npos);
  EXPECT_NE(xml.find("</VTKFile>"), std::string::npos);
  // bc array: 56 border nodes fixed (1), 8 centre nodes prescribed (2), none free.
  size_t begin = xml.find("Name=\"bc\" format=\"ascii\">\n") + 26, end = xml.find("</DataArray>", begin);
  std::istringstream values(xml.substr(begin, end - begin));
  int value = 0, fixed = 0, prescribed = 0;
  while (values >> value) (value == 1 ? fixed : prescribed) += 1;
  EXPECT_EQ(fixed, 56);
  EXPECT_EQ(prescribed, 8);
}

TEST(VtuWriter, UnwritableFolderThrowsNamingThePath) {
  TetMesh mesh = make_cube_mesh({1.0, 1, HexSplit::kSixTets});
  BoundaryConditions bc = all_free(mesh.node_count());
  EXPECT_THROW(write_vtu("/nonexistent-folder/x.vtu", mesh, bc.displacement, bc), Error);
}

}  // namespace
}  // namespace maxillo::softtissue
