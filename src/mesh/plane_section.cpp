#include "mesh/plane_section.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <utility>

#include "core/error.h"

namespace maxillo {
namespace {

using EdgeKey = std::pair<int, int>;  // vertex indices, smaller first
EdgeKey key(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

// One face's piece of the cut, between the crossing points on two of its edges. Oriented by the
// face's winding (from the edge where the winding goes down through the plane to the edge where it
// comes back up), so neighbouring faces, which run their shared edge the other way, chain head to tail.
struct Segment {
  EdgeKey from, to;
};

class Section {
 public:
  Section(const TriangleMesh& mesh, const Eigen::Vector3d& point, const Eigen::Vector3d& unit_normal) : mesh_(mesh) {
    side_.resize(size_t(mesh.vertex_count()));
    for (Eigen::Index v = 0; v < mesh.vertex_count(); ++v)
      side_[size_t(v)] = unit_normal.dot(mesh.vertices.row(v).transpose() - point);
    for (Eigen::Index f = 0; f < mesh.face_count(); ++f) add_face(f);
  }

  std::vector<std::vector<Eigen::Vector3d>> polylines() {
    std::vector<std::vector<Eigen::Vector3d>> lines;
    std::set<EdgeKey> ends;  // edges some segment leads to
    for (const auto& s : segments_) ends.insert(s.to);
    // Open lines first: they start at a segment nothing leads to (the mesh's border)...
    for (size_t i = 0; i < segments_.size(); ++i)
      if (!used_[i] && !ends.count(segments_[i].from)) add_line(lines, follow(i), false);
    // ... then what is left closes into loops.
    for (size_t i = 0; i < segments_.size(); ++i)
      if (!used_[i]) add_line(lines, follow(i), true);
    std::stable_sort(lines.begin(), lines.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
    return lines;
  }

 private:
  bool above(int v) const { return side_[size_t(v)] >= 0; }

  void add_face(Eigen::Index f) {
    std::optional<EdgeKey> down, up;
    for (int k = 0; k < 3; ++k) {
      const int a = mesh_.faces(f, k), b = mesh_.faces(f, (k + 1) % 3);
      if (above(a) && !above(b)) down = key(a, b);
      if (!above(a) && above(b)) up = key(a, b);
    }
    if (!down || !up) return;  // the face lies on one side
    outgoing_.emplace(*down, segments_.size());
    segments_.push_back({*down, *up});
    used_.push_back(false);
  }

  Eigen::Vector3d crossing(const EdgeKey& edge) const {
    const double a = side_[size_t(edge.first)], b = side_[size_t(edge.second)];
    const double t = a / (a - b);  // one side >= 0, the other < 0: never 0 / 0
    return mesh_.vertices.row(edge.first).transpose() +
           t * (mesh_.vertices.row(edge.second) - mesh_.vertices.row(edge.first)).transpose();
  }

  // The chain of segments from segment `first` on, as edge keys (first's start, then each end).
  std::vector<EdgeKey> follow(size_t first) {
    std::vector<EdgeKey> chain{segments_[first].from};
    for (std::optional<size_t> at = first; at;) {
      used_[*at] = true;
      chain.push_back(segments_[*at].to);
      at.reset();
      auto [begin, end] = outgoing_.equal_range(chain.back());
      for (auto it = begin; it != end; ++it)
        if (!used_[it->second]) {
          at = it->second;
          break;
        }
    }
    return chain;
  }

  void add_line(std::vector<std::vector<Eigen::Vector3d>>& lines, const std::vector<EdgeKey>& chain, bool loop) const {
    std::vector<Eigen::Vector3d> points;
    for (const auto& edge : chain) {
      const Eigen::Vector3d p = crossing(edge);
      // A cut through a vertex gives the same point on several edges: keep it once.
      if (points.empty() || (p - points.back()).squaredNorm() > 1e-24) points.push_back(p);
    }
    if (loop && points.size() > 1 && (points.front() - points.back()).squaredNorm() > 1e-24)
      points.push_back(points.front());  // a loop broken by a non-manifold edge still closes
    if (points.size() >= 2) lines.push_back(std::move(points));
  }

  const TriangleMesh& mesh_;
  std::vector<double> side_;  // signed distance of each vertex to the plane
  std::vector<Segment> segments_;
  std::vector<bool> used_;
  std::multimap<EdgeKey, size_t> outgoing_;  // segments by the edge they start at
};

}  // namespace

std::vector<std::vector<Eigen::Vector3d>> plane_section(const TriangleMesh& mesh, const Eigen::Vector3d& point,
                                                        const Eigen::Vector3d& normal) {
  if (!(normal.norm() > 0)) throw Error(ErrorCode::kBadValue, "section plane", "the normal is zero");
  Section section(mesh, point, normal.normalized());
  return section.polylines();
}

}  // namespace maxillo
