// A study is due once per change, after a quiet period; the clock is passed in.
#include <gtest/gtest.h>

#include "net/stable_studies.h"

namespace maxillo::net {
namespace {

using namespace std::chrono_literals;

TEST(StableStudies, DueOncePerChangeAfterTheQuietPeriod) {
  StableStudies studies(60s);
  const auto t0 = StableStudies::Clock::time_point{} + 1000s;
  EXPECT_TRUE(studies.take_due(t0).empty()) << "nothing received";
  studies.archived("1.2.3", t0);
  studies.archived("1.2.3", t0 + 10s);
  studies.archived("1.2.4", t0 + 5s);
  EXPECT_TRUE(studies.take_due(t0 + 60s).empty()) << "the last instances came 50 and 55 s ago";
  EXPECT_EQ(studies.take_due(t0 + 66s), std::vector<std::string>{"1.2.4"});
  EXPECT_EQ(studies.take_due(t0 + 70s), std::vector<std::string>{"1.2.3"});
  EXPECT_TRUE(studies.take_due(t0 + 500s).empty()) << "done for their current state";
  studies.archived("1.2.3", t0 + 600s);  // a late series
  EXPECT_TRUE(studies.take_due(t0 + 630s).empty());
  EXPECT_EQ(studies.take_due(t0 + 660s), std::vector<std::string>{"1.2.3"});
}

}  // namespace
}  // namespace maxillo::net
