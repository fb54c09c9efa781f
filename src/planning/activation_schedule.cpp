#include "planning/activation_schedule.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"

namespace maxillo::planning {
namespace {

SideSchedule side_schedule(Side side, double activation_mm, const ScheduleSettings& settings) {
  SideSchedule s;
  s.side = side;
  s.activation_mm = activation_mm;
  s.turns = std::round(activation_mm / settings.mm_per_turn * 4) / 4;
  s.delivered_mm = s.turns * settings.mm_per_turn;
  if (s.delivered_mm <= 0) return s;
  // Whole days at the full rate, plus one partial day for what is left (1e-9: 10.0 / 1.0 is 10 days).
  s.distraction_days = static_cast<int>(std::ceil(s.delivered_mm / settings.rate_mm_per_day - 1e-9));
  s.first_day = settings.latency_days + 1;
  s.last_day = settings.latency_days + s.distraction_days;
  return s;
}

}  // namespace

void validate(const ScheduleSettings& settings) {
  auto fail = [](const std::string& reason) { throw Error(ErrorCode::kBadValue, "schedule", reason); };
  if (!(settings.rate_mm_per_day > 0)) fail("rate_mm_per_day must be positive");
  if (!(settings.mm_per_turn > 0)) fail("mm_per_turn must be positive");
  if (settings.activations_per_day < 1) fail("activations_per_day must be at least 1");
  if (settings.latency_days < 0) fail("latency_days must not be negative");
  if (settings.consolidation_days < 0) fail("consolidation_days must not be negative");
}

ActivationSchedule activation_schedule(double right_mm, double left_mm, const ScheduleSettings& settings) {
  validate(settings);
  ActivationSchedule schedule;
  schedule.settings = settings;
  schedule.turns_per_activation = settings.rate_mm_per_day / settings.activations_per_day / settings.mm_per_turn;
  schedule.right = side_schedule(Side::Right, right_mm, settings);
  schedule.left = side_schedule(Side::Left, left_mm, settings);
  schedule.distraction_end_day = std::max({settings.latency_days, schedule.right.last_day, schedule.left.last_day});
  schedule.consolidation_end_day = schedule.distraction_end_day + settings.consolidation_days;
  return schedule;
}

}  // namespace maxillo::planning
