// The pieces that turn a CT into a face model: the region, the join points, and the two
// mappings from the tet mesh to the skin.
#include <gtest/gtest.h>

#include "geometry/mesh_measures.h"
#include "softtissue/bone_attachment.h"
#include "softtissue/boundary_move.h"
#include "softtissue/cube_mesh.h"
#include "softtissue/face_region.h"
#include "softtissue/gaussian_mapping.h"
#include "softtissue/shape_function_mapping.h"
#include "softtissue/tet_boundary.h"

namespace maxillo::softtissue {
namespace {

TetMesh cube(double side, int divisions) { return make_cube_mesh({side, divisions, HexSplit::kSixTets}); }

// A linear displacement field u(x) = A x + b.
struct LinearField {
  Eigen::Matrix3d a;
  Eigen::Vector3d b;
  Eigen::Vector3d at(const Eigen::Vector3d& x) const { return a * x + b; }
  Eigen::MatrixX3d on_nodes(const TetMesh& mesh) const {
    Eigen::MatrixX3d u(mesh.node_count(), 3);
    for (int n = 0; n < mesh.node_count(); ++n) u.row(n) = at(mesh.nodes.row(n).transpose()).transpose();
    return u;
  }
};
const LinearField kField{(Eigen::Matrix3d() << 0.01, 0.02, 0, -0.03, 0.005, 0.01, 0.02, 0, -0.01).finished(),
                         Eigen::Vector3d(1, -2, 0.5)};

TEST(TetBoundary, IsTheClosedOutwardSurfaceOfTheCube) {
  const auto mesh = cube(30, 4);
  const auto boundary = tet_boundary(mesh);
  EXPECT_EQ(boundary.surface.face_count(), 6 * 2 * 4 * 4);
  EXPECT_TRUE(is_watertight(boundary.surface));
  EXPECT_NEAR(maxillo::signed_volume(boundary.surface), 30.0 * 30 * 30, 1e-6);
  EXPECT_EQ(boundary.nodes.size(), size_t(5 * 5 * 5 - 3 * 3 * 3));
}

TEST(ShapeFunctionMapping, ReproducesALinearFieldInsideAndFollowsTheSurfaceOutside) {
  const auto mesh = cube(30, 4);
  VertexMatrix points(4, 3);
  points << 3, 4, 5,  // inside
      15, 15, 15,     // centre
      -1, 10, 10,     // 1 mm outside a face: takes the value at its projection (0, 10, 10)
      10, 10, 45;     // 15 mm away: beyond max distance
  auto mapping = init_shape_function_mapping(mesh, points, 2.0);
  EXPECT_EQ(mapping.bound_count(), 3);
  auto u = map_displacement(mesh, mapping, kField.on_nodes(mesh));
  for (int i = 0; i < 2; ++i)
    EXPECT_LT((u.row(i).transpose() - kField.at(points.row(i).transpose())).norm(), 1e-9) << i;
  EXPECT_LT((u.row(2).transpose() - kField.at(Eigen::Vector3d(0, 10, 10))).norm(), 1e-9);
  EXPECT_EQ(u.row(3).norm(), 0.0);
  for (size_t i = 0; i < 3; ++i) EXPECT_NEAR(mapping.weights[i].sum(), 1.0, 1e-12);  // partition of unity
}

TEST(GaussianMapping, ReproducesAConstantFieldAndIsCloseForALinearOne) {
  const auto mesh = cube(30, 6);
  // The skin: the cube's own surface (every skin vertex is a matched node).
  const auto skin = tet_boundary(mesh).surface;
  GaussianMappingOptions options;
  options.radius_mm = 6;  // the node spacing is 5 mm
  auto mapping = init_gaussian_mapping(mesh, skin, options);
  const int on_surface = int(tet_boundary(mesh).nodes.size());
  EXPECT_EQ(mapping.bound_count, on_surface);
  Eigen::MatrixX3d constant = Eigen::MatrixX3d::Zero(mesh.node_count(), 3);
  constant.rowwise() = Eigen::RowVector3d(1.5, -0.5, 2);
  auto u = map_displacement(mapping, constant);
  // Skin vertices that are tet nodes (all boundary nodes) get the constant exactly.
  for (int n : tet_boundary(mesh).nodes) EXPECT_LT((u.row(n) - Eigen::RowVector3d(1.5, -0.5, 2)).norm(), 1e-12);
  // A linear field: a matched vertex is dominated by its own weight (1 / 1e-6 mm).
  auto v = map_displacement(mapping, kField.on_nodes(mesh));
  for (int n : tet_boundary(mesh).nodes)
    EXPECT_LT((v.row(n).transpose() - kField.at(mesh.nodes.row(n).transpose())).norm(), 1e-4);
}

TEST(FaceRegion, KeepsSoftTissueOnTheKeptSideOfEveryPlane) {
  LabelVolume tissues;
  tissues.geometry.size = {10, 10, 10};
  tissues.labels.assign(1000, 1);
  for (int i = 0; i < 100; ++i) tissues.labels[size_t(i)] = 2;                              // slice k = 0 is bone
  std::vector<RegionPlane> planes{{Eigen::Vector3d(0, 0, 6.5), -Eigen::Vector3d::UnitZ()},  // keep z < 6.5
                                  {Eigen::Vector3d(2.5, 0, 0), Eigen::Vector3d::UnitX()}};  // keep x > 2.5
  auto region = face_region(tissues, {1}, planes);
  int64_t kept = 0;
  for (auto v : region.labels) kept += v;
  EXPECT_EQ(kept, 6 /* k = 1..6 */ * 10 * 7 /* i = 3..9 */);
}

// Two pieces stacked as the default face region's are: A below z = 10, B above it up to z = 20
// but only where x < 5 (the nose's root above the orbits). Together one region; where they
// meet no tissue is cut.
RegionShape stacked_pieces() {
  return RegionShape(
      std::vector<std::vector<RegionPlane>>{{{Eigen::Vector3d(0, 0, 10), -Eigen::Vector3d::UnitZ()}},   // A: z < 10
                                            {{Eigen::Vector3d(0, 0, 10), Eigen::Vector3d::UnitZ()},     // B: z > 10,
                                             {Eigen::Vector3d(0, 0, 20), -Eigen::Vector3d::UnitZ()},    //    z < 20,
                                             {Eigen::Vector3d(5, 0, 0), -Eigen::Vector3d::UnitX()}}});  //    x < 5
}

TEST(FaceRegion, TwoPiecesAreOneRegionCutOnlyWhereTissueGoesOn) {
  const RegionShape shape = stacked_pieces();
  EXPECT_TRUE(shape.contains({2, 0, 5}));
  EXPECT_TRUE(shape.contains({2, 0, 15}));
  EXPECT_FALSE(shape.contains({8, 0, 15})) << "above A, beside B";
  EXPECT_FALSE(shape.contains({2, 0, 25}));
  EXPECT_EQ(shape.planes().size(), 4u);

  EXPECT_FALSE(shape.on_cut({2, 0, 10}, 1)) << "where A and B meet";
  EXPECT_TRUE(shape.on_cut({8, 0, 10}, 1)) << "A's top beside B";
  EXPECT_TRUE(shape.on_cut({2, 0, 19.5}, 1)) << "B's top";
  EXPECT_TRUE(shape.on_cut({5, 0, 15}, 1)) << "B's side";
  EXPECT_FALSE(shape.on_cut({5, 0, 5}, 1)) << "B's side plane runs on inside A";
  EXPECT_FALSE(shape.on_cut({2, 0, 15}, 1));

  // The voxel mask: a 10 x 1 x 30 grid of soft tissue, 1 mm voxels at x = 0..9, z = 0..29.
  LabelVolume tissues;
  tissues.geometry.size = {10, 1, 30};
  tissues.labels.assign(300, 1);
  int64_t kept = 0;
  for (auto v : face_region(tissues, {1}, shape).labels) kept += v;
  EXPECT_EQ(kept, 10 * 10 /* A: z = 0..9 */ + 5 * 9 /* B: x = 0..4, z = 11..19 */);
}

TEST(BoneAttachment, JoinsNodesToTheBoneTheyTouchAndFixesCutPlanes) {
  // Tet mesh: the cube [0, 20]^3. Bone: a slab of voxels at z = -1 (below the cube), split in
  // two segments at x = 10; segment 2 moves 3 mm along y, segment 1 stays. Cut plane: x = 20.
  const auto mesh = cube(20, 4);
  LabelVolume segments;
  segments.geometry.size = {23, 23, 23};
  segments.geometry.origin = Eigen::Vector3d(-1, -1, -1);
  segments.labels.assign(size_t(segments.geometry.voxel_count()), 0);
  for (int j = 0; j < 23; ++j)
    for (int i = 0; i < 23; ++i) segments.labels[size_t(segments.geometry.index(i, j, 0))] = (i - 1) < 10 ? 1 : 2;
  const Eigen::Isometry3d move(Eigen::Translation3d(0, 3, 0));
  std::vector<RegionPlane> cuts{{Eigen::Vector3d(20, 0, 0), -Eigen::Vector3d::UnitX()}};
  AttachmentOptions tied{1.2, 0.5};
  tied.moved_bone_contact = MovedBoneContact::kTied;  // the thesis' join points
  auto attachment = attach_to_bone(mesh, segments, {{uint8_t(2), move}}, cuts, tied);
  for (int n = 0; n < mesh.node_count(); ++n) {
    const Eigen::Vector3d p = mesh.nodes.row(n).transpose();
    const auto c = attachment.bc.constraint[size_t(n)];
    if (p.z() < 0.5 && p.x() > 10.5) {
      EXPECT_EQ(c, NodeConstraint::kPrescribed) << p.transpose();
      EXPECT_LT((attachment.bc.imposed(n) - Eigen::Vector3d(0, 3, 0)).norm(), 1e-12);
    } else if (p.z() < 0.5 && p.x() < 9.5) {
      EXPECT_EQ(c, NodeConstraint::kFixed) << p.transpose();
    } else if (p.z() > 0.5 && p.x() > 19.5) {
      EXPECT_EQ(c, NodeConstraint::kFixed) << "cut plane " << p.transpose();
    } else if (p.z() > 0.5) {
      EXPECT_EQ(c, NodeConstraint::kFree) << p.transpose();
    }
  }
}

// A 1 mm bone grid, 60 mm a side, origin at 0: labels set by `bone(i, j, k)` (segment 2).
template <typename Bone>
LabelVolume bone_volume(Bone bone) {
  LabelVolume segments;
  segments.geometry.size = {60, 60, 60};
  segments.labels.assign(size_t(segments.geometry.voxel_count()), 0);
  for (int k = 0; k < 60; ++k)
    for (int j = 0; j < 60; ++j)
      for (int i = 0; i < 60; ++i)
        if (bone(i, j, k)) segments.labels[size_t(segments.geometry.index(i, j, k))] = 2;
  return segments;
}

TEST(BoneCavity, InsideAClosedBoxButNotOnItsOuterFace) {
  // A hollow box [10, 50]^3 with 2 mm walls: a sinus.
  const auto box = bone_volume([](int i, int j, int k) {
    const bool in_outer = i >= 10 && i <= 50 && j >= 10 && j <= 50 && k >= 10 && k <= 50;
    const bool in_hollow = i >= 12 && i <= 48 && j >= 12 && j <= 48 && k >= 12 && k <= 48;
    return in_outer && !in_hollow;
  });
  EXPECT_TRUE(inside_bone_cavity(box, {30, 30, 13}, {}));  // on the floor, inside
  EXPECT_TRUE(inside_bone_cavity(box, {13, 30, 30}, {}));  // on a side wall, inside
  EXPECT_FALSE(inside_bone_cavity(box, {30, 30, 9}, {}));  // under the floor, outside
  EXPECT_FALSE(inside_bone_cavity(box, {30, 9, 30}, {}));  // in front of a wall, outside
  // A tray (the box's floor with a 10 mm rim, open at the top) is no cavity for a node on its
  // floor: its rays leave upwards.
  const auto tray = bone_volume([](int i, int j, int k) {
    const bool in_outer = i >= 10 && i <= 50 && j >= 10 && j <= 50 && k >= 10 && k <= 20;
    const bool in_hollow = i >= 12 && i <= 48 && j >= 12 && j <= 48 && k >= 12;
    return in_outer && !in_hollow;
  });
  EXPECT_FALSE(inside_bone_cavity(tray, {30, 30, 13}, {}));
}

TEST(BoneAttachment, MovedBoneCarriesOnlyItsOuterSurface) {
  // The hollow box of bone (segment 2, moved) with a tet cube inside its cavity and one outside.
  const auto box = bone_volume([](int i, int j, int k) {
    const bool in_outer = i >= 10 && i <= 50 && j >= 10 && j <= 50 && k >= 10 && k <= 50;
    const bool in_hollow = i >= 12 && i <= 48 && j >= 12 && j <= 48 && k >= 12 && k <= 48;
    return in_outer && !in_hollow;
  });
  const Eigen::Isometry3d move(Eigen::Translation3d(0, 3, 0));
  auto inner = cube(8, 2);
  inner.nodes.rowwise() += Eigen::RowVector3d(26, 26, 12.2);  // its 9 bottom nodes 1.2 mm above the floor
  // A cut plane through its top holds it, as the face holds the lining of a real cavity.
  const std::vector<RegionPlane> top{{Eigen::Vector3d(0, 0, 20.2), -Eigen::Vector3d::UnitZ()}};
  AttachmentOptions outer_only;
  outer_only.outer_surface_only = true;
  auto attached = attach_to_bone(inner, box, {{uint8_t(2), move}}, top, outer_only);
  EXPECT_EQ(count_nodes(attached.bc, NodeConstraint::kPrescribed), 0);
  EXPECT_EQ(count_nodes(attached.bc, NodeConstraint::kFixed), 9);
  EXPECT_EQ(attached.inner_nodes, 9);
  // Held by nothing else, the piece would float: it follows its bone after all.
  attached = attach_to_bone(inner, box, {{uint8_t(2), move}}, {}, outer_only);
  EXPECT_EQ(count_nodes(attached.bc, NodeConstraint::kPrescribed), 9);
  EXPECT_EQ(attached.inner_nodes, 0);
  // Without the rule the floor's nodes follow the bone; unmoved bone holds them either way.
  AttachmentOptions tie_all;
  tie_all.outer_surface_only = false;
  tie_all.moved_bone_contact = MovedBoneContact::kTied;
  attached = attach_to_bone(inner, box, {{uint8_t(2), move}}, {}, tie_all);
  EXPECT_EQ(count_nodes(attached.bc, NodeConstraint::kPrescribed), 9);
  attached = attach_to_bone(inner, box, {}, {}, outer_only);
  EXPECT_EQ(count_nodes(attached.bc, NodeConstraint::kFixed), 9);

  auto outer = cube(8, 2);
  outer.nodes.rowwise() += Eigen::RowVector3d(26, 26, 51.2);  // its bottom 1.2 mm above the box's top
  attached = attach_to_bone(outer, box, {{uint8_t(2), move}}, {}, outer_only);
  EXPECT_EQ(count_nodes(attached.bc, NodeConstraint::kPrescribed), 9);
  EXPECT_EQ(attached.inner_nodes, 0);
}

TEST(BoneAttachment, TissueOnMovedBoneSlidesAlongItsOutwardNormal) {
  // A block of bone (segment 2, moved sideways and up) under a tet cube whose bottom lies 1.2 mm
  // above it; a cut plane through the cube's top holds it.
  const auto slab =
      bone_volume([](int i, int j, int k) { return i >= 10 && i <= 50 && j >= 10 && j <= 50 && k <= 50; });
  const Eigen::Isometry3d move(Eigen::Translation3d(0, 3, 1));
  auto tissue = cube(8, 2);
  tissue.nodes.rowwise() += Eigen::RowVector3d(26, 26, 51.2);
  const std::vector<RegionPlane> top{{Eigen::Vector3d(0, 0, 59.2), -Eigen::Vector3d::UnitZ()}};
  AttachmentOptions sliding;
  sliding.moved_bone_contact = MovedBoneContact::kSliding;
  auto attached = attach_to_bone(tissue, slab, {{uint8_t(2), move}}, top, sliding);
  EXPECT_EQ(count_nodes(attached.bc, NodeConstraint::kSliding), 9);
  EXPECT_EQ(count_nodes(attached.bc, NodeConstraint::kPrescribed), 0);
  for (int i = 0; i < tissue.node_count(); ++i) {
    if (attached.bc.constraint[size_t(i)] != NodeConstraint::kSliding) continue;
    EXPECT_GT(attached.bc.normal.row(i).dot(Eigen::RowVector3d::UnitZ()), std::cos(M_PI / 180)) << i;
    EXPECT_NEAR(attached.bc.imposed(i).z(), 1.0, 1e-9);  // pushed up, not carried sideways
    EXPECT_NEAR(attached.bc.imposed(i).y(), 0.0, 1e-9);
    EXPECT_EQ(attached.segment[size_t(i)], 2);
  }
  // Nothing else holding it, the block would slide off: it follows its bone after all.
  attached = attach_to_bone(tissue, slab, {{uint8_t(2), move}}, {}, sliding);
  EXPECT_EQ(count_nodes(attached.bc, NodeConstraint::kSliding), 0);
  EXPECT_EQ(count_nodes(attached.bc, NodeConstraint::kPrescribed), 9);
  // Unmoved bone holds its tissue either way.
  attached = attach_to_bone(tissue, slab, {}, top, sliding);
  EXPECT_EQ(count_nodes(attached.bc, NodeConstraint::kFixed), 9 + 9);
}

TEST(BoneAttachment, TissueTheMovedBoneDoesNotCarryIsLeftFreeOnItAndHeldByUnmovedBone) {
  // The slab of bone and the tet cube above it of the test before; the three bottom nodes at
  // x = 26 are tissue the bone does not carry (as the cartilaginous nose on the maxilla).
  const auto slab =
      bone_volume([](int i, int j, int k) { return i >= 10 && i <= 50 && j >= 10 && j <= 50 && k <= 50; });
  const Eigen::Isometry3d move(Eigen::Translation3d(0, 3, 1));
  auto tissue = cube(8, 2);
  tissue.nodes.rowwise() += Eigen::RowVector3d(26, 26, 51.2);
  std::vector<uint8_t> not_carried(size_t(tissue.node_count()), 0);
  for (int i = 0; i < tissue.node_count(); ++i) not_carried[size_t(i)] = tissue.nodes(i, 0) < 27 ? 1 : 0;
  const std::vector<RegionPlane> top{{Eigen::Vector3d(0, 0, 59.2), -Eigen::Vector3d::UnitZ()}};
  const AttachmentOptions sliding;
  auto attached = attach_to_bone(tissue, slab, {{uint8_t(2), move}}, top, sliding, not_carried);
  EXPECT_EQ(attached.uncarried_nodes, 3);
  EXPECT_EQ(count_nodes(attached.bc, NodeConstraint::kSliding), 6);
  for (int i = 0; i < tissue.node_count(); ++i) {
    if (!not_carried[size_t(i)] || tissue.nodes(i, 2) > 52) continue;
    EXPECT_EQ(attached.bc.constraint[size_t(i)], NodeConstraint::kFree) << i;
    EXPECT_EQ(attached.segment[size_t(i)], 0) << i;
  }
  // Unmoved, the bone holds every node on it, carried or not.
  attached = attach_to_bone(tissue, slab, {}, top, sliding, not_carried);
  EXPECT_EQ(count_nodes(attached.bc, NodeConstraint::kFixed), 9 + 9);
  EXPECT_EQ(attached.uncarried_nodes, 0);
  // With nothing else holding the block, its loose nodes follow the bone after all.
  attached = attach_to_bone(tissue, slab, {{uint8_t(2), move}}, {}, sliding, not_carried);
  EXPECT_EQ(count_nodes(attached.bc, NodeConstraint::kPrescribed), 9);
  EXPECT_EQ(attached.uncarried_nodes, 0);
}

TEST(BoundaryMove, LargestMoveWithinTheBandInsideEachPlane) {
  // The cube [0, 20]^3 (nodes every 5 mm) moving by u = (0, 0.1 x, 0): at the plane x = 20
  // (kept side x < 20) the band of 5 mm holds the nodes at x = 15 and 20, so 2 mm; at x = 0
  // (kept side x > 0) those at x = 0 and 5, so 0.5 mm; a plane beyond the cube sees none.
  const auto mesh = cube(20, 4);
  Eigen::MatrixX3d u = Eigen::MatrixX3d::Zero(mesh.node_count(), 3);
  u.col(1) = 0.1 * mesh.nodes.col(0);
  const std::vector<RegionPlane> planes{{Eigen::Vector3d(20, 0, 0), -Eigen::Vector3d::UnitX()},
                                        {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d::UnitX()},
                                        {Eigen::Vector3d(0, 0, 40), -Eigen::Vector3d::UnitZ()}};
  const auto largest = largest_move_near_planes(mesh, u, planes, 5);
  ASSERT_EQ(largest.size(), 3u);
  EXPECT_NEAR(largest[0], 2.0, 1e-12);
  EXPECT_NEAR(largest[1], 0.5, 1e-12);
  EXPECT_EQ(largest[2], 0.0);
  EXPECT_NEAR(largest_move_near_planes(mesh, u, planes, 2)[0], 2.0, 1e-12);  // x = 20 only
}

TEST(BoundaryMove, AFaceWherePiecesMeetIsNoBoundary) {
  // The cube [0, 20]^3 (nodes 1 mm apart) in two pieces side by side, A at x < 10 and B at
  // x > 10; u_y = 0.1 x.
  const auto mesh = cube(20, 20);
  Eigen::MatrixX3d u = Eigen::MatrixX3d::Zero(mesh.node_count(), 3);
  u.col(1) = 0.1 * mesh.nodes.col(0);
  const RegionShape shape(std::vector<std::vector<RegionPlane>>{
      {{Eigen::Vector3d(10, 0, 0), -Eigen::Vector3d::UnitX()}, {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d::UnitX()}},
      {{Eigen::Vector3d(10, 0, 0), Eigen::Vector3d::UnitX()}, {Eigen::Vector3d(20, 0, 0), -Eigen::Vector3d::UnitX()}}});
  const auto largest = largest_move_near_planes(mesh, u, shape, 5);
  ASSERT_EQ(largest.size(), 4u);
  EXPECT_EQ(largest[0], 0.0) << "A's face at x = 10 lies against B";
  EXPECT_NEAR(largest[1], 0.5, 1e-12);
  EXPECT_EQ(largest[2], 0.0) << "B's face at x = 10 lies against A";
  EXPECT_NEAR(largest[3], 2.0, 1e-12);
}

}  // namespace
}  // namespace maxillo::softtissue
