// Issue 16: the report's skin and bone surfaces as they are made now (traced on the triangle
// budget's grid, decimated by our quadric edge collapse) against the path they replaced (traced on
// the CT's own grid, decimated by vtkDecimatePro with its topology kept, as maxillo did up to
// 02fb24c), on the same segmentation: the 1 mm phantom and the real cadaver head (skips without
// ../shared/data). Same triangle budget, the same pieces, the topology of the undecimated
// iso-surface, within a fraction of a voxel of the old surfaces, no rougher and with fewer
// needle triangles. The measured figures are printed.
#include <gtest/gtest.h>
#include <vtkDecimatePro.h>
#include <vtkNew.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

#include "imaging/segmentation.h"
#include "imaging/volume_file.h"
#include "geometry/mesh_measures.h"
#include "mesh/mesh_repair.h"
#include "mesh/surface_extraction.h"
#include "mesh/vtk_bridge.h"  // the mesh module's own tests may use its VTK bridge
#include "sample/phantom.h"
#include "validation/distance_statistics.h"

namespace maxillo {
namespace {

// ---- The previous path: native grid, windowed sinc, vtkDecimatePro, repairs. ----

// Euler characteristic V - E + F, summed over the pieces (2 per sphere-like piece, 0 per torus).
int64_t euler_characteristic(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> edges;
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f)
    for (int e = 0; e < 3; ++e) edges[std::minmax(mesh.faces(f, e), mesh.faces(f, (e + 1) % 3))]++;
  return mesh.vertex_count() - int64_t(edges.size()) + mesh.face_count();
}

// What extract_surface did before issue 16 with the same options: the undecimated native-grid
// surface (flying edges, largest pieces, windowed sinc), then vtkDecimatePro as it was set up,
// then the repairs it needed (fins, pinches, the holes they open).
struct PreviousPath {
  TriangleMesh undecimated;  // the native grid's smoothed iso-surface, as both paths start from it here
  TriangleMesh result;
};

PreviousPath previous_surface(const Volume& ct, const LabelVolume& labels, LabelRange region, double iso,
                              SurfaceOptions options) {
  const int64_t budget = options.target_triangles;
  options.grid = SurfaceGrid::Native;
  options.target_triangles = 0;
  PreviousPath path;
  path.undecimated = extract_region_surface(ct, labels, region, iso, options);
  TriangleMesh mesh = path.undecimated;
  if (mesh.face_count() > budget) {
    vtkNew<vtkDecimatePro> decimator;
    decimator->SetInputData(vtk_bridge::to_polydata(mesh));
    decimator->SetTargetReduction(1.0 - double(budget) / double(mesh.face_count()));
    decimator->PreserveTopologyOn();
    decimator->SplittingOff();
    decimator->BoundaryVertexDeletionOff();
    decimator->SetMaximumError(VTK_DOUBLE_MAX);
    decimator->SetFeatureAngle(60);
    decimator->Update();
    mesh = vtk_bridge::from_polydata(decimator->GetOutput());
  }
  int64_t changes = remove_duplicate_faces(mesh);
  for (int round = 0; round < 3 && !is_watertight(mesh); ++round) {
    changes += split_pinched_vertices(mesh);
    changes += close_small_holes(mesh);
  }
  if (changes > 0)
    mesh = keep_largest_components(mesh, options.keep_largest_components, options.min_component_fraction);
  orient_outward(mesh);
  path.result = std::move(mesh);
  return path;
}

// ---- Measures. ----

Eigen::Vector3d face_normal(const TriangleMesh& mesh, Eigen::Index f) {
  const Eigen::Vector3d a = mesh.vertices.row(mesh.faces(f, 0)), b = mesh.vertices.row(mesh.faces(f, 1)),
                        c = mesh.vertices.row(mesh.faces(f, 2));
  return (b - a).cross(c - a).normalized();
}

// Roughness: the mean angle between the normals of two faces sharing an edge, in degrees.
double mean_dihedral_deviation_deg(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, Eigen::Index> first_face;
  double sum = 0;
  int64_t pairs = 0;
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f)
    for (int e = 0; e < 3; ++e) {
      const int a = mesh.faces(f, e), b = mesh.faces(f, (e + 1) % 3);
      const auto [it, inserted] = first_face.emplace(std::minmax(a, b), f);
      if (inserted) continue;
      const double cosine = std::clamp(face_normal(mesh, f).dot(face_normal(mesh, it->second)), -1.0, 1.0);
      sum += std::acos(cosine) * 180.0 / M_PI;
      ++pairs;
    }
  return pairs ? sum / double(pairs) : 0;
}

// Triangle shape: the fraction of triangles with an angle under 10 degrees (needles and slivers).
double needle_fraction(const TriangleMesh& mesh) {
  int64_t needles = 0;
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f) {
    double smallest = 180;
    for (int c = 0; c < 3; ++c) {
      const Eigen::Vector3d p = mesh.vertices.row(mesh.faces(f, c)), q = mesh.vertices.row(mesh.faces(f, (c + 1) % 3)),
                            r = mesh.vertices.row(mesh.faces(f, (c + 2) % 3));
      const double cosine = std::clamp((q - p).normalized().dot((r - p).normalized()), -1.0, 1.0);
      smallest = std::min(smallest, std::acos(cosine) * 180.0 / M_PI);
    }
    needles += smallest < 10;
  }
  return mesh.face_count() ? double(needles) / double(mesh.face_count()) : 0;
}

struct Limits {
  double mean_mm, p95_mm;  // of the distances between the two surfaces, both ways
};

