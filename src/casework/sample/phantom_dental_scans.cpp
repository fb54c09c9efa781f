#include "casework/sample/phantom_dental_scans.h"

#include <cmath>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/json.h"
#include "core/parallel_slabs.h"
#include "geometry/mesh_transform.h"
#include "mesh/mesh_io.h"
#include "mesh/surface_extraction.h"
#include "occlusion/occlusion_files.h"
#include "sample/phantom_design.h"
#include "sample/phantom_dentition.h"
#include "sample/simulated_dental_scan.h"

namespace maxillo::casework {
namespace {

using sample::Dentition;
using sample::Jaw;
using sample::Tooth;

constexpr double kMarginMm = 2.0;  // around the tooth's nominal box: cusps, roots' spread

// A grid in the tooth's own frame (distal, buccal, apical) of the reference anatomy, covering
// the tooth with a margin, labelled 1 inside its crown or roots as the displaced jaw holds them.
LabelVolume tooth_grid(const Dentition& dentition, const Tooth& tooth, double spacing) {
  Eigen::Matrix3d axes;
  axes << tooth.mesiodistal, tooth.buccal, tooth.apical;
  if (axes.determinant() < 0) axes.col(1) = -axes.col(1);  // a right-handed grid
  const Eigen::Vector3d low(-tooth.width / 2 - kMarginMm, -tooth.thickness / 2 - kMarginMm, -kMarginMm);
  const Eigen::Vector3d high(tooth.width / 2 + kMarginMm, tooth.thickness / 2 + kMarginMm,
                             tooth.crown_height + tooth.root_length + kMarginMm);
  LabelVolume grid;
  grid.geometry.spacing = Eigen::Vector3d::Constant(spacing);
  grid.geometry.direction = axes;
  grid.geometry.origin = tooth.origin + axes * low;
  grid.geometry.size = ((high - low) / spacing).array().ceil().cast<int>() + 1;
  grid.labels.assign(size_t(grid.geometry.voxel_count()), 0);
  for (int k = 0; k < grid.geometry.size.z(); ++k)
    for (int j = 0; j < grid.geometry.size.y(); ++j)
      for (int i = 0; i < grid.geometry.size.x(); ++i) {
        const Eigen::Vector3d p = dentition.displaced(tooth.jaw, grid.geometry.world(Eigen::Vector3d(i, j, k)));
        if (dentition.inside(tooth, sample::ToothPart::kCrown, p) ||
            dentition.inside(tooth, sample::ToothPart::kRoot, p))
          grid.labels[size_t(grid.geometry.index(i, j, k))] = 1;
      }
  return grid;
}

// The tooth's closed surface where its jaw holds it (LPS mm): traced in the reference anatomy,
// then carried by the jaw's displacement, as the CT's voxels were.
TriangleMesh tooth_surface(const Dentition& dentition, const Tooth& tooth, double spacing) {
  SurfaceOptions options;
  options.target_triangles = 4000;  // a scanner's density (about 0.3 mm edges), not the grid's
  TriangleMesh surface = extract_surface(tooth_grid(dentition, tooth, spacing), 1, options);
  for (Eigen::Index v = 0; v < surface.vertex_count(); ++v)
    surface.vertices.row(v) = dentition.displaced(tooth.jaw, surface.vertices.row(v).transpose()).transpose();
  return surface;
}

// A scanner's frame: the arch's centroid at its origin, turned by a fixed rotation of its own,
// as scanners put their scans where they like.
Eigen::Isometry3d scanner_pose(const TriangleMesh& arch_in_ct, double angle_deg, const Eigen::Vector3d& axis) {
  const Eigen::Vector3d centroid = arch_in_ct.vertices.colwise().mean().transpose();
  Eigen::Isometry3d scan_to_ct = Eigen::Isometry3d::Identity();
  scan_to_ct.translate(centroid).rotate(Eigen::AngleAxisd(angle_deg * M_PI / 180, axis.normalized()));
  return scan_to_ct;
}

Json truth_json(const PhantomDentalScans& scans) {
  return Json{{"upper", {{"scan_to_ct", occlusion::transform_to_json(scans.upper.scan_to_ct)}}},
              {"lower", {{"scan_to_ct", occlusion::transform_to_json(scans.lower.scan_to_ct)}}}};
}

}  // namespace

PhantomDentalScans make_phantom_dental_scans(const PhantomSpec& spec, const PhantomDentalScanOptions& options) {
  const Dentition dentition(sample::make_design(spec));
  const auto& teeth = dentition.teeth();
  std::vector<TriangleMesh> surfaces(teeth.size());
  for_each_slab(0, int(teeth.size()),
                [&](int begin, int end) {
                  for (int t = begin; t < end; ++t)
                    surfaces[size_t(t)] = tooth_surface(dentition, teeth[size_t(t)], options.spacing_mm);
                },
                {.min_slab_size = 1});
  std::vector<TriangleMesh> upper, lower;
  for (size_t t = 0; t < teeth.size(); ++t) (teeth[t].jaw == Jaw::kUpper ? upper : lower).push_back(surfaces[t]);
  // Between the arches: the incisal edges' and the molar cusps' middle, on the occlusal plane.
  const Eigen::Vector3d between = 0.25 * (dentition.incisal_edge_centre(Jaw::kUpper, sample::Side::kRight) +
                                          dentition.incisal_edge_centre(Jaw::kLower, sample::Side::kLeft) +
                                          dentition.mesiobuccal_cusp_tip(Jaw::kUpper, sample::Side::kRight) +
                                          dentition.mesiobuccal_cusp_tip(Jaw::kLower, sample::Side::kLeft));
  DentalScanOptions scan;
  scan.noise_mm = options.noise_mm;
  PhantomDentalScans scans;
  scan.seed = options.seed;
  const TriangleMesh upper_in_ct = simulated_dental_scan(upper, between, scan);
  scan.seed = options.seed + 1;
  const TriangleMesh lower_in_ct = simulated_dental_scan(lower, between, scan);
  scans.upper.scan_to_ct = scanner_pose(upper_in_ct, 150, Eigen::Vector3d(0.3, 1, 0.2));
  scans.lower.scan_to_ct = scanner_pose(lower_in_ct, 110, Eigen::Vector3d(1, -0.4, 0.5));
  scans.upper.scan = transformed(upper_in_ct, scans.upper.scan_to_ct.inverse());
  scans.lower.scan = transformed(lower_in_ct, scans.lower.scan_to_ct.inverse());
  return scans;
}

void write_phantom_dental_scans(const PhantomDentalScans& scans, const std::filesystem::path& folder) {
  create_folders_durably(folder);
  write_mesh(scans.upper.scan, folder / "upper.stl");
  write_mesh(scans.lower.scan, folder / "lower.stl");
  write_file_atomically(folder / "truth.json", truth_json(scans).dump(2) + "\n");
}

PhantomDentalScans read_phantom_dental_truth(const std::filesystem::path& folder) {
  const auto path = folder / "truth.json";
  const auto bytes = read_file(path);
  const Json truth =
      Json::parse(std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size()), nullptr, false);
  if (truth.is_discarded() || !truth.contains("upper") || !truth.contains("lower"))
    throw Error(ErrorCode::kBadValue, path.string(), "not a dental scans' truth (upper and lower scan_to_ct)");
  PhantomDentalScans scans;
  scans.upper.scan_to_ct = occlusion::transform_from_json(truth["upper"]["scan_to_ct"], path.string());
  scans.lower.scan_to_ct = occlusion::transform_from_json(truth["lower"]["scan_to_ct"], path.string());
  return scans;
}

}  // namespace maxillo::casework
