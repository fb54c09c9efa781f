#include "dental/arch_registration.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <random>
#include <string>

#include "core/error.h"
#include "geometry/aabb_tree.h"
#include "validation/distance_statistics.h"
#include "validation/rigid_icp.h"

namespace maxillo::dental {
namespace {

// The fits from each start, coarse to fine: how far apart pairs may lie, how many scan vertices
// are used, and when the fit stops (the largest move of an iteration). The coarse fits need not
// settle to a micrometre: the finest one does.
struct FitStage {
  double reach_mm;
  int samples;
  double tolerance_mm;
};
constexpr FitStage kCoarse{8.0, 1000, 0.01};
constexpr std::array<FitStage, 2> kFine{{{3.0, 2000, 0.01}, {1.0, 0, 1e-4}}};
// Starts whose coarse fit scores best go on to the fine fits; the others stop there.
constexpr size_t kRefinedStarts = 3;

struct PrincipalFrame {
  Eigen::Vector3d centroid;
  Eigen::Matrix3d axes;  // columns: unit axes by decreasing spread, right-handed
};

PrincipalFrame principal_frame(const TriangleMesh& mesh) {
  PrincipalFrame frame;
  frame.centroid = mesh.vertices.colwise().mean().transpose();
  const Eigen::MatrixX3d centred = mesh.vertices.rowwise() - frame.centroid.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(centred.transpose() * centred);
  // Eigen sorts the eigenvalues increasingly: reverse, so the widest spread comes first.
  frame.axes = solver.eigenvectors().rowwise().reverse();
  if (frame.axes.determinant() < 0) frame.axes.col(2) *= -1;
  return frame;
}

// A deterministic subset of the scan's vertices, in increasing order.
std::vector<int> sampled_vertices(const TriangleMesh& mesh, int count) {
  std::vector<int> all(size_t(mesh.vertex_count()));
  std::iota(all.begin(), all.end(), 0);
  if (count > 0 && int(all.size()) > count) {
    std::mt19937 random(1);
    std::shuffle(all.begin(), all.end(), random);
    all.resize(size_t(count));
    std::sort(all.begin(), all.end());
  }
  return all;
}

// One stage's fit from `pose`; a fit that finds too few pairs keeps the pose it was given.
Eigen::Isometry3d fit_stage(const TriangleMesh& scan, const validation::IcpTarget& ct_teeth, const FitStage& stage,
                            const Eigen::Isometry3d& pose, const ArchRegistrationOptions& options) {
  validation::IcpOptions icp;
  icp.max_pair_distance_mm = stage.reach_mm;
  icp.max_samples = stage.samples > 0 ? stage.samples : options.max_samples;
  icp.tolerance_mm = stage.tolerance_mm;
  try {
    return validation::rigid_icp(scan, ct_teeth, pose, icp).transform;
  } catch (const Error& e) {
    if (e.code() != ErrorCode::kProcessing) throw;  // too few pairs from this start: it stays where it is
    return pose;
  }
}

ArchFit score_on(const TriangleMesh& scan, const AabbTree& tree, const std::vector<int>& samples,
                 const Eigen::Isometry3d& transform, const ArchRegistrationOptions& options) {
  std::vector<double> on_teeth;
  int within_0_3 = 0;
  for (int v : samples) {
    const auto nearest =
        tree.nearest(transform * Eigen::Vector3d(scan.vertices.row(v).transpose()), options.on_teeth_mm);
    if (nearest.face < 0) continue;
    on_teeth.push_back(nearest.distance);
    within_0_3 += nearest.distance <= 0.3;
  }
  ArchFit fit;
  fit.transform = transform;
  if (samples.empty()) return fit;
  fit.on_teeth_share = double(on_teeth.size()) / double(samples.size());
  fit.within_0_3_share = double(within_0_3) / double(samples.size());
  if (on_teeth.empty()) return fit;
  double sum = 0;
  for (double d : on_teeth) sum += d * d;
  fit.rms_mm = std::sqrt(sum / double(on_teeth.size()));
  fit.p95_mm = validation::percentile(on_teeth, 95);
  return fit;
}

void require_surface(const TriangleMesh& mesh, const char* what) {
  if (mesh.vertex_count() < 3 || mesh.face_count() < 1)
    throw Error(ErrorCode::kBadValue, what, "an empty surface: nothing to register");
}

std::string percent(double share) { return std::to_string(int(std::lround(100 * share))) + " %"; }

// The four rotations that keep a frame right-handed while flipping its axes' signs: none, or
// two at a time (a turn of the frame by 180 degrees).
constexpr std::array<std::array<double, 3>, 4> kRightHandedFlips{{{1, 1, 1}, {-1, -1, 1}, {-1, 1, -1}, {1, -1, -1}}};

// The eight right-handed poses laying the scan's principal axes on the teeth's (step 1).
std::vector<Eigen::Isometry3d> principal_axis_starts(const TriangleMesh& scan, const TriangleMesh& ct_teeth) {
  const PrincipalFrame from = principal_frame(scan), to = principal_frame(ct_teeth);
  std::vector<Eigen::Isometry3d> starts;
  for (bool swapped : {false, true}) {
    Eigen::Matrix3d target = to.axes;
    if (swapped) {
      target.col(0).swap(target.col(1));
      target.col(2) *= -1;  // still right-handed
    }
    for (const auto& flip : kRightHandedFlips) {
      Eigen::Isometry3d start = Eigen::Isometry3d::Identity();
      start.linear() = target * Eigen::Vector3d(flip[0], flip[1], flip[2]).asDiagonal() * from.axes.transpose();
      start.translation() = to.centroid - start.linear() * from.centroid;
      starts.push_back(start);
    }
  }
  return starts;
}

}  // namespace

std::vector<Eigen::Isometry3d> landmark_starts(const TriangleMesh& scan, const ArchLandmarks& landmarks) {
  require_surface(scan, "dental scan");
  const Eigen::Vector3d across = landmarks.left_molar - landmarks.right_molar;
  const Eigen::Vector3d molars = 0.5 * (landmarks.left_molar + landmarks.right_molar);
  Eigen::Vector3d forward = landmarks.incisor - molars;
  forward -= forward.dot(across.normalized()) * across.normalized();
  if (across.norm() < 20 || forward.norm() < 10)
    throw Error(ErrorCode::kBadValue, "dental landmarks",
                "the incisor and first molars span no arch (molars " + std::to_string(int(across.norm())) +
                    " mm apart, incisor " + std::to_string(int(forward.norm())) + " mm in front of them)");
  Eigen::Matrix3d arch;
  arch.col(0) = across.normalized();
  arch.col(1) = forward.normalized();
  arch.col(2) = arch.col(0).cross(arch.col(1));
  const PrincipalFrame from = principal_frame(scan);
  const Eigen::Vector3d centre = landmarks.incisor + 0.5 * (molars - landmarks.incisor);
  std::vector<Eigen::Isometry3d> starts;
  for (const auto& flip : kRightHandedFlips) {
    Eigen::Isometry3d start = Eigen::Isometry3d::Identity();
    start.linear() = arch * Eigen::Vector3d(flip[0], flip[1], flip[2]).asDiagonal() * from.axes.transpose();
    start.translation() = centre - start.linear() * from.centroid;
    starts.push_back(start);
  }
  return starts;
}

double pose_distance_mm(const TriangleMesh& mesh, const Eigen::Isometry3d& a, const Eigen::Isometry3d& b,
                        const std::vector<int>& vertices) {
  const Eigen::Index count = vertices.empty() ? mesh.vertex_count() : Eigen::Index(vertices.size());
  double sum = 0;
  for (Eigen::Index k = 0; k < count; ++k) {
    const Eigen::Vector3d p = mesh.vertices.row(vertices.empty() ? k : vertices[size_t(k)]).transpose();
    sum += (a * p - b * p).squaredNorm();
  }
  return count == 0 ? 0 : std::sqrt(sum / double(count));
}

ArchRegistration register_arch(const TriangleMesh& scan, const TriangleMesh& ct_teeth,
                               const std::vector<Eigen::Isometry3d>& extra_starts,
                               const ArchRegistrationOptions& options) {
  require_surface(scan, "dental scan");
  require_surface(ct_teeth, "the CT's teeth");
  std::vector<Eigen::Isometry3d> starts = extra_starts;
  if (options.principal_axis_starts)
    for (const auto& start : principal_axis_starts(scan, ct_teeth)) starts.push_back(start);
  if (starts.empty()) throw Error(ErrorCode::kUsage, "dental scan", "no start to register it from");
  const validation::IcpTarget icp_target(ct_teeth);
  const AabbTree tree(ct_teeth);
  const std::vector<int> samples = sampled_vertices(scan, options.max_samples);
  ArchRegistration result;
  for (const auto& start : starts)
    result.candidates.push_back(
        score_on(scan, tree, samples, fit_stage(scan, icp_target, kCoarse, start, options), options));
  // The fine fits from the best coarse ones (the order of the starts breaks ties).
  std::vector<size_t> order(result.candidates.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return result.candidates[a].on_teeth_share > result.candidates[b].on_teeth_share;
  });
  order.resize(std::min(order.size(), kRefinedStarts));
  for (size_t i : order) {
    Eigen::Isometry3d pose = result.candidates[i].transform;
    for (const FitStage& stage : kFine) pose = fit_stage(scan, icp_target, stage, pose, options);
    result.candidates[i] = score_on(scan, tree, samples, pose, options);
  }
  const auto best =
      std::max_element(result.candidates.begin(), result.candidates.end(),
                       [](const ArchFit& a, const ArchFit& b) { return a.on_teeth_share < b.on_teeth_share; });
  result.fit = *best;
  double other = 0;
  for (const auto& candidate : result.candidates)
    if (pose_distance_mm(scan, candidate.transform, best->transform, samples) > options.distinct_mm)
      other = std::max(other, candidate.on_teeth_share);
  result.confidence = best->on_teeth_share > 0 ? 1 - other / best->on_teeth_share : 0;
  if (best->on_teeth_share < options.min_fit_share)
    throw Error(ErrorCode::kProcessing, "dental scan",
                "it does not fit the CT's teeth: at best " + percent(best->on_teeth_share) + " of it lies within " +
                    std::to_string(options.on_teeth_mm).substr(0, 3) + " mm of them (needed " +
                    percent(options.min_fit_share) +
                    "): an arch of another patient, an upper arch given as lower, or a scan not in millimetres?");
  if (result.confidence < options.min_confidence)
    throw Error(ErrorCode::kProcessing, "dental scan",
                "two different poses fit it about as well (" + percent(best->on_teeth_share) + " and " +
                    percent(other) + " of it on the CT's teeth): the registration is ambiguous");
  return result;
}

}  // namespace maxillo::dental
