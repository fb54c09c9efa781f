#include "bench/face_benchmark.h"

#include <algorithm>
#include <optional>
#include <vector>

#include "bench/formatted.h"
#include "bench/peak_memory.h"
#include "bench/timing.h"
#include "casework/softtissue/soft_tissue_prediction.h"
#include "mesh/surface_extraction.h"
#include "planning/osteotomy.h"
#include "sample/phantom.h"
#include "softtissue/gaussian_mapping.h"
#include "softtissue/shape_function_mapping.h"
#include "softtissue/tet_boundary.h"

namespace maxillo::bench {
namespace {

using casework::SoftTissueOptions;
using casework::SoftTissuePrediction;

// The prediction the other figures start from, made `runs` times; the median meshing time and
// the mesh.
Json meshing_figures(const casework::SoftTissueInput& input, const SoftTissueOptions& options, int runs,
                     SoftTissuePrediction& base) {
  std::vector<double> meshing;
  for (int r = 0; r < runs; ++r) {
    base = casework::predict_soft_tissue(input, options);
    meshing.push_back(base.seconds.meshing);
  }
  return {{"seconds", median(meshing)},
          {"tets", base.mesh.tet_count()},
          {"nodes", base.mesh.node_count()},
          {"cell_mm", base.meshing.cell_size_mm},
          {"min_dihedral_deg", base.quality.min_dihedral_deg},
          {"mean_aspect_ratio", base.quality.mean_aspect_ratio},
          {"max_aspect_ratio", base.quality.max_aspect_ratio}};
}

// Each model re-solved on the base prediction's mesh: set-up and solve, medians of `runs`.
Json model_figures(const SoftTissuePrediction& base, const TriangleMesh& skin, const SoftTissueOptions& options,
                   int runs) {
  Json models = Json::array();
  for (const auto& entry : softtissue::soft_tissue_models()) {
    if (!entry.in_face_benchmark) continue;
    const auto model = entry.model;
    auto variant = options;
    variant.model = model;
    std::vector<double> solve, assembly;
    SoftTissuePrediction p;
    for (int r = 0; r < runs; ++r) {
      p = casework::resolve_soft_tissue(base, skin, variant);
      solve.push_back(p.seconds.solve);
      assembly.push_back(p.seconds.assembly);
    }
    models.push_back({{"model", softtissue::model_name(model)},
                      {"title", softtissue::model_title(model)},
                      {"setup_seconds", median(assembly)},
                      {"solve_seconds", median(solve)},
                      {"iterations", p.iterations},
                      {"largest_skin_move_mm", p.skin_displacement.rowwise().norm().maxCoeff()}});
  }
  return models;
}

// P95 of how far apart two mappings put the skin vertices the second one bound (mm).
double p95_difference(const Eigen::MatrixX3d& a, const Eigen::MatrixX3d& b) {
  std::vector<double> difference;
  for (Eigen::Index v = 0; v < a.rows(); ++v)
    if (b.row(v).squaredNorm() > 0) difference.push_back((a.row(v) - b.row(v)).norm());
  std::sort(difference.begin(), difference.end());
  return difference.empty() ? 0 : difference[size_t(0.95 * double(difference.size() - 1))];
}

// Both mappings of the base prediction onto the skin: initialisation and update, medians of
// `runs`, and how far apart they put the skin.
Json mapping_figures(const SoftTissuePrediction& base, const TriangleMesh& skin, const SoftTissueOptions& options,
                     int runs) {
  softtissue::ShapeFunctionMapping shape;
  const double shape_init = median_seconds(runs, [&] {
    shape = softtissue::init_shape_function_mapping(base.mesh, skin.vertices, options.skin_binding_mm);
  });
  const double shape_update =
      median_seconds(runs, [&] { (void)softtissue::map_displacement(base.mesh, shape, base.node_displacement); });
  softtissue::GaussianMappingOptions gaussian_options;
  gaussian_options.radius_mm = std::max(3.0, base.meshing.cell_size_mm);  // must reach the next surface node
  softtissue::TetBoundary boundary;
  const double boundary_seconds = median_seconds(runs, [&] { boundary = softtissue::tet_boundary(base.mesh); });
  std::optional<softtissue::SkinIndex> skin_index;
  const double skin_seconds = median_seconds(runs, [&] { skin_index.emplace(skin); });
  softtissue::GaussianMapping gaussian;
  const double gaussian_init = median_seconds(
      runs, [&] { gaussian = softtissue::init_gaussian_mapping(base.mesh, boundary, *skin_index, gaussian_options); });
  const double gaussian_update =
      median_seconds(runs, [&] { (void)softtissue::map_displacement(gaussian, base.node_displacement); });
  const double p95 = p95_difference(softtissue::map_displacement(base.mesh, shape, base.node_displacement),
                                    softtissue::map_displacement(gaussian, base.node_displacement));
  return {{"shape_function_mapping",
           {{"init_seconds", shape_init}, {"update_seconds", shape_update}, {"bound_vertices", shape.bound_count()}}},
          {"tet_boundary_seconds", boundary_seconds},
          {"skin_index_seconds", skin_seconds},
          {"gaussian_mapping",
           {{"radius_mm", gaussian_options.radius_mm},
            {"init_seconds", gaussian_init},
            {"update_seconds", gaussian_update},
            {"bound_vertices", gaussian.bound_count}}},
          {"mapping_difference_p95_mm", p95}};
}

}  // namespace

Json run_face_benchmark(const FaceBenchOptions& options) {
  PhantomSpec spec;
  spec.spacing_mm = options.spacing_mm;
  const auto phantom = make_phantom(spec);
  const auto cut = planning::cut_skeleton(phantom.labels, planning::default_osteotomies(phantom.landmarks, {}));
  SurfaceOptions surface;
  surface.target_triangles = options.skin_triangles;
  const auto skin = extract_surface(phantom.ct, -400, surface);

  casework::SoftTissueInput input{&phantom.labels, &cut.segments, &skin, phantom.landmarks, {}};
  input.moves[uint8_t(planning::Segment::kMaxilla)] = Eigen::Translation3d(0, -options.advancement_mm, 0);
  SoftTissueOptions prediction;
  prediction.meshing.max_tets = options.max_tets;
  prediction.meshing.cell_size_mm = options.cell_mm;
  SoftTissuePrediction base;
  Json figures = {{"spacing_mm", options.spacing_mm},
                  {"skin_vertices", skin.vertex_count()},
                  {"advancement_mm", options.advancement_mm},
                  {"runs", options.runs}};
  figures["meshing"] = meshing_figures(input, prediction, options.runs, base);
  figures["models"] = model_figures(base, skin, prediction, options.runs);
  figures.update(mapping_figures(base, skin, prediction, options.runs));
  figures["peak_memory_mb"] = double(peak_memory_kb()) / 1024.0;
  return figures;
}

std::string face_benchmark_text(const Json& figures) {
  const Json &meshing = figures["meshing"], &shape = figures["shape_function_mapping"],
             &gaussian = figures["gaussian_mapping"];
  const auto skin_vertices = figures["skin_vertices"].get<long long>();
  std::string text =
      formatted("phantom %.1f mm voxels; skin %lld vertices; Le Fort I advancement %.1f mm; medians of %d runs\n",
                figures["spacing_mm"].get<double>(), skin_vertices, figures["advancement_mm"].get<double>(),
                figures["runs"].get<int>());
  text += formatted(
      "meshing: %.2f s -> %d tets, %d nodes (cell %.2f mm), min dihedral %.1f deg, aspect mean %.2f max %.1f\n",
      meshing["seconds"].get<double>(), meshing["tets"].get<int>(), meshing["nodes"].get<int>(),
      meshing["cell_mm"].get<double>(), meshing["min_dihedral_deg"].get<double>(),
      meshing["mean_aspect_ratio"].get<double>(), meshing["max_aspect_ratio"].get<double>());
  for (const auto& model : figures["models"])
    text += formatted("%-18s set-up %.3f s, solve %.3f s (%d iterations), largest skin move %.2f mm\n",
                      model["title"].get<std::string>().c_str(), model["setup_seconds"].get<double>(),
                      model["solve_seconds"].get<double>(), model["iterations"].get<int>(),
                      model["largest_skin_move_mm"].get<double>());
  text += formatted("shape-function mapping: init %.1f ms, update %.1f ms (%d of %lld vertices bound)\n",
                    1e3 * shape["init_seconds"].get<double>(), 1e3 * shape["update_seconds"].get<double>(),
                    shape["bound_vertices"].get<int>(), skin_vertices);
  text += formatted(
      "once per model: surface of the tet mesh %.1f ms; once per skin: closest-point tree and adjacency %.1f ms\n",
      1e3 * figures["tet_boundary_seconds"].get<double>(), 1e3 * figures["skin_index_seconds"].get<double>());
  text += formatted(
      "Gaussian mapping (radius %.1f mm): init %.1f ms, update %.1f ms (%d vertices bound; targets 50 / 10 ms)\n",
      gaussian["radius_mm"].get<double>(), 1e3 * gaussian["init_seconds"].get<double>(),
      1e3 * gaussian["update_seconds"].get<double>(), gaussian["bound_vertices"].get<int>());
  text += formatted("shape function vs Gaussian on the skin: P95 difference %.2f mm\n",
                    figures["mapping_difference_p95_mm"].get<double>());
  return text + formatted("peak memory: %.0f MB\n", figures["peak_memory_mb"].get<double>());
}

}  // namespace maxillo::bench
