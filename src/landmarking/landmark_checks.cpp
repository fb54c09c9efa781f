#include "landmarking/landmark_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

#include "landmarking/landmark_template.h"

namespace maxillo::landmarking {
namespace {

constexpr double kMirrorToleranceMm = 5;  // adult asymmetry of paired landmarks stays within a few mm

std::string figure(const char* format, double value) {
  char text[96];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

// Angle at `vertex` between the rays to a and b, in degrees.
double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& vertex, const Eigen::Vector3d& b) {
  const Eigen::Vector3d u = (a - vertex).normalized(), w = (b - vertex).normalized();
  return std::acos(std::clamp(u.dot(w), -1.0, 1.0)) * 180 / std::numbers::pi;
}

class Checker {
 public:
  Checker(const FramePoints& points, double scale) : points_(points), scale_(scale) {}

  bool has(std::initializer_list<const char*> labels) const {
    for (const char* l : labels)
      if (!points_.count(l)) return false;
    return true;
  }
  const Eigen::Vector3d& at(const char* label) const { return points_.at(label); }

  void add(std::initializer_list<const char*> labels, CheckOutcome outcome) {
    for (const char* l : labels) result_[l].push_back(outcome);
  }
  // `a` lies beyond `b` along `axis` (0 x, 1 y, 2 z) by at least `margin` in direction `sign`.
  void order(const char* name, const char* a, const char* b, int axis, int sign, double margin) {
    if (!has({a, b})) return;
    const double by = sign * (at(a)[axis] - at(b)[axis]);
    add({a, b}, {std::string("order: ") + name, by >= margin, figure("%.1f mm", by)});
  }
  void range(const char* name, std::initializer_list<const char*> labels, double value, double lo, double hi,
             const char* unit) {
    char detail[120];
    std::snprintf(detail, sizeof detail, "%.1f %s (adult range taken as %.0f to %.0f)", value, unit, lo, hi);
    add(labels, {std::string("range: ") + name, value >= lo && value <= hi, detail});
  }
  // The pair mirrored about the sagittal plane at `midline_x` (the frame's x = 0 is the skull's
  // midplane), `midline` naming another plane in the check's detail.
  void mirror(const char* pair, double midline_x = 0, const char* midline = nullptr) {
    const std::string r = std::string(pair) + "R", l = std::string(pair) + "L";
    if (!points_.count(r) || !points_.count(l)) return;
    Eigen::Vector3d mirrored = points_.at(l);
    mirrored.x() = 2 * midline_x - mirrored.x();
    const double gap = (mirrored - points_.at(r)).norm();
    std::string detail = figure("%.1f mm from the mirror image", gap);
    if (midline) detail += " about " + std::string(midline) + figure(", %.1f mm from the skull's", midline_x);
    add({r.c_str(), l.c_str()}, {"mirror", gap <= kMirrorToleranceMm, detail});
  }
  double scale() const { return scale_; }
  std::map<std::string, std::vector<CheckOutcome>> take() { return std::move(result_); }

