#pragma once
// Another patient from a Patient ID: the phantom's anatomy, its pose in the scanner and the
// scanner's noise drawn from the ID, so that a detector can be tested on many different heads
// whose landmarks are known (the generator places them by construction, then moves them with
// the head). The same ID gives the same patient on every machine: the draws come from a
// SHA-256 of the ID through mt19937_64, whose output the C++ standard fixes.
//
// What varies, uniformly within these ranges:
//   size         the head scaled by 0.92-1.08 (S-N 64-76 mm);
//   jaws         maxilla -3..+3 mm and mandible -6..+6 mm forward: ANB from about -4 to +7 deg,
//                skeletal Class I, II and III;
//   pose         turned up to 15 deg about each axis (yaw, pitch, roll) and shifted up to 15 mm
//                along each, voxelised in that pose (the voxels are not aligned with the head);
//   noise        5-30 HU (CT) or 20-50 HU (cone-beam);
//   cone-beam    (when asked for) grey values 0.5-1.5 per HU with air anywhere from -1000 to
//                +500, cupping 5-20 %, metal streaks of 200-500 HU, a cylinder 75-90 mm in
//                radius whose top lies 25-60 mm above Frankfort (above the orbits, sometimes
//                below sella) and whose axis lies 20-40 mm in front of the porions (the ears often
//                outside), padded with air's grey value or 200 below it.
//   asymmetry    the mandibular body and chin 0-3 mm to one side, the rami in place (a chin
//                deviation; 4 mm is where published series start calling a face asymmetric).
// Not varied (yet): facial height and the mandibular angle, which need the design's own knobs to
// keep the landmark definitions exact.
#include <string>
#include <string_view>

#include "sample/phantom.h"

namespace maxillo {

enum class ScannerKind { kCt, kConeBeam };

// The phantom spec of the patient with this ID, at the given spacing.
PhantomSpec varied_phantom_spec(std::string_view patient_id, ScannerKind scanner, double spacing_mm);

// One line on what was drawn: "scale 1.03, maxilla +1.2 mm, mandible -3.4 mm, turned (4, -11, 7) deg, ...".
std::string describe_variation(const PhantomSpec& spec);

}  // namespace maxillo
