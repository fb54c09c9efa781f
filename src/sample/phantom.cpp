#include "sample/phantom.h"

#include <cassert>
#include <cmath>

#include "sample/phantom_landmarks.h"
#include "sample/phantom_voxelize.h"

namespace maxillo {
namespace {

// Field of view (LPS mm): the whole head with a margin, the neck down to C3-C4 level, the
// head rest and the table. x is symmetric so that a voxel column lies on x = 0.
constexpr double kHalfWidthX = 88;
constexpr double kMinY = -112, kMaxY = 150;  // nose tip at y ~ -99, table underside at y ~ 146
constexpr double kMinZ = -135, kMaxZ = 138;  // vertex at z ~ 130

VolumeGeometry phantom_grid(double spacing) {
  VolumeGeometry g;
  g.spacing = Eigen::Vector3d::Constant(spacing);
  g.size =
      Eigen::Vector3i(2 * int(std::floor(kHalfWidthX / spacing)) + 1, int(std::floor((kMaxY - kMinY) / spacing)) + 1,
                      int(std::floor((kMaxZ - kMinZ) / spacing)) + 1);
  g.origin = Eigen::Vector3d(-(g.size.x() - 1) / 2 * spacing, kMinY, kMinZ);
  return g;
}

}  // namespace

std::string_view tissue_name(Tissue tissue) {
  switch (tissue) {
    case Tissue::kAir: return "air";
    case Tissue::kSoftTissue: return "soft tissue";
    case Tissue::kBone: return "bone";
    case Tissue::kUpperTooth: return "upper tooth";
    case Tissue::kSinusAir: return "sinus air";
    case Tissue::kHeadRest: return "head rest";
    case Tissue::kLowerTooth: return "lower tooth";
    case Tissue::kMandible: return "mandible";
    case Tissue::kTable: return "table";
  }
  return "unknown";
}

PhantomSpec phantom_spec_for_class(SkeletalClass skeletal_class) {
  PhantomSpec spec;
  switch (skeletal_class) {
    case SkeletalClass::I: break;
    case SkeletalClass::II: spec.mandibular_protrusion_mm = -5; break;
    case SkeletalClass::III:
      spec.maxillary_advancement_mm = -2;
      spec.mandibular_protrusion_mm = 5;
      break;
  }
  return spec;
}

Phantom make_phantom(const PhantomSpec& spec) {
  assert(spec.spacing_mm >= 0.25 && spec.spacing_mm <= 4 && "phantom spacing must be within [0.25, 4] mm");
  assert(std::abs(spec.mandibular_protrusion_mm) <= 12 && std::abs(spec.maxillary_advancement_mm) <= 12 &&
         "phantom displacements beyond 12 mm are not modelled");
  const sample::PhantomDesign design = sample::make_design(spec);
  const sample::PartList parts = sample::build_phantom_parts(design);
  sample::PaintedGrid grid = sample::paint_parts(parts, phantom_grid(spec.spacing_mm));
  Phantom phantom;
  phantom.ct = sample::compute_ct(grid, spec);
  phantom.labels = LabelVolume{grid.geometry, std::move(grid.tissue)};
  phantom.landmarks = sample::phantom_landmarks(design, parts);
  return phantom;
}

LandmarkSet make_phantom_landmarks(const PhantomSpec& spec) {
  const sample::PhantomDesign design = sample::make_design(spec);
  return sample::phantom_landmarks(design, sample::build_phantom_parts(design));
}

}  // namespace maxillo
