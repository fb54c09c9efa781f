// Sliding nodes squeezed between moved and unmoved bone (softtissue/squeezed_nodes.h): a block
// whose floor is held and whose first layer of nodes, 2.5 mm above it, slides on a bone that
// pushes it down. Pushed past the layer's height (or to within a tenth of it) the tets between
// the two layers, with no free corner, flatten or turn inside out whatever the rest does: the
// layer's nodes are freed. A lesser push, a push along the bone, or a free corner keep them.
#include <gtest/gtest.h>

#include "softtissue/cube_mesh.h"
#include "softtissue/squeezed_nodes.h"

namespace maxillo::softtissue {
namespace {

constexpr double kBlockEdge = 10, kLayer = 2.5;  // 4 divisions

struct LayeredBlock {
  TetMesh mesh;
  BoundaryConditions bc;
  int layer_nodes = 0;
};

// The floor held, the first layer sliding on a bone with `normal` that moves by `move`.
LayeredBlock block(const Eigen::Vector3d& normal, const Eigen::Vector3d& move) {
  LayeredBlock b{make_cube_mesh({kBlockEdge, 4, HexSplit::kSixTets}), {}, 0};
  b.bc = all_free(b.mesh.node_count());
  for (int i = 0; i < b.mesh.node_count(); ++i) {
    const double z = b.mesh.nodes(i, 2);
    if (z < 1e-9) b.bc.constraint[size_t(i)] = NodeConstraint::kFixed;
    if (std::abs(z - kLayer) < 1e-9) {
      make_sliding(b.bc, i, normal, move);
      ++b.layer_nodes;
    }
  }
  return b;
}

TEST(SqueezedNodes, ALayerPushedThroughTheHeldFloorIsFreed) {
  for (double press : {3.0, 2.4}) {  // through the floor; to 4 % of the layer's height
    LayeredBlock b = block(Eigen::Vector3d::UnitZ(), Eigen::Vector3d(0, 0, -press));
    EXPECT_EQ(release_squeezed_sliding_nodes(b.mesh, b.bc), b.layer_nodes) << press;
    EXPECT_EQ(count_nodes(b.bc, NodeConstraint::kSliding), 0) << press;
    EXPECT_EQ(count_nodes(b.bc, NodeConstraint::kFixed), 25) << press;  // the floor stays held
    EXPECT_TRUE(b.bc.displacement.isZero()) << press;
  }
}

TEST(SqueezedNodes, ALesserPushOrAPushAlongTheBoneKeepsThemSliding) {
  LayeredBlock pressed = block(Eigen::Vector3d::UnitZ(), Eigen::Vector3d(0, 0, -1.0));  // 60 % of the height left
  EXPECT_EQ(release_squeezed_sliding_nodes(pressed.mesh, pressed.bc), 0);
  EXPECT_EQ(count_nodes(pressed.bc, NodeConstraint::kSliding), pressed.layer_nodes);
  // The bone moves 3 mm down along its own surface (normal x): nothing is imposed across it.
  LayeredBlock along = block(Eigen::Vector3d::UnitX(), Eigen::Vector3d(0, 0, -3.0));
  EXPECT_EQ(release_squeezed_sliding_nodes(along.mesh, along.bc), 0);
}

TEST(SqueezedNodes, TetsWithAFreeCornerOrNoHeldOneAreLeftToTheSolver) {
  // The floor free: nothing holds the layer from below, the tissue gives way.
  LayeredBlock loose = block(Eigen::Vector3d::UnitZ(), Eigen::Vector3d(0, 0, -3.0));
  for (auto& c : loose.bc.constraint)
    if (c == NodeConstraint::kFixed) c = NodeConstraint::kFree;
  EXPECT_EQ(release_squeezed_sliding_nodes(loose.mesh, loose.bc), 0);
  // A floor sliding too (two bones both moving): no tet holds a fixed corner.
  LayeredBlock both = block(Eigen::Vector3d::UnitZ(), Eigen::Vector3d(0, 0, -3.0));
  for (int i = 0; i < both.mesh.node_count(); ++i)
    if (both.bc.constraint[size_t(i)] == NodeConstraint::kFixed)
      make_sliding(both.bc, i, Eigen::Vector3d::UnitZ(), Eigen::Vector3d::Zero());
  EXPECT_EQ(release_squeezed_sliding_nodes(both.mesh, both.bc), 0);
}

}  // namespace
}  // namespace maxillo::softtissue
