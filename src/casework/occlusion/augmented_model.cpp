#include "casework/occlusion/augmented_model.h"

#include "mesh/surface_extraction.h"
#include "sample/phantom.h"

namespace maxillo::casework {

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
  surface.grid = SurfaceGrid::Native;
  surface.smoothing_iterations = 5;   // the roots' voxel steps; the crowns' zero level is smooth already
  surface.target_triangles = 150000;  // the grid's 0.25 mm steps need no more
  out.surface = extract_surface(solid.field, 0, surface);
  return out;
}

}  // namespace maxillo::casework
