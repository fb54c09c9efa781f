// maxillo bench face: the soft tissue pipeline's costs on the phantom's face (issue 3):
// tet meshing of the face region, the static solve of each model, and both mappings to the
// dense skin (initialisation and update), as medians of --runs, with the peak memory.
// Targets: meshing <= 10 s at <= 100,000 tets; Gaussian mapping onto ~60,000 skin vertices:
// initialisation <= 50 ms, update <= 10 ms.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>

#include "cli/command.h"
#include "mesh/surface_extraction.h"
#include "casework/soft_tissue_prediction.h"
#include "planning/osteotomy.h"
#include "sample/phantom.h"
#include "softtissue/gaussian_mapping.h"
#include "softtissue/shape_function_mapping.h"
#include "softtissue/tet_boundary.h"

namespace maxillo::cli {
namespace {

struct FaceBenchArguments {
  double spacing_mm = 1.0;
  int runs = 5;
  int max_tets = 100000;
  double cell_mm = 3.0;
  int64_t skin_triangles = 120000;  // about 60,000 vertices
  double advancement_mm = 6;
};

template <class Work>
double seconds_of(Work&& work) {
  auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

template <class Work>
double median_seconds(int runs, Work&& work) {
  std::vector<double> times;
  for (int r = 0; r < runs; ++r) times.push_back(seconds_of(work));
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;
}

void run_face_bench(const FaceBenchArguments& args) {
  PhantomSpec spec;
  spec.spacing_mm = args.spacing_mm;
  const auto phantom = make_phantom(spec);
  const auto cut = planning::cut_skeleton(phantom.labels, planning::default_osteotomies(phantom.landmarks, {}));
  SurfaceOptions surface;
  surface.target_triangles = args.skin_triangles;
  const auto skin = extract_surface(phantom.ct, -400, surface);
  std::printf("phantom %.1f mm voxels; skin %lld vertices; Le Fort I advancement %.1f mm; medians of %d runs\n",
              args.spacing_mm, (long long)skin.vertex_count(), args.advancement_mm, args.runs);

  casework::SoftTissueInput input{&phantom.labels, &cut.segments, &skin, phantom.landmarks, {}};
  input.moves[uint8_t(planning::Segment::kMaxilla)] = Eigen::Translation3d(0, -args.advancement_mm, 0);
  casework::SoftTissueOptions options;
  options.meshing.max_tets = args.max_tets;
  options.meshing.cell_size_mm = args.cell_mm;
  casework::SoftTissuePrediction base;
  std::vector<double> meshing;
  for (int r = 0; r < args.runs; ++r) {
    base = casework::predict_soft_tissue(input, options);
    meshing.push_back(base.seconds.meshing);
  }
  std::sort(meshing.begin(), meshing.end());
  std::printf("meshing: %.2f s -> %d tets, %d nodes (cell %.2f mm), min dihedral %.1f deg, aspect mean %.2f max %.1f\n",
              meshing[meshing.size() / 2], base.mesh.tet_count(), base.mesh.node_count(), base.meshing.cell_size_mm,
              base.quality.min_dihedral_deg, base.quality.mean_aspect_ratio, base.quality.max_aspect_ratio);

  for (auto model : {softtissue::SoftTissueModel::kMassTensor, softtissue::SoftTissueModel::kLinearFem,
                     softtissue::SoftTissueModel::kMassSpring}) {
    auto variant = options;
    variant.model = model;
    std::vector<double> solve, assembly;
    casework::SoftTissuePrediction p;
    for (int r = 0; r < args.runs; ++r) {
      p = casework::resolve_soft_tissue(base, skin, variant);
      solve.push_back(p.seconds.solve);
      assembly.push_back(p.seconds.assembly);
    }
    std::sort(solve.begin(), solve.end());
    std::sort(assembly.begin(), assembly.end());
    std::printf("%-18s set-up %.3f s, solve %.3f s (%d iterations), largest skin move %.2f mm\n",
                std::string(softtissue::model_title(model)).c_str(), assembly[assembly.size() / 2],
                solve[solve.size() / 2], p.iterations, p.skin_displacement.rowwise().norm().maxCoeff());
  }

  softtissue::ShapeFunctionMapping shape;
  const double shape_init = median_seconds(args.runs, [&] {
    shape = softtissue::init_shape_function_mapping(base.mesh, skin.vertices, options.skin_binding_mm);
  });
  const double shape_update =
      median_seconds(args.runs, [&] { (void)softtissue::map_displacement(base.mesh, shape, base.node_displacement); });
  softtissue::GaussianMappingOptions gaussian_options;
  gaussian_options.radius_mm = std::max(3.0, base.meshing.cell_size_mm);  // must reach the next surface node
  softtissue::TetBoundary boundary;
  const double boundary_seconds = median_seconds(args.runs, [&] { boundary = softtissue::tet_boundary(base.mesh); });
  std::optional<softtissue::SkinIndex> skin_index;
  const double skin_seconds = median_seconds(args.runs, [&] { skin_index.emplace(skin); });
  softtissue::GaussianMapping gaussian;
  const double gaussian_init = median_seconds(args.runs, [&] {
    gaussian = softtissue::init_gaussian_mapping(base.mesh, boundary, *skin_index, gaussian_options);
  });
  const double gaussian_update =
      median_seconds(args.runs, [&] { (void)softtissue::map_displacement(gaussian, base.node_displacement); });
  const auto a = softtissue::map_displacement(base.mesh, shape, base.node_displacement);
  const auto b = softtissue::map_displacement(gaussian, base.node_displacement);
  std::vector<double> difference;
  for (Eigen::Index v = 0; v < a.rows(); ++v)
    if (b.row(v).squaredNorm() > 0) difference.push_back((a.row(v) - b.row(v)).norm());
  std::sort(difference.begin(), difference.end());
  const double p95 = difference.empty() ? 0 : difference[size_t(0.95 * double(difference.size() - 1))];
  std::printf("shape-function mapping: init %.1f ms, update %.1f ms (%d of %lld vertices bound)\n", 1e3 * shape_init,
              1e3 * shape_update, shape.bound_count(), (long long)skin.vertex_count());
  std::printf(
      "once per model: surface of the tet mesh %.1f ms; once per skin: closest-point tree and adjacency %.1f ms\n",
      1e3 * boundary_seconds, 1e3 * skin_seconds);
  std::printf(
      "Gaussian mapping (radius %.1f mm): init %.1f ms, update %.1f ms (%d vertices bound; targets 50 / 10 ms)\n",
      gaussian_options.radius_mm, 1e3 * gaussian_init, 1e3 * gaussian_update, gaussian.bound_count);
  std::printf("shape function vs Gaussian on the skin: P95 difference %.2f mm\n", p95);
  std::printf("peak memory: %.0f MB\n", peak_rss_mb());
}

}  // namespace

void attach_bench_face(CLI::App& bench, CommandContext& /*ctx*/) {
  auto args = std::make_shared<FaceBenchArguments>();
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
  face->callback([args] { run_face_bench(*args); });
}

}  // namespace maxillo::cli
