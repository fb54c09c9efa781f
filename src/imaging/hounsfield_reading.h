#pragma once
// A scan's grey values read as Hounsfield units, for every step whose thresholds are in HU (the
// tissue segmentation, the skin and bone surfaces, the landmarks). A CT whose values are HU as
// stored is read as it is. A cone-beam scan (or raw CT numbers) is read through what the scan
// itself shows: its cupping undone (cupping_correction.h), then its air and soft-tissue modes
// mapped to -1000 and 40 HU (grey_calibration.h); the scanner's padding outside its field
// becomes air. The thresholds then mean in HU what they mean on a CT, and the reading says which
// grey values they fell on.
#include <optional>
#include <string>

#include "core/volume.h"
#include "imaging/grey_calibration.h"

namespace maxillo {

struct GreyReading {
  GreyCalibration grey;      // of the scan after its cupping was undone
  double cupping_depth = 0;  // the share of soft tissue's level lost on the axis, undone (0: none)

  // The values are HU as stored and no cupping was undone: the scan is used as it is.
  bool hounsfield_as_stored() const { return cupping_depth == 0 && grey.is_hounsfield(); }
  // One line for a person: the calibration, the cupping undone, and where `hu` threshold falls.
  std::string describe() const;
  // The grey value a threshold in HU falls on (at the field's rim, where no cupping was undone).
  double grey_of(double hu) const { return grey.from_hu(hu); }
};

// How to read `scan` as HU. `uncupped`, when given, receives the scan with its cupping undone
// if it had a significant one (left untouched otherwise). Deterministic.
GreyReading read_grey_values(const Volume& scan, Volume* uncupped = nullptr);

// The scan's values in HU (clamped to int16, padding to -1000), or nullopt when they are HU as
// stored (use the scan itself: no copy). `reading` receives how the scan was read.
std::optional<Volume> in_hounsfield_units(const Volume& scan, GreyReading* reading = nullptr);
// The same for a scan the caller gives up: returned as it is when its values are HU as stored.
Volume as_hounsfield_units(Volume scan, GreyReading* reading = nullptr);

}  // namespace maxillo
