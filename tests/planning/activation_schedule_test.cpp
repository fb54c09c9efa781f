// The activation schedule against hand-counted numbers.
#include <gtest/gtest.h>

#include "core/error.h"
#include "planning/activation_schedule.h"

namespace maxillo::planning {
namespace {

TEST(ActivationSchedule, TenMillimetresAtTheSourceProtocol) {
  const ActivationSchedule s = activation_schedule(10, 10);
  EXPECT_DOUBLE_EQ(s.turns_per_activation, 1);  // 0.5 mm twice a day, 0.5 mm per turn
  EXPECT_DOUBLE_EQ(s.right.turns, 20);
  EXPECT_EQ(s.right.distraction_days, 10);
  EXPECT_EQ(s.right.first_day, 6);  // after 5 days of latency
  EXPECT_EQ(s.right.last_day, 15);
  EXPECT_EQ(s.distraction_end_day, 15);
  EXPECT_EQ(s.consolidation_end_day, 15 + 84);
}

TEST(ActivationSchedule, TurnsRoundToAQuarterAndTheLastDayIsPartial) {
  const ActivationSchedule s = activation_schedule(10.44, 7.3);
  EXPECT_DOUBLE_EQ(s.right.turns, 21);  // 20.88 -> 21
  EXPECT_DOUBLE_EQ(s.right.delivered_mm, 10.5);
  EXPECT_EQ(s.right.distraction_days, 11);  // 10 full days + one turn
  EXPECT_DOUBLE_EQ(s.left.turns, 14.5);     // 14.6 -> 14.5
  EXPECT_EQ(s.left.distraction_days, 8);
  EXPECT_EQ(s.left.last_day, 13);
  EXPECT_EQ(s.distraction_end_day, 16);
}

TEST(ActivationSchedule, OtherRatesAndPitches) {
  const ActivationSchedule s = activation_schedule(12, 12,
                                                   {.latency_days = 7,
                                                    .rate_mm_per_day = 2,
                                                    .activations_per_day = 4,
                                                    .mm_per_turn = 0.25,
                                                    .consolidation_days = 60});
  EXPECT_DOUBLE_EQ(s.turns_per_activation, 2);
  EXPECT_DOUBLE_EQ(s.left.turns, 48);
  EXPECT_EQ(s.left.distraction_days, 6);
  EXPECT_EQ(s.left.first_day, 8);
  EXPECT_EQ(s.consolidation_end_day, 13 + 60);
}

TEST(ActivationSchedule, RefusesImpossibleSettings) {
  EXPECT_THROW(activation_schedule(10, 10, {.rate_mm_per_day = 0}), Error);
  EXPECT_THROW(activation_schedule(10, 10, {.activations_per_day = 0}), Error);
  EXPECT_THROW(activation_schedule(10, 10, {.latency_days = -1}), Error);
}

}  // namespace
}  // namespace maxillo::planning
