#include "landmarking/landmark_template.h"

#include <map>
#include <stdexcept>

namespace maxillo::landmarking {
namespace {

// Left side for bilateral points (mirrored for the right).
const std::map<std::string, Eigen::Vector3d>& table() {
  static const std::map<std::string, Eigen::Vector3d> positions = {
      {"S", {0, 0, 0}},
      {"N", {0, -69.5, 8.5}},
      {"Or", {33, -57, -20}},
      {"Po", {62, 20, -20}},
      {"A", {0, -68.5, -49.5}},
      {"B", {0, -64.5, -86.3}},
      {"ANS", {0, -72.5, -44}},
      {"PNS", {0, -19.5, -45}},
      {"Pog", {0, -67.5, -98.3}},
      {"Me", {0, -60, -111.8}},
      {"Gn", {0, -63.6, -110.1}},
      {"Go", {47, 7, -76}},
      {"Ar", {50, 12.2, -26}},
      {"U1", {-4.2, -71.9, -72.1}},
      {"L1", {-2.5, -68.5, -69.4}},
      {"U6", {29.1, -48.5, -67.7}},
      {"L6", {27.2, -50.6, -68}},
      {"Prn", {0, -99, -35}},
      {"Sn", {0, -82, -46}},
      {"Ls", {0, -86.5, -63}},
      {"Li", {0, -85, -77}},
      {"PogS", {0, -78.5, -98.3}},
      {"NS", {0, -75.5, 8.5}},
  };
  return positions;
}

}  // namespace

const std::vector<std::string>& detected_labels() {
  static const std::vector<std::string> labels = {"S",   "N",   "OrR", "OrL", "PoR", "PoL", "A",   "B",    "ANS", "PNS",
                                                  "Pog", "Me",  "Gn",  "GoR", "GoL", "ArR", "ArL", "U1",   "L1",  "U6R",
                                                  "U6L", "L6R", "L6L", "Prn", "Sn",  "Ls",  "Li",  "PogS", "NS"};
  return labels;
}

Eigen::Vector3d expected_position(const std::string& label, double scale) {
  const auto& positions = table();
  if (auto it = positions.find(label); it != positions.end()) return scale * it->second;
  // A bilateral label: its side's suffix.
  const std::string base = label.substr(0, label.size() - 1);
  const auto it = positions.find(base);
  if (it == positions.end() || (label.back() != 'R' && label.back() != 'L'))
    throw std::invalid_argument("no template position for landmark " + label);
  Eigen::Vector3d p = scale * it->second;
  if (label.back() == 'R') p.x() = -p.x();
  return p;
}

}  // namespace maxillo::landmarking
