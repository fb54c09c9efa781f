#pragma once
// The nose's cartilage in the face model (issue 34). A model of one homogeneous tissue lets the
// nose hang from the upper lip: a Le Fort I advancement moved the cadaver's nose tip by 0.48 of
// the advancement where published series measure 0.17-0.3. What holds the tip is its framework:
// the alar and upper lateral cartilages and the septum, joined to the nasal bones' lower edge,
// which a Le Fort I leaves in place. Nasal cartilage's Young's modulus is of the order of MPa
// (below), the face's fat and muscle's of kPa; at the model's 4-5 mm cells its plates, a
// millimetre thick, cannot be meshed, so the whole cartilaginous nose is one stiffer tissue, its
// modulus the rule of mixtures along the plates (Voigt) with about a tenth of it cartilage.
//
// The region, in the landmarks' head frame (ceph/landmark_frame.h):
//   in front of the plane through the nasion N and the anterior nasal spine ANS, square to the
//     midsagittal plane (the external nose, and the tissue over the nasal bones, which holds it);
//   above subnasale Sn (the columella's foot; the upper lip below it stays soft tissue);
//   within 17 mm of the midline through pronasale Prn (an adult's alar base is about 35 mm wide).
// The face region bounds it above (below the orbits, or up to the forehead's cut).
#include <cstdint>
#include <optional>
#include <vector>

#include "ceph/landmark.h"
#include "softtissue/face_region.h"
#include "softtissue/tet_mesh.h"

namespace maxillo::casework {

// Nasal cartilage's Young's modulus, MPa: in compression 2.72 +/- 0.63 (septum), 2.09 +/- 0.81
// (alar), 0.98 +/- 0.29 (upper lateral), Griffin et al. 2016, J Mater Sci Mater Med 27:11; in
// tension 3.01 +/- 0.39 (septum), Richmon et al. 2005, Am J Rhinol 19:617.
inline constexpr double kCartilageModulusMpa = 2.0;
// The share of the nose's tissue that is cartilage: an estimate (plates about 1 mm thick in a
// nose a centimetre and more deep), not a measurement.
inline constexpr double kCartilageVolumeFraction = 0.1;
// The face's soft tissue, as the models take it (softtissue/linear_elasticity.h).
inline constexpr double kFaceTissueModulusMpa = 0.003;
// Young's modulus of the cartilaginous nose over the face's soft tissue: 0.1 x 2 + 0.9 x 0.003
// MPa = 0.203 MPa, about 68 times the soft tissue.
inline constexpr double kNasalCartilageStiffness =
    (kCartilageVolumeFraction * kCartilageModulusMpa + (1 - kCartilageVolumeFraction) * kFaceTissueModulusMpa) /
    kFaceTissueModulusMpa;

// The region above; nullopt when N, ANS, Sn or Prn is missing, or Prn does not lie in front of
// the N-ANS plane.
std::optional<softtissue::RegionShape> nasal_cartilage_region(const LandmarkSet& landmarks);

// Gives the tets whose centroid lies in `region` the stiffness `factor` (the others keep theirs,
// 1 when the mesh had none). Returns how many tets lie in the region.
int stiffen_region(softtissue::TetMesh& mesh, const softtissue::RegionShape& region, double factor);

// Per node of `mesh`, 1 for a corner of a tet whose centroid lies in `region` (stiffen_region's
// tets), else 0. The case workflow passes the nose's to softtissue::attach_to_bone as tissue that
// the moved bone does not carry: a Le Fort I frees the septum from the maxillary crest, so the
// cartilaginous nose follows the tissue around it, not the bone. Joined to the maxilla, the few
// nodes of this stiff region that touch it (2 at 4 mm cells, 3 at 2.5 mm on the cadaver head)
// drove the whole nose: its tip moved 0.31 of a 6 mm advancement at 4 mm cells and 0.40 at
// 2.5 mm; free, 0.18 and 0.19 (docs/ARCHITECTURE.md, "Soft tissue realism").
std::vector<uint8_t> region_tet_nodes(const softtissue::TetMesh& mesh, const softtissue::RegionShape& region);

}  // namespace maxillo::casework
