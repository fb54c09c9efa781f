// maxillo bench face [--spacing MM] [--runs 5] [--max-tets N] [--cell-mm MM] [--skin-triangles N]:
// the soft tissue pipeline's costs on the phantom's face: meshing, solves, skin mappings
// (bench/face_benchmark.h).
#include <iostream>

#include "bench/face_benchmark.h"
#include "cli/command.h"
#include "core/json.h"

namespace maxillo::cli {

void attach_bench_face(CLI::App& bench, CommandContext& ctx) {
  auto args = std::make_shared<bench::FaceBenchOptions>();
  CLI::App* face =
      bench.add_subcommand("face", "soft tissue model of the phantom's face: meshing, solves, skin mappings");
  face->add_option("--spacing", args->spacing_mm, "phantom voxel size, mm")
      ->check(CLI::Range(0.5, 3.0))
      ->capture_default_str();
  face->add_option("--runs", args->runs, "runs; medians are reported")->check(CLI::Range(1, 50))->capture_default_str();
  face->add_option("--max-tets", args->max_tets, "tetrahedra budget")->check(kTetrahedra)->capture_default_str();
  face->add_option("--cell-mm", args->cell_mm, "target tetrahedron size, mm")->check(kCellMm)->capture_default_str();
  face->add_option("--skin-triangles", args->skin_triangles, "skin decimation target")
      ->check(kTriangles)
      ->capture_default_str();
  face->callback([args, &ctx] {
    const Json figures = bench::run_face_benchmark(*args);
    std::cout << (ctx.global.json ? json_text(figures) + "\n" : bench::face_benchmark_text(figures));
  });
}

}  // namespace maxillo::cli
