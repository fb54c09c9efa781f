// CT patient support: a curved head rest (a cylindrical trough under the occiput, its inner
// surface 1.5 mm from the skin at the back of the head) and the flat table plate below it.
// Segmentation has to remove both; they never touch the patient's bone.
#include "sample/phantom_parts.h"

namespace maxillo::sample {
namespace {

constexpr double kOcciputSkinY = 118;   // most posterior skin point (scalp ellipsoid, x = 0, z = 40)
constexpr double kHeadRestGap = 1.5;    // skin to head rest (mm)
constexpr double kHeadRestRadius = 90;  // inner radius of the trough
constexpr double kHeadRestThickness = 8;
constexpr double kHeadRestRimDrop = 40;                      // the trough rises to 40 mm anterior of its lowest line
constexpr double kHeadRestBottom = -60, kHeadRestTop = 110;  // z extent
constexpr double kTableGap = 8, kTableThickness = 10;

constexpr double kAxisY = kOcciputSkinY + kHeadRestGap - kHeadRestRadius;

}  // namespace

void add_support_parts(const PhantomDesign&, PartList& parts) {
  const TissueMask air = mask_of(Tissue::kAir);
  const double outer = kHeadRestRadius + kHeadRestThickness;
  parts.push_back({"head rest",
                   Box{{-outer, kAxisY + kHeadRestRimDrop, kHeadRestBottom}, {outer, kAxisY + outer, kHeadRestTop}},
                   [outer](const Vector3d& p) {
                     double dy = p.y() - kAxisY, r = std::hypot(p.x(), dy);
                     return dy > kHeadRestRimDrop && r > kHeadRestRadius && r < outer;
                   },
                   Tissue::kHeadRest, Material::kHeadRest, air});
  const double table_y = kAxisY + outer + kTableGap;
  parts.push_back({"table", Box{{-1e4, table_y, -1e4}, {1e4, table_y + kTableThickness, 1e4}},
                   [](const Vector3d&) { return true; }, Tissue::kTable, Material::kTable, air});
}

}  // namespace maxillo::sample
