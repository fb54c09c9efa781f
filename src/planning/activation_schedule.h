#pragma once
// The activation schedule of the two distractors (thesis ch. 2, 4a, 4b, 5).
//
// Day 0 is the operation. Latency: no activation for latency_days (source: 5 days). Distraction:
// rate_mm_per_day in activations_per_day equal activations (source: 1 mm/day as 2 x 0.5 mm);
// one 360 deg turn of the screw advances it mm_per_turn (TS-MD: 0.5 mm). The turns of a side
// are its activation length over mm_per_turn, rounded to the nearest quarter turn (what a
// patient or parent can count); the delivered length is those turns x mm_per_turn. A side
// activates from day latency_days + 1 until its turns are done, the last day possibly with fewer
// turns; with unequal lengths (midline correction) the shorter side stops earlier. Consolidation
// (the distractors stay as rigid fixation): consolidation_days after the last activation
// (source: 3 months in ch. 4b; about 2 months until callus maturation in ch. 4a).
#include "planning/distraction_vectors.h"

namespace maxillo::planning {

struct ScheduleSettings {
  int latency_days = 5;
  double rate_mm_per_day = 1.0;
  int activations_per_day = 2;
  double mm_per_turn = 0.5;
  int consolidation_days = 84;
};

struct SideSchedule {
  Side side = Side::Right;
  double activation_mm = 0;  // planned
  double turns = 0;          // quarter-turn resolution
  double delivered_mm = 0;   // turns x mm_per_turn
  int distraction_days = 0;
  int first_day = 0;  // first activation day (0 when there is nothing to activate)
  int last_day = 0;   // last activation day
};

struct ActivationSchedule {
  ScheduleSettings settings;
  double turns_per_activation = 0;  // rate / activations_per_day / mm_per_turn
  SideSchedule right, left;
  int distraction_end_day = 0;    // last activation day of either side
  int consolidation_end_day = 0;  // distractor removal at the earliest
};

// Error(kBadValue, "schedule", reason) for a non-positive rate, turn pitch or activation count,
// or a negative latency or consolidation.
void validate(const ScheduleSettings& settings);
ActivationSchedule activation_schedule(double right_mm, double left_mm, const ScheduleSettings& settings = {});

}  // namespace maxillo::planning
