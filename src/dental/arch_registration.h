#pragma once
// A dental arch scan (an intraoral scan's crowns and gingiva, or a digitised cast's crowns and
// base) placed onto the CT's teeth (issue 30), without hands:
// 1. Starts: the scan's principal axes laid on the CT teeth's, in each of the eight ways that
//    keep a right-handed frame (the two long axes of an arch, its width and depth, may come in
//    either order, and each axis either way round), about the centroids; and any starts given
//    (from dental landmarks).
// 2. From each start, point-to-plane ICP (validation/rigid_icp.h) with pairs up to 8 mm apart;
//    the three starts whose coarse fits lay most of the scan on the teeth go on with pairs up to
//    3 mm, then 1 mm: the last fit uses only the scan's surface that lies on the CT's teeth, so
//    the gingiva, the cast base and the crowns' streaked or missing parts drop out.
// 3. The fit kept is the one with the largest share of the scan within 0.5 mm of the CT's teeth.
//    Its confidence is how far the best other fit (one that places the scan more than 1 mm away)
//    falls short of it: 1 - its share / the best share.
// A fit with less than `min_fit_share` of the scan on the teeth (an arch of another patient, an
// upper arch given as lower) or a confidence under `min_confidence` (two poses fit as well) is an
// error saying which.
#include <Eigen/Geometry>
#include <vector>

#include "core/triangle_mesh.h"

namespace maxillo::dental {

struct ArchRegistrationOptions {
  double on_teeth_mm = 0.5;           // a scan point this close to the CT's teeth is on them
  double min_fit_share = 0.4;         // of the scan on the teeth, below which the fit is poor
  double min_confidence = 0.05;       // below which another pose fits about as well
  double distinct_mm = 1.0;           // fits placing the scan farther apart (RMS) are different poses
  int max_samples = 4000;             // scan vertices used by the fits (a deterministic subset)
  bool principal_axis_starts = true;  // step 1's eight starts (off: only the starts given)
};

// How well a pose lays the scan on the CT's teeth, over the scan's sampled vertices.
struct ArchFit {
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();  // scan frame -> CT frame
  double on_teeth_share = 0;                                    // within on_teeth_mm of the CT's teeth
  double rms_mm = 0;                                            // of the distances of those on the teeth
  double p95_mm = 0;                                            // of the same
  double within_0_3_share = 0;
};

struct ArchRegistration {
  ArchFit fit;
  double confidence = 0;            // 1 - (best other pose's share) / (the fit's share)
  std::vector<ArchFit> candidates;  // one per start, in the starts' order (coarse only, but for the three refined)
};

// Throws Error(BadValue) for an empty mesh, Error(Processing) for a poor or ambiguous fit.
ArchRegistration register_arch(const TriangleMesh& scan, const TriangleMesh& ct_teeth,
                               const std::vector<Eigen::Isometry3d>& extra_starts = {},
                               const ArchRegistrationOptions& options = {});

// An arch's dental landmarks in the CT (LPS mm): the incisor's incisal edge (U1 or L1) and the
// first molars' mesiobuccal cusp tips (U6R, U6L or L6R, L6L).
struct ArchLandmarks {
  Eigen::Vector3d incisor, right_molar, left_molar;
};

// Starts from the landmarks (issue 30: "from the dental landmarks where there are some"): the
// scan's principal axes (widest: side to side; next: front to back; least: crowns' height) laid
// on the arch frame the landmarks define, in the four right-handed ways the axes' signs allow,
// the scan's centroid put halfway between the incisor and the molars. Unlike the CT teeth's own
// principal axes, the landmarks' frame does not tilt with the roots, the streaks or a missing
// tooth. Error(kBadValue) for landmarks that span no arch (molars < 20 mm apart, incisor not in
// front of them).
std::vector<Eigen::Isometry3d> landmark_starts(const TriangleMesh& scan, const ArchLandmarks& landmarks);

// RMS over `vertices` of the mesh (all of them when empty) of the distance between where the
// two poses put each: how far apart two registrations place a scan, or one lies from the truth.
double pose_distance_mm(const TriangleMesh& mesh, const Eigen::Isometry3d& a, const Eigen::Isometry3d& b,
                        const std::vector<int>& vertices = {});

}  // namespace maxillo::dental
