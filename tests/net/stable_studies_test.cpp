// A study is due once per change, after a quiet period; the clock is passed in.
#include <gtest/gtest.h>

#include "core/temporary_folder.h"
#include "net/pending_studies.h"
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

// What is owed survives the object (a restart); a study that changed again after its action was
// taken stays owed, one that did not is removed.
TEST(PendingStudies, KeepsWhatIsOwedAcrossRestartsAndRemovesOnlySettledStudies) {
  TemporaryFolder folder("pending-studies");
  const auto file = folder / "serve" / "pending";
  {
    PendingStudies pending(file);
    EXPECT_TRUE(pending.studies().empty());
    pending.add("1.2.3");
    pending.add("1.2.4");
    pending.add("1.2.3");
  }
  PendingStudies reopened(file);
  EXPECT_EQ(reopened.studies(), (std::vector<std::string>{"1.2.3", "1.2.4"}));
  StableStudies stable(0s);
  const auto now = StableStudies::Clock::now();
  stable.archived("1.2.3", now);
  stable.archived("1.2.4", now);
  ASSERT_EQ(stable.take_due(now).size(), 2u);
  stable.archived("1.2.4", now + 1s);  // changed again while its action ran
  for (const std::string study : {"1.2.3", "1.2.4"})
    reopened.remove_if_settled(study, [&] { return stable.changed_since_due(study); });
  EXPECT_EQ(PendingStudies(file).studies(), (std::vector<std::string>{"1.2.4"}));
}

}  // namespace
}  // namespace maxillo::net
