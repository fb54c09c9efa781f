#pragma once
// Iso-surfaces of a CT volume or a mask (VTK flying edges behind TriangleMesh).
//
// The result is in patient LPS millimetres (the volume's origin, spacing and direction applied),
// closed (the volume is padded by one voxel of "outside" first, so a body cut by the scan's
// field of view is capped at the border), and oriented with normals pointing out of the
// region above the iso-value.
//
// Pipeline: block means for the budget (SurfaceGrid) -> pad -> vtkFlyingEdges3D in index*spacing space -> keep the largest components ->
// vtkWindowedSincPolyDataFilter -> quadric edge collapse (mesh/quadric_decimation.h, topology kept) ->
// direction matrix + origin -> orient. `maxillo bench surfaces` gives the cost of each step.
#include <cstdint>

#include "core/triangle_mesh.h"
#include "core/volume.h"

namespace maxillo {

// Where the iso-surface is traced: on the CT's own grid, or (the default) on blocks of voxels as
// large as the triangle budget can use (see kOversampling in surface_extraction.cpp): a 0.5 mm
// CT's skin for 200,000 triangles is traced on 1 mm blocks, as a 1 mm CT's would be.
enum class SurfaceGrid { Native, ForBudget };

struct SurfaceOptions {
  // Keep the N connected components with the most triangles (<= 0: keep all) ...
  int keep_largest_components = 1;
  // ... and of those only the ones with at least this fraction of the largest one's triangles.
  double min_component_fraction = 0.01;
  // Windowed-sinc smoothing (Taubin-like, shrinks little): 0 iterations = none. The pass band is
  // VTK's (0..2, lower = smoother); 0.1 is a moderate smoothing of a CT staircase.
  int smoothing_iterations = 15;
  double smoothing_passband = 0.1;
  // Decimation down to about this many triangles (<= 0: no decimation). Never refines; may
  // stop above the target where removing more would change the topology.
  int64_t target_triangles = 0;
  SurfaceGrid grid = SurfaceGrid::ForBudget;  // used on CT values only (not by extract_surface(LabelVolume))
};

// Surface where the HU crosses iso_hu (e.g. -400 for skin, 300 for bone).
// Returns an empty mesh when nothing in the volume exceeds iso_hu.
TriangleMesh extract_surface(const Volume& volume, double iso_hu, const SurfaceOptions& options = {});

// The surface of the region whose labels lie in [first, last], drawn through the CT's own values:
// the surface of restrict_to_mask(volume, select_labels(labels, first, last), iso_hu) at iso_hu
// (imaging/segmentation.h), the same triangles, without the two volume-sized copies (3 bytes a
// voxel: 0.3 GB for a 0.5 mm head) that making that volume first costs.
struct LabelRange {
  uint8_t first = 1, last = 255;
};
TriangleMesh extract_region_surface(const Volume& volume, const LabelVolume& labels, LabelRange region, double iso_hu,
                                    const SurfaceOptions& options = {});

// Surface of the voxels of `mask` equal to `label` (iso 0.5 on the 0/1 indicator).
TriangleMesh extract_surface(const LabelVolume& mask, uint8_t label, const SurfaceOptions& options = {});

}  // namespace maxillo
