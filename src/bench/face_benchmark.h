#pragma once
// `maxillo bench face`: the soft tissue pipeline's costs on the phantom's face (issue 3): tet
// meshing of the face region, the static solve of each model, and both mappings to the dense
// skin (initialisation and update), as medians of `runs`, with the peak memory.
// Targets: meshing <= 10 s at <= 100,000 tets; Gaussian mapping onto ~60,000 skin vertices:
// initialisation <= 50 ms, update <= 10 ms.
#include <cstdint>
#include <string>

#include "core/json.h"

namespace maxillo::bench {

struct FaceBenchOptions {
  double spacing_mm = 1.0;          // the phantom's voxel size
  int runs = 5;                     // medians are reported
  int max_tets = 100000;            // the tetrahedra budget
  double cell_mm = 3.0;             // target tetrahedron size
  int64_t skin_triangles = 120000;  // the skin's decimation target, about 60,000 vertices
  double advancement_mm = 6;        // the Le Fort I advancement predicted
};

// The figures: spacing_mm, skin_vertices, advancement_mm, runs; meshing (seconds, tets, nodes,
// cell_mm, min_dihedral_deg, mean_aspect_ratio, max_aspect_ratio); models, one entry per model
// (model, title, setup_seconds, solve_seconds, iterations, largest_skin_move_mm);
// shape_function_mapping and gaussian_mapping (init_seconds, update_seconds, bound_vertices;
// the Gaussian's radius_mm), tet_boundary_seconds and skin_index_seconds (what the Gaussian
// mapping builds once per model and once per skin), mapping_difference_p95_mm (shape functions
// against Gaussian on the skin), peak_memory_mb.
Json run_face_benchmark(const FaceBenchOptions& options);

// The figures as `bench face` prints them, a line per stage.
std::string face_benchmark_text(const Json& figures);

}  // namespace maxillo::bench
