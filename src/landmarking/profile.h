#pragma once
// The tools the landmark rules are written with: where a ray first meets a tissue, the profile
// of the bone or the skin seen from the front in the midsagittal plane, and how deep a profile
// point lies behind the profile's convex hull (a concavity such as nasion, A or B point has a
// depth; the definition "deepest point between two prominences" does not depend on the head's
// tilt when it is read as the depth behind the hull).
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "landmarking/head_volume.h"

namespace maxillo::landmarking {

inline constexpr double kBoneHu = 300;     // cortical and cancellous bone above this
inline constexpr double kSkinHu = -300;    // skin: the air/soft tissue boundary
inline constexpr double kEnamelHu = 1800;  // enamel and dentine of the crowns (above most bone)

// The first point on from + t * direction (unit), 0 < t <= length, where the HU reach
// `threshold`, to 0.02 mm (marching by `step`, then bisection). nullopt when none.
std::optional<Eigen::Vector3d> first_crossing(const HeadVolume& v, const Eigen::Vector3d& from,
                                              const Eigen::Vector3d& direction, double length, double threshold,
                                              double step = 0.25);
// The same for HU falling below `threshold` (leaving a tissue).
std::optional<Eigen::Vector3d> first_drop(const HeadVolume& v, const Eigen::Vector3d& from,
                                          const Eigen::Vector3d& direction, double length, double threshold,
                                          double step = 0.25);

// The tissue's edge on the ray: the first crossing of `threshold`, then moved to where the HU
// are halfway between the tissue in front (1.5 mm before) and the tissue's peak (within 2.5 mm
// after): the half-maximum edge, which does not depend on the threshold or on the blur.
std::optional<Eigen::Vector3d> first_edge(const HeadVolume& v, const Eigen::Vector3d& from,
                                          const Eigen::Vector3d& direction, double length, double threshold);

// A profile seen from the front: for each height z (descending), the smallest y at which the
// tissue's edge (first_edge) lies within |x - centre_x| <= half_width; points without tissue are
// left out.
struct ProfilePoint {
  double z, y, x;
};
using Profile = std::vector<ProfilePoint>;
Profile anterior_profile(const HeadVolume& v, double z_top, double z_bottom, double y_from, double y_to,
                         double threshold, double centre_x = 0, double half_width = 0, double z_step = 0.25);

// The same slab's columns each seen on their own: one profile per column (x from centre_x -
// half_width to centre_x + half_width in 0.5 mm steps), where anterior_profile keeps the most
// anterior of them on each row.
std::vector<Profile> column_profiles(const HeadVolume& v, double z_top, double z_bottom, double y_from, double y_to,
                                     double threshold, double centre_x, double half_width, double z_step = 0.25);

// Depth (mm, >= 0) of each profile point behind the profile's anterior convex hull in the (y, z)
// plane: 0 on the hull's vertices, largest at the bottom of a concavity.
std::vector<double> depth_behind_hull(const Profile& profile);

// The profile up to (not including) its first jump backwards or forwards of more than
// `max_jump_mm` between consecutive heights: a profile read downwards stops where a structure ends.
Profile until_jump(const Profile& profile, double max_jump_mm);

// Index of the smallest / largest y among the profile's points (first of equals); -1 if empty.
int most_anterior(const Profile& profile);
int most_posterior(const Profile& profile);

// The points of the profile with z in [z_low, z_high].
Profile between_heights(const Profile& profile, double z_low, double z_high);

// The extremum of y(z) at profile[index] to a fraction of the sampling step: the vertex of the
// parabola fitted to the points within `half_window_mm` of it (the sample itself when the fit
// has no vertex there). The point's x is kept.
ProfilePoint refined_extremum(const Profile& profile, int index, double half_window_mm = 2.0);
// The same for a value per point (the depth behind the hull): the height where it peaks.
ProfilePoint refined_peak(const Profile& profile, const std::vector<double>& value, int index,
                          double half_window_mm = 2.0);

}  // namespace maxillo::landmarking
