#pragma once
// The landmarks of the midsagittal plane, each read the way the field defines it, in a head frame
// whose origin is sella and whose axes are the patient's (x left, y posterior, z superior, z
// normal to Frankfort): "most anterior" is the smallest y, "lowest" the smallest z.
//
//   N    nasion: the deepest point of the bony concavity between the forehead and the nasal bones
//   ANS  anterior nasal spine: the tip of the spine, the most anterior point of the nasal floor
//   A    subspinale: the most posterior point of the upper alveolar front between ANS and prosthion
//   PNS  posterior nasal spine: the posterior end of the hard palate
//   B    supramentale: the most posterior point of the lower alveolar front between infradentale
//        and pogonion
//   Pog  pogonion: the most anterior point of the bony chin
//   Me   menton: the lowest point of the symphysis
//   Gn   gnathion: the point of the chin's outline midway between Pog and Me (where its outward
//        normal points 45 degrees antero-inferiorly)
//   U1   the incisal tip of the upper central incisor; L1 of the lower
//   NS, Prn, Sn, Ls, Li, PogS: soft-tissue nasion (deepest point of the skin between forehead and
//        nose), pronasale (nose tip, most anterior), subnasale (deepest point between nose and
//        upper lip), labrale superius and inferius (most anterior points of the lips), soft-tissue
//        pogonion (most anterior point of the soft chin)
#include <optional>

#include "landmarking/head_volume.h"
#include "landmarking/profile.h"
#include "landmarking/rule_finding.h"

namespace maxillo::landmarking {

RuleFinding find_nasion(const HeadVolume& v, const Eigen::Vector3d& expected);
// ANS, A and PNS together (A and PNS are read from ANS).
void find_maxillary_midline(const HeadVolume& v, double scale, Findings& found);
// B, Pog, Me and Gn together, in the chin's own middle (a chin to one side: L1 again there).
void find_symphysis(const HeadVolume& v, double scale, Findings& found);
// U1 and L1.
void find_incisors(const HeadVolume& v, double scale, Findings& found);
// L1 alone, its window and its arch's midline `midline_x` mm to the left of the skull's.
void find_lower_incisor(const HeadVolume& v, double scale, double midline_x, Findings& found);
// The chin read without the head frame, as on a lateral cephalogram of a flat chin (one whose
// bulge and concavity a frame pitched by a few degrees would erase): Pog where the line from
// nasion touches the symphysis' front (Downs' facial line), B the deepest point behind the line
// from infradentale (the top of the alveolar front) to that Pog. `alveolar_front` runs upwards
// from below the chin to infradentale; the chin is sought from `lowest_chin_z` to halfway up to
// infradentale. nullopt on too short a profile. find_symphysis reads a flat chin this way.
struct ChinReading {
  ProfilePoint pog, b;
  double b_depth;  // mm behind the line from infradentale to Pog
};
std::optional<ChinReading> chin_from_nasion(const Profile& alveolar_front, const Eigen::Vector3d& nasion,
                                            double lowest_chin_z);
// NS, Prn, Sn, Ls, Li, PogS, from the skin profile (needs N and Me or their expected positions).
void find_soft_tissue_profile(const HeadVolume& v, double scale, Findings& found);

}  // namespace maxillo::landmarking
