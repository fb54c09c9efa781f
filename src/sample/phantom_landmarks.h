#pragma once
// The phantom's landmarks (LPS mm), placed by construction on the displaced anatomy:
//   S    centre of the sella turcica pit            N    frontonasal point, anterior bone surface
//   OrR/OrL lowest point of the infraorbital margin (x = -/+33 mm, z = 0)
//   PoR/PoL top of the bony ear canal at its lateral opening (z = 0)
//   ANS/PNS tips of the nasal spines                A    deepest point of the upper alveolar front
//   B    deepest point of the lower alveolar front  Pog  most anterior chin point
//   Gn   chin outline point facing 45 deg antero-inferiorly   Me lowest chin point
//   GoR/GoL gonial angle vertex    ArR/ArL posterior border of the condylar process (ramus outline)
//   U1/L1 incisal edge centre of the patient's right central incisors
//   U6R/U6L/L6R/L6L mesio-buccal cusp tips of the first molars
//   soft tissue on the skin, mid-sagittal: NS (soft nasion, 6 mm in front of N), Prn (pronasale),
//   Sn (subnasale: the bottom of the concavity behind the line Prn-Ls), Ls/Li (labrale superius/inferius), PogS (soft pogonion, 11 mm in front of Pog).
// Right = patient right = -x.
#include "ceph/landmark.h"
#include "sample/phantom_parts.h"

namespace maxillo::sample {

LandmarkSet phantom_landmarks(const PhantomDesign& design, const PartList& parts);

}  // namespace maxillo::sample
