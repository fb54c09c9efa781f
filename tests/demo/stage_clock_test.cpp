// The demo's stage clock: every stage in the order marked, the total their sum.
#include "demo/stage_clock.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace maxillo::demo {
namespace {

TEST(StageClock, KeepsEveryStageAndTheirSum) {
  StageClock clock;
  clock.mark("first");
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  clock.mark("second");
  const Json times = clock.to_json();
  const Json& stages = times.at("stages_seconds");
  ASSERT_EQ(stages.size(), 2u);
  EXPECT_GE(stages.at("second").get<double>(), 0.02);  // it waited 20 ms at least
  EXPECT_GE(stages.at("first").get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(times.at("total_seconds").get<double>(),
                   stages.at("first").get<double>() + stages.at("second").get<double>());
}

}  // namespace
}  // namespace maxillo::demo
