#include "sample/phantom.h"

#include <cassert>
#include <cmath>

#include "sample/phantom_cone_beam.h"
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

// The designed field of view as it lies in the scanner: the bounding box of the placed box.
VolumeGeometry placed_grid(double spacing, const PhantomPlacement& placement) {
  if (placement.is_identity()) return phantom_grid(spacing);
  const VolumeGeometry designed = phantom_grid(spacing);
  const Eigen::Vector3d far = designed.world(designed.size.cast<double>() - Eigen::Vector3d::Ones());
  const sample::Box box = sample::placed_box(placement, {designed.origin, far});
  const Eigen::Vector3d lo = box.lo, hi = box.hi;
  VolumeGeometry g;
  g.spacing = Eigen::Vector3d::Constant(spacing);
  for (int axis = 0; axis < 3; ++axis) g.size[axis] = int(std::floor((hi[axis] - lo[axis]) / spacing)) + 1;
  g.origin = lo;
  return g;
}

VolumeGeometry scanned_grid(const PhantomSpec& spec) {
  return spec.cone_beam ? sample::cone_beam_grid(*spec.cone_beam, spec.spacing_mm)
                        : placed_grid(spec.spacing_mm, spec.placement);
}

// The designed head's parts (and a cone-beam scan's fillings) as they lie in the scanner.
sample::PartList scanned_parts(const sample::PhantomDesign& design, sample::PartList parts, const PhantomSpec& spec) {
  if (spec.cone_beam && spec.cone_beam->metal_fillings) sample::add_amalgam_fillings(design, parts);
  if (spec.placement.is_identity()) return parts;
  for (auto& part : parts) part = sample::placed(spec.placement, std::move(part));
  return parts;
}

// The designed landmarks where the placed head has them, less those outside a cone-beam field
// (a scan without them: the truth is "absent").
LandmarkSet scanned_landmarks(const sample::PhantomDesign& design, const sample::PartList& designed_parts,
                              const PhantomSpec& spec) {
  LandmarkSet scanned;
  for (auto l : sample::phantom_landmarks(design, designed_parts)) {
    l.position = spec.placement.to_scanner(l.position);
    if (!spec.cone_beam || spec.cone_beam->reconstructs(l.position)) scanned.push_back(l);
  }
  return scanned;
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
  const sample::PartList designed_parts = sample::build_phantom_parts(design);
  sample::PaintedGrid grid = sample::paint_parts(scanned_parts(design, designed_parts, spec), scanned_grid(spec));
  Phantom phantom;
  phantom.ct = sample::compute_ct(grid, spec);
  phantom.labels = LabelVolume{grid.geometry, std::move(grid.tissue)};
  phantom.landmarks = scanned_landmarks(design, designed_parts, spec);
  return phantom;
}

LandmarkSet make_phantom_landmarks(const PhantomSpec& spec) {
  const sample::PhantomDesign design = sample::make_design(spec);
  return scanned_landmarks(design, sample::build_phantom_parts(design), spec);
}

}  // namespace maxillo
