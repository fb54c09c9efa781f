#include "casework/augmented_model.h"

#include "geometry/aabb_tree.h"
#include "geometry/mesh_measures.h"
#include "mesh/surface_extraction.h"
#include "sample/phantom.h"

namespace maxillo::casework {
namespace {

// The scan's crown triangles (all three corners on a crown) as a mesh of their own.
TriangleMesh crowns_of(const TriangleMesh& scan, const std::vector<uint8_t>& crown_vertex) {
  TriangleMesh crowns;
  crowns.vertices = scan.vertices;
  std::vector<Eigen::Vector3i> faces;
  for (Eigen::Index f = 0; f < scan.face_count(); ++f) {
    const Eigen::Vector3i face = scan.faces.row(f).transpose();
    if (crown_vertex[size_t(face(0))] && crown_vertex[size_t(face(1))] && crown_vertex[size_t(face(2))])
      faces.push_back(face);
  }
  crowns.faces.resize(Eigen::Index(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f) crowns.faces.row(Eigen::Index(f)) = faces[f].transpose();
  return crowns;
}

}  // namespace

AugmentedArch augmented_arch(const Volume& ct, const CaseTissues& tissues, records::DentalArch arch,
                             const TriangleMesh& ct_teeth, const TriangleMesh& opposing_teeth,
                             const TriangleMesh& placed_scan, const AugmentedModelOptions& options) {
  const uint8_t label = uint8_t(arch == records::DentalArch::kUpper ? Tissue::kUpperTooth : Tissue::kLowerTooth);
  // From this jaw's teeth (roots included) towards the opposing ones: the way the crowns point.
  const Eigen::Vector3d towards_occlusal =
      (opposing_teeth.vertices.colwise().mean() - ct_teeth.vertices.colwise().mean()).transpose().normalized();
  const dental::AugmentedDentition solid =
      dental::augmented_dentition(ct, tissues.jaws, label, ct_teeth, placed_scan, towards_occlusal, options.dentition);
  AugmentedArch out;
  out.arch = arch;
  out.crown_voxels = solid.crown_voxels;
  out.ct_voxels_kept = solid.ct_voxels_kept;
  out.ct_voxels_cut = solid.ct_voxels_cut;
  SurfaceOptions surface;
  surface.keep_largest_components = 0;  // every tooth
  surface.smoothing_iterations = 10;
  surface.target_triangles = 150000;  // the grid's 0.25 mm steps need no more; the crowns are snapped after
  out.surface = extract_surface(solid.solid, 1, surface);
  // The crowns are the scan's: surface points near them are put onto them.
  const TriangleMesh crowns = crowns_of(placed_scan, solid.crown_vertex);
  out.from_scan.assign(size_t(out.surface.vertex_count()), 0);
  if (crowns.face_count() == 0) return out;
  const AabbTree tree(crowns);
  for (Eigen::Index v = 0; v < out.surface.vertex_count(); ++v) {
    const auto nearest = tree.nearest(out.surface.vertices.row(v).transpose(), options.snap_mm);
    if (nearest.face < 0) continue;
    out.surface.vertices.row(v) = nearest.point.transpose();
    out.from_scan[size_t(v)] = 1;
  }
  return out;
}

}  // namespace maxillo::casework