// `now` traced on the same grid as previous.undecimated (the 1 mm phantom and the cadaver need no
// coarser grid for the budget), so its topology must be that surface's: the quadric edge collapse
// keeps it by its link condition. vtkDecimatePro with PreserveTopology did not quite (the cadaver
// lost handles); that is printed, not required.
void expect_no_worse(const TriangleMesh& now, const PreviousPath& previous, const SurfaceOptions& options,
                     const std::string& what, Limits limits) {
  const TriangleMesh& before = previous.result;
  ASSERT_GT(before.face_count(), 1000) << what;
  EXPECT_LE(now.face_count(), int64_t(1.02 * double(options.target_triangles))) << what << ": the same budget";
  EXPECT_GE(now.face_count(), int64_t(0.9 * double(options.target_triangles))) << what << ": the budget is used";
  EXPECT_TRUE(is_watertight(now)) << what;
  EXPECT_EQ(connected_components(now).face_counts.size(), connected_components(before).face_counts.size()) << what;
  EXPECT_EQ(euler_characteristic(now), euler_characteristic(previous.undecimated))
      << what << ": the iso-surface's topology";
  EXPECT_NEAR(signed_volume(now), signed_volume(before), 0.01 * signed_volume(before)) << what;

  const auto forth = validation::distance_statistics(validation::signed_surface_distances(now, before));
  const auto back = validation::distance_statistics(validation::signed_surface_distances(before, now));
  const double rough_now = mean_dihedral_deviation_deg(now), rough_before = mean_dihedral_deviation_deg(before);
  const double needles_now = needle_fraction(now), needles_before = needle_fraction(before);
  std::cout << "[previous path] " << what << ": triangles " << before.face_count() << " -> " << now.face_count()
            << "; pieces " << connected_components(now).face_counts.size() << "; Euler characteristic undecimated "
            << euler_characteristic(previous.undecimated) << ", before " << euler_characteristic(before) << ", now "
            << euler_characteristic(now) << "; now to before: mean |d| " << forth.mean_absolute << " mm, mean "
            << forth.mean_signed << " mm, P5/P95 " << forth.p5 << "/" << forth.p95 << " mm, max " << forth.max_absolute
            << " mm; before to now: mean |d| " << back.mean_absolute << " mm, max " << back.max_absolute
            << " mm; mean dihedral deviation " << rough_before << " -> " << rough_now << " deg; needles (<10 deg) "
            << 100 * needles_before << " -> " << 100 * needles_now << " %\n";
  for (const auto& stats : {forth, back}) {
    EXPECT_LT(stats.mean_absolute, limits.mean_mm) << what;
    EXPECT_LT(std::max(std::abs(stats.p5), std::abs(stats.p95)), limits.p95_mm) << what;
  }
  EXPECT_LT(rough_now, 1.05 * rough_before) << what << ": no rougher";
  EXPECT_LT(needles_now, std::max(needles_before, 0.01)) << what << ": no more needles";
}

// Skin and bone of a CT with the report's recipe (pipeline/case_surfaces.h).
void compare_skin_and_bone(const Volume& ct, const std::string& name, Limits skin_limits, Limits bone_limits,
                           const SegmentationOptions& segmentation = {}) {
  const LabelVolume labels = segment_tissues(ct, segmentation);
  const SurfaceOptions skin{.keep_largest_components = 1, .target_triangles = 150000};
  const SurfaceOptions bone{.keep_largest_components = 8, .min_component_fraction = 0.02, .target_triangles = 200000};
  expect_no_worse(extract_region_surface(ct, labels, {kSoftTissue, kTeeth}, -400, skin),
                  previous_surface(ct, labels, {kSoftTissue, kTeeth}, -400, skin), skin, name + " skin", skin_limits);
  expect_no_worse(extract_region_surface(ct, labels, {kBone, kTeeth}, 300, bone),
                  previous_surface(ct, labels, {kBone, kTeeth}, 300, bone), bone, name + " bone", bone_limits);
}

TEST(PreviousSurfacePath, PhantomSurfacesAreNoWorse) {
  const Phantom phantom = make_phantom(PhantomSpec{});  // 1 mm, the demo's
  compare_skin_and_bone(phantom.ct, "phantom 1 mm", {0.1, 0.25}, {0.1, 0.3});
}

TEST(PreviousSurfacePath, CadaverSurfacesAreNoWorse) {
  const auto slices = std::filesystem::path(MAXILLO_SHARED_DATA) / "cthead-stanford" / "slices";
  if (!std::filesystem::exists(slices / "CThead.113")) GTEST_SKIP() << "real data absent: " << slices;
  const auto header =
      std::filesystem::temp_directory_path() / ("cthead-previous-path-" + std::to_string(getpid()) + ".mhd");
  std::ofstream(header) << "ObjectType = Image\nNDims = 3\nDimSize = 256 256 113\nElementType = MET_USHORT\n"
                           "ElementSpacing = 1.0 1.0 2.0\nElementByteOrderMSB = True\nOffset = 0 0 0\n"
                           "ElementDataFile = "
                        << std::filesystem::absolute(slices).string() << "/CThead.%d 1 113 1\n";
  const Volume ct = read_volume_file(header, {.hu_offset = -1024});
  std::filesystem::remove(header);
  // On the segmentation these limits were measured on, before thin pieces cut off by the opening
  // were put back: with the cadaver's thin-walled nose tip in the skin, the previous path's
  // vtkDecimatePro leaves part of it up to 19.7 mm from the surface (mean |d| 0.133 mm), a
  // failure of the path replaced, not a measure of this one.
  compare_skin_and_bone(ct, "cadaver", {0.1, 0.3}, {0.15, 0.4}, {.max_restored_piece_mm3 = 0});
}

}  // namespace
}  // namespace maxillo
