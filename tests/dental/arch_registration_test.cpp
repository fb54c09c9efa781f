// A simulated intraoral scan of a real patient's teeth (openfulljaw-p26-teeth: crowns cut from
// the CBCT-segmented teeth, a gingiva collar, noise, another triangulation) placed back onto the
// teeth with their roots (what the CT shows) from random poses up to 20 mm and 30 degrees away:
// the truth is where the crowns came from. Skipped where the real teeth are absent.
#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <random>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/error.h"
#include "dental/arch_registration.h"
#include "registration_error.h"
#include "geometry/mesh_transform.h"
#include "mesh/mesh_io.h"
#include "mesh/surface_extraction.h"
#include "occlusion/occlusion_benchmark.h"
#include "sample/simulated_dental_scan.h"
#include "sample/teeth_ct.h"

namespace maxillo::dental {
namespace {

std::filesystem::path teeth_folder() { return std::filesystem::path(MAXILLO_SHARED_DATA) / "openfulljaw-p26-teeth"; }

struct RealArches {
  TriangleMesh upper, lower;  // the teeth with their roots, as the CT shows them
  TriangleMesh upper_scan, lower_scan;
};

const RealArches* real_arches() {
  static const std::optional<RealArches> arches = []() -> std::optional<RealArches> {
    const auto folder = teeth_folder();
    if (!std::filesystem::exists(folder / "upper_teeth_merged.stl")) return std::nullopt;
    RealArches a;
    a.upper = read_mesh(folder / "upper_teeth_merged.stl");
    a.lower = read_mesh(folder / "lower_teeth_merged.stl");
    const Eigen::Vector3d between =
        0.5 * (a.upper.vertices.colwise().mean() + a.lower.vertices.colwise().mean()).transpose();
    a.upper_scan = simulated_dental_scan(read_meshes_in(folder / "maxilla"), between);
    a.lower_scan = simulated_dental_scan(read_meshes_in(folder / "mandible"), between, {8.0, 2.0, 0.02, 2});
    return a;
  }();
  return arches ? &*arches : nullptr;
}

TEST(ArchRegistration, AScanOfRealCrownsFindsItsTeethFromFarStarts) {
  const auto* arches = real_arches();
  if (!arches) GTEST_SKIP() << "the real teeth are not at " << teeth_folder();
  std::mt19937 random(7);
  for (const auto& [scan, teeth, name] : {std::tuple{&arches->upper_scan, &arches->upper, "upper"},
                                          std::tuple{&arches->lower_scan, &arches->lower, "lower"}})
    for (int trial = 0; trial < 3; ++trial) {
      const Eigen::Vector3d centre = scan->vertices.colwise().mean().transpose();
      const Eigen::Isometry3d pose = occlusion::random_displacement(random, centre, 20, 30);
      const TriangleMesh scan_moved = transformed(*scan, pose);
      const ArchRegistration r = register_arch(scan_moved, *teeth);
      const double error = pose_distance_mm(scan_moved, r.fit.transform, pose.inverse());
      EXPECT_LT(error, 0.15) << name << " trial " << trial;  // issue 30's target
      // The crowns lie on the teeth (the collar, about a twentieth of the scan, does not), the
      // distances are the scan's noise, and no other pose comes close.
      EXPECT_GT(r.fit.on_teeth_share, 0.9) << name;
      EXPECT_LT(r.fit.rms_mm, 0.05) << name;
      EXPECT_GT(r.fit.within_0_3_share, 0.9) << name;
      EXPECT_GT(r.confidence, 0.3) << name;
      EXPECT_EQ(r.candidates.size(), 8u);
    }
}

using testing::registration_error;

// What a CT shows of both arches (sample/teeth_ct.h: 0.4 mm, alveolar bone, three fillings and
// their streaks), as the surface at the segmentation's teeth threshold.
TEST(ArchRegistration, EachScanFindsItsArchInACtOfBothWithFillingStreaks) {
  const auto* arches = real_arches();
  if (!arches) GTEST_SKIP() << "the real teeth are not at " << teeth_folder();
  SurfaceOptions surface;
  surface.keep_largest_components = 0;
  const TriangleMesh ct_teeth = extract_surface(teeth_ct(arches->upper, arches->lower), 1500, surface);
  std::mt19937 random(3);
  for (const auto& [scan, name] : {std::pair{&arches->upper_scan, "upper"}, std::pair{&arches->lower_scan, "lower"}}) {
    const Eigen::Vector3d centre = scan->vertices.colwise().mean().transpose();
    const Eigen::Isometry3d pose = occlusion::random_displacement(random, centre, 20, 30);
    const TriangleMesh scan_moved = transformed(*scan, pose);
    const ArchRegistration r = register_arch(scan_moved, ct_teeth);
    EXPECT_LT(pose_distance_mm(scan_moved, r.fit.transform, pose.inverse()), 0.15) << name;
    EXPECT_GT(r.fit.on_teeth_share, 0.8) << name;
  }
}

// An upper arch given for the lower one, or a scan in centimetres: the fit is poor and the error
// says so and names the likely causes; nothing is returned as a registration.
TEST(ArchRegistration, TheWrongArchOrAScanInCentimetresIsAnError) {
  const auto* arches = real_arches();
  if (!arches) GTEST_SKIP() << "the real teeth are not at " << teeth_folder();
  const std::string swapped = registration_error(arches->upper_scan, arches->lower);
  EXPECT_NE(swapped.find("it does not fit the CT's teeth"), std::string::npos) << swapped;
  EXPECT_NE(swapped.find("an upper arch given as lower"), std::string::npos) << swapped;
  TriangleMesh centimetres = arches->upper_scan;
  centimetres.vertices *= 0.1;
  const std::string scaled = registration_error(centimetres, arches->upper);
  EXPECT_NE(scaled.find("it does not fit the CT's teeth: at best 0 %"), std::string::npos) << scaled;
}

}  // namespace
}  // namespace maxillo::dental
