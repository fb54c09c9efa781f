// maxillo bench face [--spacing MM] [--runs 5] [--max-tets N] [--cell-mm MM] [--skin-triangles N]:
// the soft tissue pipeline's costs on the phantom's face: meshing, solves, skin mappings
// (bench/face_benchmark.h).
// maxillo bench face --real [--advance MM ...] [--free-cavities]: how the predicted profile follows Le Fort I
// advancements on the real cadaver head, beside published series (bench/face_realism_benchmark.h).
#include <iostream>

#include "bench/face_benchmark.h"
#include "bench/face_realism_benchmark.h"
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
  auto real = std::make_shared<bool>(false);
  auto realism = std::make_shared<bench::FaceRealismOptions>();
  face->add_flag("--real", *real,
                 "the real cadaver head instead: profile ratios per model beside published series (issue 34)");
  face->add_option("--advance", realism->advancements_mm, "with --real: Le Fort I advancements, mm")
      ->check(CLI::Range(0.5, 20.0))
      ->capture_default_str();
  face->add_flag("--free-cavities", realism->free_cavities,
                 "with --real: moved bone carries only the tissue on its outer surface (off by default)");
  face->add_flag("--nose-root", realism->nose_root,
                 "with --real: the face region goes on above the orbits in front of the eyes (off by default)");
  auto at_orbitales = std::make_shared<bool>(false);
  face->add_flag("--top-at-orbitales", *at_orbitales,
                 "with --real: the face region's top at the orbitales, as before issue 34 (default: at the brows, "
                 "the brain's base left out)");
  face->add_flag("--part-lips", realism->part_lips,
                 "with --real: the model parted between the lips at their cleft (off by default)");
  auto contact = std::make_shared<std::string>(softtissue::contact_name(realism->bone_contact));
  face->add_option("--bone-contact", *contact, "with --real: tissue on the moved bone is tied to it or slides on it")
      ->check(CLI::IsMember(softtissue::contact_names()))
      ->capture_default_str();
  face->add_option("--nose-stiffness", realism->nose_stiffness,
                   "with --real: Young's modulus of the cartilaginous nose over the soft tissue's (1: homogeneous)")
      ->check(CLI::Range(1.0, 1000.0))
      ->capture_default_str();
  face->add_option("--poisson", realism->poisson_ratio, "with --real: the soft tissue's Poisson ratio")
      ->check(CLI::Range(0.0, 0.499))
      ->capture_default_str();
  face->callback([args, real, realism, contact, at_orbitales, face, &ctx] {
    if (*real) {
      realism->top_at_brows = !*at_orbitales;
      if (face->count("--cell-mm") > 0) realism->meshing.cell_size_mm = args->cell_mm;
      if (face->count("--max-tets") > 0) realism->meshing.max_tets = args->max_tets;
      realism->bone_contact = *softtissue::contact_named(*contact);
      const Json figures = bench::run_face_realism_benchmark(*realism);
      std::cout << (ctx.global.json ? json_text(figures) + "\n" : bench::face_realism_text(figures));
      return;
    }
    const Json figures = bench::run_face_benchmark(*args);
    std::cout << (ctx.global.json ? json_text(figures) + "\n" : bench::face_benchmark_text(figures));
  });
}

}  // namespace maxillo::cli
