#include "tetmesh/labelled_tet_mesher.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Image_3.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/make_mesh_3.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include "core/error.h"
#include "core/log.h"

namespace maxillo::tetmesh {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Domain = CGAL::Labeled_mesh_domain_3<Kernel>;
using Triangulation = CGAL::Mesh_triangulation_3<Domain>::type;
using Complex = CGAL::Mesh_complex_3_in_triangulation_3<Triangulation>;
using Criteria = CGAL::Mesh_criteria_3<Triangulation>;

// The voxels [lo, hi] (inclusive) of the label, padded by two voxels of background so the
// region's surface is closed inside the image.
struct Crop {
  Eigen::Vector3i lo, size;
};

Crop crop_around(const LabelVolume& volume, uint8_t label) {
  const auto& g = volume.geometry;
  Eigen::Vector3i lo = g.size, hi = Eigen::Vector3i::Constant(-1);
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i)
        if (volume.labels[size_t(g.index(i, j, k))] == label) {
          lo = lo.cwiseMin(Eigen::Vector3i(i, j, k));
          hi = hi.cwiseMax(Eigen::Vector3i(i, j, k));
        }
  if (hi.x() < 0) throw Error(ErrorCode::kEmptyResult, "tetrahedral mesh", "the region to mesh has no voxels");
  lo.array() -= 2;
  hi.array() += 2;
  return {lo, hi - lo + Eigen::Vector3i::Ones()};
}

// A CGAL image of the crop: 1 inside the region, 0 outside (background is the default value,
// which Mesh_3 treats as outside the domain).
CGAL::Image_3 make_image(const LabelVolume& volume, uint8_t label, const Crop& crop) {
  const auto& g = volume.geometry;
  _image* image = ::_createImage(size_t(crop.size.x()), size_t(crop.size.y()), size_t(crop.size.z()), 1, g.spacing.x(),
                                 g.spacing.y(), g.spacing.z(), 1, WK_FIXED, SGN_UNSIGNED);
  auto* data = static_cast<unsigned char*>(image->data);
  std::memset(data, 0, size_t(crop.size.prod()));
  for (int k = 0; k < crop.size.z(); ++k)
    for (int j = 0; j < crop.size.y(); ++j)
      for (int i = 0; i < crop.size.x(); ++i) {
        const Eigen::Vector3i v = crop.lo + Eigen::Vector3i(i, j, k);
        if (!g.contains(v.x(), v.y(), v.z())) continue;
        if (volume.labels[size_t(g.index(v.x(), v.y(), v.z()))] == label)
          data[size_t(i) + size_t(crop.size.x()) * (size_t(j) + size_t(crop.size.y()) * size_t(k))] = 1;
      }
  return CGAL::Image_3(image);
}

Complex run_mesh_3(const Domain& domain, const TetMeshingOptions& o, double cell_size) {
  namespace p = CGAL::parameters;
  Criteria criteria(p::facet_angle = o.facet_angle_deg, p::facet_size = cell_size,
                    p::facet_distance = o.facet_distance_mm, p::cell_radius_edge_ratio = o.radius_edge_ratio,
                    p::cell_size = cell_size);
  // Perturbation and exudation remove slivers. A time limit would make the mesh depend on the
  // machine's load (a loaded machine optimises less), so there is none: the perturber raises the
  // worst dihedral angle degree by degree and stops at the bound or at the first degree it cannot
  // gain; the exuder makes one pass over the cells below the bound.
  return CGAL::make_mesh_3<Complex>(domain, criteria, p::no_lloyd(), p::no_odt(),
                                    p::perturb(p::time_limit = 0, p::sliver_bound = o.sliver_bound_deg),
                                    p::exude(p::time_limit = 0, p::sliver_bound = o.sliver_bound_deg));
}

// Cells of the complex as a TetMesh in LPS: image coordinates are index x spacing from the crop.
softtissue::TetMesh to_tet_mesh(const Complex& complex, const VolumeGeometry& g, const Crop& crop) {
  const Eigen::Vector3d crop_origin = g.world(crop.lo.cast<double>());
  std::unordered_map<Complex::Vertex_handle, int> index;
  std::vector<Eigen::Vector3d> nodes;
  std::vector<Eigen::Vector4i> tets;
  const auto& tr = complex.triangulation();
  auto point_of = tr.geom_traits().construct_point_3_object();
  for (auto cell = complex.cells_in_complex_begin(); cell != complex.cells_in_complex_end(); ++cell) {
    Eigen::Vector4i tet;
    for (int c = 0; c < 4; ++c) {
      auto vertex = cell->vertex(c);
      auto [it, added] = index.try_emplace(vertex, int(nodes.size()));
      if (added) {
        const auto p = point_of(vertex->point());
        nodes.push_back(crop_origin + g.direction * Eigen::Vector3d(p.x(), p.y(), p.z()));
      }
      tet[c] = it->second;
    }
    tets.push_back(tet);
  }
  softtissue::TetMesh mesh;
  mesh.nodes.resize(Eigen::Index(nodes.size()), 3);
  for (size_t n = 0; n < nodes.size(); ++n) mesh.nodes.row(Eigen::Index(n)) = nodes[n].transpose();
  mesh.tets.resize(Eigen::Index(tets.size()), 4);
  for (size_t t = 0; t < tets.size(); ++t) mesh.tets.row(Eigen::Index(t)) = tets[t].transpose();
  softtissue::orient_positively(mesh);  // a direction matrix with det -1 mirrors the image
  return mesh;
}

}  // namespace

// Each attempt re-meshes with cells grown by the cube root of the overshoot, which lands within
// a few percent of the budget in one or two attempts; six bound the loop.
constexpr int kMaxAttempts = 6;

TetMeshingResult mesh_label(const LabelVolume& volume, uint8_t label, const TetMeshingOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const Crop crop = crop_around(volume, label);
  CGAL::Image_3 image = make_image(volume, label, crop);
  CGAL::get_default_random() = CGAL::Random(options.random_seed);
  Domain domain = Domain::create_labeled_image_mesh_domain(image);
  TetMeshingResult result;
  result.cell_size_mm = options.cell_size_mm;
  result.tet_budget = options.max_tets;
  for (;;) {
    CGAL::get_default_random() = CGAL::Random(options.random_seed);
    Complex complex = run_mesh_3(domain, options, result.cell_size_mm);
    ++result.attempts;
    const auto cells = int(complex.number_of_cells_in_complex());
    if (cells <= options.max_tets || result.attempts >= kMaxAttempts) {
      if (cells > options.max_tets)  // said, with the numbers: the caller asked for a budget
        log::warning("tet mesh: ", cells, " tetrahedra after ", result.attempts, " attempts, over the budget of ",
                     options.max_tets, " (cell size ", result.cell_size_mm, " mm)");
      result.mesh = to_tet_mesh(complex, volume.geometry, crop);
      break;
    }
    // Tet count scales with 1/size^3: aim 5% below the limit.
    const double factor = std::cbrt(double(cells) / (0.95 * options.max_tets));
    log::debug("tet mesh: ", cells, " tets at ", result.cell_size_mm, " mm; retrying at x", factor);
    result.cell_size_mm *= factor;
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace maxillo::tetmesh
