#pragma once
// Undoing a header whose axis was flipped (imaging/head_orientation.h found the face posterior
// or the vertex inferior): the volume's values stay as they are, its patient frame is
// reflected back. A flipped axis is the usual fault of a conversion (a MetaImage written with
// an identity direction, slices stacked in reverse), and undoing it needs a person's word that
// this is what happened: the anatomy shows which axis is reversed, but not whether left and
// right were exchanged with it (a 180° turn reverses two axes, one of them left-right, and a
// head looks alike either way). So `maxillo orientation CASE --reorient` applies it only on
// request, and only when the contradiction is along y or z; a face pointing sideways is not
// an axis flip and is refused.
#include <optional>

#include <Eigen/Core>

#include "core/volume.h"
#include "imaging/head_orientation.h"

namespace maxillo {

// The reflection of the patient axes that undoes the contradiction: diag(1, -1 if the face
// points posterior, -1 if the vertex points inferior). nullopt when the header agrees, is
// undetermined, or the face points sideways (not a pure axis flip).
std::optional<Eigen::Matrix3d> axis_flip_correction(const HeadOrientation& found);

// The geometry with every voxel's patient position p moved to c + flip (p - c), c the grid's
// centre (so the volume stays where it was): the direction becomes flip * direction and the
// origin moves accordingly. Values and voxel order are untouched.
VolumeGeometry flipped_about_centre(const VolumeGeometry& geometry, const Eigen::Matrix3d& flip);

// The grid's centre in patient coordinates (LPS mm): the point flipped_about_centre keeps.
Eigen::Vector3d grid_centre(const VolumeGeometry& geometry);

}  // namespace maxillo
