#include "ceph/cephalometric_analysis.h"

#include <cstdio>
#include <functional>
#include <initializer_list>

#include "ceph/cephalometric_measures.h"
#include "core/error.h"

namespace maxillo::ceph {
namespace {

using Points = std::vector<Eigen::Vector2d>;

// Distinct anatomical points lie millimetres apart; closer than this, an angle or line through
// them is noise, and at zero distance undefined: the landmark set is wrong, not the measure.
constexpr double kCoincidentMm = 0.5;

void require_apart(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const std::string& a_label,
                   const std::string& b_label) {
  const double distance = (a - b).norm();
  if (!(distance >= kCoincidentMm)) {
    char apart[32];
    std::snprintf(apart, sizeof apart, "%.2f", distance);
    throw Error(ErrorCode::kBadValue, "landmarks",
                a_label + " and " + b_label + " coincide (" + apart +
                    " mm apart in the sagittal plane): " + "no measurement can use both");
  }
}

// The points of `labels`, or the reason they are not all there. Points that coincide are an
// input error (Error kBadValue naming them).
std::optional<Points> gather(const SagittalLandmarks& set, std::initializer_list<const char*> labels,
                             std::string& reason) {
  Points points;
  std::string missing;
  for (const char* label : labels) {
    if (auto p = set.find(label))
      points.push_back(*p);
    else
      missing += (missing.empty() ? "" : ", ") + std::string(label);
  }
  if (!missing.empty()) {
    reason = "missing landmark(s): " + missing;
    return std::nullopt;
  }
  const auto* label = labels.begin();
  for (size_t i = 0; i < points.size(); ++i)
    for (size_t j = i + 1; j < points.size(); ++j) require_apart(points[i], points[j], label[i], label[j]);
  return points;
}

struct OcclusalLine {
  Eigen::Vector2d posterior, anterior;
  std::string description;
};

std::optional<Eigen::Vector2d> midpoint(const SagittalLandmarks& set, const char* upper, const char* lower) {
  auto u = set.find(upper), l = set.find(lower);
  if (!u || !l) return std::nullopt;
  return (*u + *l) / 2;
}

std::optional<OcclusalLine> occlusal_line_points(const SagittalLandmarks& set, std::string& reason);

std::optional<OcclusalLine> occlusal_line(const SagittalLandmarks& set, std::string& reason) {
  auto line = occlusal_line_points(set, reason);
  if (line) require_apart(line->posterior, line->anterior, "the occlusal line's posterior point", "its anterior point");
  return line;
}

std::optional<OcclusalLine> occlusal_line_points(const SagittalLandmarks& set, std::string& reason) {
  if (auto p = set.find("OccP"), a = set.find("OccA"); p && a)
    return OcclusalLine{*p, *a, "occlusal line OccP-OccA (traced)"};
  auto molars = midpoint(set, "U6", "L6");
  if (!molars) {
    reason = "missing landmark(s) of the occlusal plane: U6 and L6 (first molars) or OccP/OccA";
    return std::nullopt;
  }
  if (auto premolars = midpoint(set, "U4", "L4"))
    return OcclusalLine{*molars, *premolars, "functional occlusal plane (U6/L6 - U4/L4 midpoints)"};
  if (auto premolars = midpoint(set, "U5", "L5"))
    return OcclusalLine{*molars, *premolars, "functional occlusal plane (U6/L6 - U5/L5 midpoints)"};
  if (auto incisors = midpoint(set, "U1", "L1"))
    return OcclusalLine{*molars, *incisors, "occlusal plane through molar and incisor overlap (U6/L6 - U1/L1)"};
  reason = "missing landmark(s) of the occlusal plane: U4/L4, U5/L5 or U1/L1 besides U6/L6";
  return std::nullopt;
}

Measurement make(const char* id, const char* name, const char* unit) {
  Measurement m;
  m.id = id;
  m.name = name;
  m.unit = unit;
  return m;
}

void set_value(Measurement& m, double value, Sex sex) {
  m.value = value;
  m.norm = norm_for(m.id, sex);
  if (m.norm) m.deviation = deviation_of(value, *m.norm);
}

void add_frame_coordinates(std::vector<Measurement>& out, const SagittalLandmarks& set, const char* label, Sex sex) {
  Measurement x = make("", "", "mm"), y = make("", "", "mm");
  x.id = std::string(label) + "_X";
  y.id = std::string(label) + "_Y";
  x.name = std::string(label) + " sagittal (X, + anterior)";
  y.name = std::string(label) + " vertical (Y, + inferior)";
  std::string reason;
  if (auto p = gather(set, {"S", "N", label}, reason)) {
    auto xy = in_nasion_frame(nasion_frame((*p)[0], (*p)[1]), (*p)[2]);
    set_value(x, xy.x(), sex);
    set_value(y, xy.y(), sex);
  } else {
    x.not_available_reason = y.not_available_reason = reason;
  }
  out.push_back(x);
  out.push_back(y);
}

}  // namespace

const Measurement* CephalometricAnalysis::find(const std::string& id) const {
  for (const auto& m : measurements)
    if (m.id == id) return &m;
  return nullptr;
}

std::optional<double> CephalometricAnalysis::value(const std::string& id) const {
  const auto* m = find(id);
  return m ? m->value : std::nullopt;
}

const std::vector<std::string>& measurement_ids() {
  static const std::vector<std::string> ids = {"SNA",   "SNB",   "ANB",  "Wits", "ANS_X", "ANS_Y",
                                               "PNS_X", "PNS_Y", "Si_X", "Si_Y", "alpha"};
  return ids;
}

CephalometricAnalysis analyse(const SagittalLandmarks& set, Sex sex) {
  CephalometricAnalysis result;
  result.frame = set.frame;
  auto& out = result.measurements;
  std::string reason;

  auto sna = make("SNA", "SNA angle", "deg"), snb = make("SNB", "SNB angle", "deg"),
       anb = make("ANB", "ANB angle (SNA - SNB)", "deg");
  if (auto p = gather(set, {"S", "N", "A"}, reason))
    set_value(sna, sna_deg((*p)[0], (*p)[1], (*p)[2]), sex);
  else
    sna.not_available_reason = reason;
  if (auto p = gather(set, {"S", "N", "B"}, reason))
    set_value(snb, snb_deg((*p)[0], (*p)[1], (*p)[2]), sex);
  else
    snb.not_available_reason = reason;
  if (auto p = gather(set, {"S", "N", "A", "B"}, reason))
    set_value(anb, anb_deg((*p)[0], (*p)[1], (*p)[2], (*p)[3]), sex);
  else
    anb.not_available_reason = reason;
  out.insert(out.end(), {sna, snb, anb});

  auto wits = make("Wits", "Wits appraisal (AO - BO, + Class II)", "mm");
  if (auto ab = gather(set, {"A", "B"}, reason)) {
    if (auto line = occlusal_line(set, reason)) {
      set_value(wits, wits_mm((*ab)[0], (*ab)[1], line->posterior, line->anterior), sex);
      wits.note = line->description;
    } else {
      wits.not_available_reason = reason;
    }
  } else {
    wits.not_available_reason = reason;
  }
  out.push_back(wits);

  for (const char* label : {"ANS", "PNS", "Si"}) add_frame_coordinates(out, set, label, sex);

  auto alpha = make("alpha", "palatal plane angle alpha (ANS-PNS / Y, + upward)", "deg");
  if (auto p = gather(set, {"S", "N", "ANS", "PNS"}, reason))
    set_value(alpha, palatal_angle_alpha_deg(nasion_frame((*p)[0], (*p)[1]), (*p)[2], (*p)[3]), sex);
  else
    alpha.not_available_reason = reason;
  out.push_back(alpha);
  return result;
}

}  // namespace maxillo::ceph
