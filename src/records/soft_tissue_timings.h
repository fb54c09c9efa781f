#pragma once
// The seconds each stage of a face prediction took (soft_tissue_prediction.h), as the
// simulation's summary stores them (simulation_summary.h).

namespace maxillo::records {

struct SoftTissueTimings {
  double region = 0, meshing = 0, attachment = 0, assembly = 0, solve = 0, mapping = 0;
  double total() const { return region + meshing + attachment + assembly + solve + mapping; }
};

}  // namespace maxillo::records
