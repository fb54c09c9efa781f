#pragma once
// The phantom's teeth: 14 upper and 14 lower (no third molars), each a crown (enamel) and
// roots (dentine) in the tooth's own frame, placed along elliptical dental arches in the
// occlusal plane. All crowns but the central incisors' stop at the occlusal plane (upper above,
// lower below), so the arches touch at cusp tips without interpenetrating; the central incisors
// overlap vertically (overbite ~2.7 mm) with the uppers labial (overjet ~3 mm), Class I.
#include <vector>

#include "sample/phantom_design.h"

namespace maxillo::sample {

enum class Jaw { kUpper, kLower };

// A dental arch (tooth reference points) as a superellipse quadrant in the axial plane:
// |x / half_width|^n + |(a - centre) / depth|^n = 1, from the midline (a = front) backwards.
// The lower arch is squarer (n = 3) than the upper (n = 2) so that, with adult tooth widths,
// the upper first molar sits ~2 mm distal of the lower one (Class I).
struct ArchShape {
  double front, half_width, depth, exponent;
  double centre() const { return front - depth; }
};
inline constexpr ArchShape kUpperArch{72.3, 29, 42, 2};
inline constexpr ArchShape kLowerArch{68.5, 26, 40, 3};
enum class Side { kRight, kLeft };  // patient right = -x

struct Tooth {
  Jaw jaw;
  Side side;
  int position;          // 1 central incisor .. 7 second molar
  Vector3d origin;       // reference anatomy: incisal edge centre / occlusal centre, LPS mm
  Vector3d mesiodistal;  // unit, pointing distally
  Vector3d buccal;       // unit, pointing labially/buccally
  Vector3d apical;       // unit, from the crown towards the root apex
  Vector3d into_jaw;     // unit occlusal-plane normal pointing from the plane into this jaw
  double width, crown_height, thickness, root_length;
  int roots;
  bool posterior;              // premolars and molars: flat-topped crowns with cusps and fossa
  bool cut_by_occlusal_plane;  // all but the central incisors stay on their side of the plane
};

enum class ToothPart { kCrown, kRoot };

class Dentition {
 public:
  explicit Dentition(const PhantomDesign& design);

  const std::vector<Tooth>& teeth() const { return teeth_; }
  // Inside tests on the displaced anatomy (spec knobs applied), p in LPS mm.
  bool inside(const Tooth& tooth, ToothPart part, const Vector3d& p) const;
  bool inside_upper(const Vector3d& p) const;
  bool inside_lower(const Vector3d& p) const;

  const Tooth& tooth(Jaw jaw, Side side, int position) const;
  // Landmarks on the displaced anatomy.
  Vector3d incisal_edge_centre(Jaw jaw, Side side) const;   // central incisor (U1, L1)
  Vector3d mesiobuccal_cusp_tip(Jaw jaw, Side side) const;  // first molar (U6, L6)
  // The reference-anatomy point that the jaw's displacement carries to p.
  Vector3d reference_of(Jaw jaw, const Vector3d& p) const;
  // Where the jaw's displacement carries a reference-anatomy point (the inverse of reference_of).
  Vector3d displaced(Jaw jaw, const Vector3d& reference) const;

 private:
  bool inside_reference(const Tooth& tooth, ToothPart part, const Vector3d& p) const;

  PhantomDesign design_;
  std::vector<Tooth> teeth_;
};

}  // namespace maxillo::sample
