#pragma once
// The phantom as an ordered list of parts. Each part is an inside test with a bounding box, the
// tissue label and material it paints, and the labels it may overwrite. Painting the parts in
// order (later parts win) builds the label volume; the same list answers point queries, which
// is how landmarks on computed surfaces (Or, Po) are found exactly.
#include <cstdint>
#include <functional>
#include <vector>

#include "sample/implicit.h"
#include "sample/phantom_design.h"

namespace maxillo::sample {

// What a voxel is made of; decides its HU (phantom_hu.cpp). Bone's cortical/cancellous split
// is made later from the distance to the bone surface.
enum class Material : uint8_t {
  kAir,
  kFat,
  kSoft,
  kBrain,
  kVitreous,
  kBone,
  kEnamel,
  kDentine,
  kHeadRest,
  kTable,
  kAmalgam  // metal fillings (the cone-beam flavour's)
};

using TissueMask = uint16_t;
constexpr TissueMask mask_of(Tissue t) { return TissueMask(1u << unsigned(t)); }
template <typename... T>
constexpr TissueMask mask_of(Tissue first, T... rest) {
  return mask_of(first) | mask_of(rest...);
}
inline constexpr TissueMask kAnyTissue = 0xFFFF;

struct Part {
  const char* name;
  Box box;                                      // LPS mm; nothing is painted outside it
  std::function<bool(const Vector3d&)> inside;  // p in LPS mm
  Tissue tissue;
  Material material;
  TissueMask overwrites = kAnyTissue;  // labels this part may replace
};
using PartList = std::vector<Part>;

// A part defined for the left side (x >= 0) and mirrored to the right: evaluated on |x|.
Part bilateral(const char* name, const Box& left_box, std::function<bool(const Vector3d&)> left_inside, Tissue tissue,
               Material material, TissueMask overwrites = kAnyTissue);

// The part moved with the maxilla (below the Le Fort I band) or the mandibular body by the
// spec's displacement knobs: queries are pulled back to the reference anatomy.
Part with_maxilla(const PhantomDesign& design, Part part);
Part with_mandible(const PhantomDesign& design, Part part);

// Anatomical groups, each appending its parts in painting order.
void add_soft_tissue_parts(const PhantomDesign& design, PartList& parts);
void add_cranium_parts(const PhantomDesign& design, PartList& parts);
void add_midface_parts(const PhantomDesign& design, PartList& parts);
void add_cavity_parts(const PhantomDesign& design, PartList& parts);
void add_mandible_parts(const PhantomDesign& design, PartList& parts);
void add_neck_parts(const PhantomDesign& design, PartList& parts);
void add_dentition_parts(const PhantomDesign& design, PartList& parts);
void add_support_parts(const PhantomDesign& design, PartList& parts);
// An occlusal amalgam filling in each first molar's crown (after the teeth).
void add_amalgam_fillings(const PhantomDesign& design, PartList& parts);
// The part as it lies in the scanner: queries mapped back to the anatomy frame, box widened.
Part placed(const PhantomPlacement& placement, Part part);
// The axis-aligned box around a box of the anatomy frame as it lies in the scanner.
Box placed_box(const PhantomPlacement& placement, const Box& box);

// Anterior coordinate of the nasal bones' outer surface at (x, z) (shared by the nasal cavity).
double nasal_bone_front(const PhantomDesign& design, double x, double z);

// All parts in painting order.
PartList build_phantom_parts(const PhantomDesign& design);

struct PointSample {
  Tissue tissue = Tissue::kAir;
  Material material = Material::kAir;
};
// What the painted phantom holds at p (before voxelisation).
PointSample sample_parts(const PartList& parts, const Vector3d& p);

}  // namespace maxillo::sample