 private:
  const FramePoints& points_;
  double scale_;
  std::map<std::string, std::vector<CheckOutcome>> result_;
};

// The lower arch's midline across the skull's, and what it was read from. A chin deviated to one
// side carries the lower arch with it: the lower molars mirror about the mandible's own midline,
// not the skull's, or every asymmetric mandible would flag correct molars. The mean x of the
// mandible's midline points found (B, Pog, Me); without them (a cone-beam field whose floor cut
// the chin), the lower central incisors' contact, half a crown's width to the left of L1 (the
// right central incisor: L1 itself, taken for the midline, flagged good molars); none without.
struct ArchMidline {
  double x;
  const char* read_from;
};
std::optional<ArchMidline> lower_arch_midline(const Checker& c) {
  double sum = 0;
  int count = 0;
  for (const char* label : {"B", "Pog", "Me"})
    if (c.has({label})) sum += c.at(label).x(), ++count;
  if (count > 0) return ArchMidline{sum / count, "the mandible's midline"};
  if (c.has({"L1"})) return ArchMidline{c.at("L1").x() + kLowerCentralWidthMm / 2, "the lower incisors' midline"};
  return std::nullopt;
}

void mirrored_pairs(Checker& c) {
  // The rami (Go, Ar) stay in place when the chin deviates: they mirror about the skull's plane.
  for (const char* pair : {"Or", "Po", "Go", "Ar", "U6"}) c.mirror(pair);
  if (const auto midline = lower_arch_midline(c))
    c.mirror("L6", midline->x, midline->read_from);
  else
    c.mirror("L6");
}

void anatomical_order(Checker& c) {
  const double s = c.scale();
  c.order("N anterior to S", "S", "N", 1, +1, 40 * s);
  c.order("ANS anterior to PNS", "PNS", "ANS", 1, +1, 30 * s);
  c.order("Me below Pog", "Pog", "Me", 2, +1, 2);
  c.order("B above Pog", "B", "Pog", 2, +1, 3);
  c.order("A below ANS", "ANS", "A", 2, +1, 1);
  c.order("ANS below N", "N", "ANS", 2, +1, 30 * s);
  c.order("Or anterior to Po (left)", "PoL", "OrL", 1, +1, 40 * s);
  c.order("Or anterior to Po (right)", "PoR", "OrR", 1, +1, 40 * s);
  c.order("Prn anterior to ANS", "ANS", "Prn", 1, +1, 8);
  c.order("NS anterior to N", "N", "NS", 1, +1, 1);
  c.order("PogS anterior to Pog", "Pog", "PogS", 1, +1, 2);
  c.order("Ls anterior to A", "A", "Ls", 1, +1, 5);
  c.order("Go below Ar (left)", "ArL", "GoL", 2, +1, 15 * s);
  c.order("Go below Ar (right)", "ArR", "GoR", 2, +1, 15 * s);
  // The bite: upper incisor in front of the lower one, unless the jaws say Class III.
  if (c.has({"U1", "L1", "S", "N", "A", "B"})) {
    const double overjet = c.at("L1").y() - c.at("U1").y();
    const double anb = angle_deg(c.at("S"), c.at("N"), c.at("A")) - angle_deg(c.at("S"), c.at("N"), c.at("B"));
    const bool consistent = overjet > 0 || anb < 1;
    c.add({"U1", "L1"}, {"order: U1 in front of L1 as the bite says", consistent,
                         figure("overjet %.1f mm", overjet) + figure(", ANB %.1f deg", anb)});
  }
}

void adult_ranges(Checker& c) {
  if (c.has({"S", "N"})) c.range("S-N", {"S", "N"}, (c.at("N") - c.at("S")).norm(), 58, 88, "mm");
  if (c.has({"ANS", "Me"})) c.range("ANS-Me", {"ANS", "Me"}, (c.at("Me") - c.at("ANS")).norm(), 48, 90, "mm");
  if (c.has({"ANS", "PNS"})) c.range("ANS-PNS", {"ANS", "PNS"}, (c.at("PNS") - c.at("ANS")).norm(), 38, 65, "mm");
  if (c.has({"S", "N", "A"})) c.range("SNA", {"A"}, angle_deg(c.at("S"), c.at("N"), c.at("A")), 70, 94, "deg");
  if (c.has({"S", "N", "B"})) c.range("SNB", {"B"}, angle_deg(c.at("S"), c.at("N"), c.at("B")), 68, 92, "deg");
  for (const char* side : {"L", "R"}) {
    const std::string ar = std::string("Ar") + side, go = std::string("Go") + side;
    if (c.has({ar.c_str(), go.c_str(), "Me"}))
      c.range("gonial angle", {ar.c_str(), go.c_str()}, angle_deg(c.at(ar.c_str()), c.at(go.c_str()), c.at("Me")), 105,
              145, "deg");
  }
}

}  // namespace

CheckOutcome second_start_check(const Eigen::Vector3d& first, const std::optional<Eigen::Vector3d>& again) {
  if (!again) return {"second start", false, "not found again from a second start"};
  const double distance = (*again - first).norm();
  return {
      "second start", distance <= kSecondStartToleranceMm,
      figure("found %.1f mm away from a second start", distance) + figure(" (limit %.1f mm)", kSecondStartToleranceMm)};
}

std::map<std::string, std::vector<CheckOutcome>> check_landmarks(const FramePoints& points, double scale) {
  Checker c(points, scale);
  mirrored_pairs(c);
  anatomical_order(c);
  adult_ranges(c);
  return c.take();
}

}  // namespace maxillo::landmarking
