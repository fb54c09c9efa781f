#include "sample/phantom_parts.h"

#include <cmath>

namespace maxillo::sample {

Part bilateral(const char* name, const Box& left_box, std::function<bool(const Vector3d&)> left_inside, Tissue tissue,
               Material material, TissueMask overwrites) {
  auto mirrored = [inside = std::move(left_inside)](const Vector3d& p) {
    return inside(Vector3d(std::abs(p.x()), p.y(), p.z()));
  };
  return Part{name, left_box.united(left_box.mirrored_x()), mirrored, tissue, material, overwrites};
}

Part with_maxilla(const PhantomDesign& design, Part part) {
  auto inside = std::move(part.inside);
  part.inside = [design, inside](const Vector3d& p) { return inside(design.to_maxilla_reference(p)); };
  double shift = std::abs(design.maxilla_shift);
  part.box.lo.y() -= shift;
  part.box.hi.y() += shift;
  return part;
}

Part with_mandible(const PhantomDesign& design, Part part) {
  auto inside = std::move(part.inside);
  part.inside = [design, inside](const Vector3d& p) { return inside(design.to_mandible_reference(p)); };
  double shift = std::abs(design.mandible_shift), deviation = std::abs(design.mandible_deviation);
  part.box.lo.y() -= shift;
  part.box.hi.y() += shift;
  part.box.lo.x() -= deviation;
  part.box.hi.x() += deviation;
  return part;
}

Part placed(const PhantomPlacement& placement, Part part) {
  // The designed box stays part of the test: some parts (the table) are their box.
  auto inside = std::move(part.inside);
  part.inside = [placement, inside, designed = part.box](const Vector3d& p) {
    const Vector3d q = placement.to_anatomy(p);
    return designed.contains(q) && inside(q);
  };
  part.box = placed_box(placement, part.box);
  return part;
}

Box placed_box(const PhantomPlacement& placement, const Box& box) {
  Box placed_corners{placement.to_scanner(box.lo), placement.to_scanner(box.lo)};
  for (int corner = 1; corner < 8; ++corner) {
    const Vector3d c((corner & 1 ? box.hi : box.lo).x(), (corner & 2 ? box.hi : box.lo).y(),
                     (corner & 4 ? box.hi : box.lo).z());
    const Vector3d p = placement.to_scanner(c);
    placed_corners = placed_corners.united({p, p});
  }
  return placed_corners;
}

PartList build_phantom_parts(const PhantomDesign& design) {
  PartList parts;
  add_soft_tissue_parts(design, parts);
  add_cranium_parts(design, parts);
  add_midface_parts(design, parts);
  add_cavity_parts(design, parts);
  add_mandible_parts(design, parts);
  add_neck_parts(design, parts);
  add_dentition_parts(design, parts);
  add_support_parts(design, parts);
  return parts;
}

PointSample sample_parts(const PartList& parts, const Vector3d& p) {
  PointSample sample;
  for (const Part& part : parts) {
    if (!(part.overwrites & mask_of(sample.tissue))) continue;
    if (!part.box.contains(p) || !part.inside(p)) continue;
    sample = {part.tissue, part.material};
  }
  return sample;
}

}  // namespace maxillo::sample
