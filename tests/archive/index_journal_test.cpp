// The index journal's own rules (index_journal.h): an entry is pending until its transaction
// commits, and no entry is ever written over.
#include <gtest/gtest.h>

#include <algorithm>

#include "archive/index_journal.h"
#include "archive_fixture.h"
#include "core/error.h"
#include "support/error_of.h"

namespace maxillo {
namespace {

using testing::TemporaryFolder;

JournalEntry entry(int64_t sequence, const std::string& operation) {
  JournalEntry made;
  made.sequence = sequence;
  made.at = "2026-11-27T10:00:00Z";
  made.operation = operation;
  made.program_version = "test";
  made.rows.push_back({"patients", Json{{"id", sequence}, {"patient_id", "P" + std::to_string(sequence)}}});
  return made;
}

using testing::error_of;

TEST(IndexJournal, AnEntryIsPendingUntilMarkedCommitted) {
  TemporaryFolder folder;
  IndexJournal journal(folder / "journal");
  journal.write_pending(entry(1, "import"));
  EXPECT_TRUE(journal.has_pending(1));
  EXPECT_FALSE(journal.has(1));
  EXPECT_TRUE(journal.sequences().empty());  // readers see committed entries only
  journal.mark_committed(1);
  EXPECT_TRUE(journal.has(1));
  EXPECT_FALSE(journal.has_pending(1));
  EXPECT_EQ(journal.sequences(), std::vector<int64_t>{1});
  EXPECT_EQ(journal.read(1).operation, "import");
}

TEST(IndexJournal, ACommittedEntryIsNeverWrittenOver) {
  TemporaryFolder folder;
  IndexJournal journal(folder / "journal");
  journal.write_pending(entry(1, "import"));
  journal.mark_committed(1);
  const std::string before = testing::read_text(journal.path_of(1));

  // A writer whose index is at 0 while entry 1 is committed: its index is behind its journal.
  EXPECT_NE(error_of([&] { journal.write_pending(entry(1, "role")); }, ErrorCode::kIndexDamaged).find("behind"),
            std::string::npos);
  EXPECT_FALSE(journal.has_pending(1));
  // A copy of another entry of that number (a migration into the wrong archive) is refused.
  error_of([&] { journal.write_committed(entry(1, "role")); }, ErrorCode::kConflict);
  EXPECT_EQ(testing::read_text(journal.path_of(1)), before);
  // The same entry copied again (a resumed migration) changes nothing.
  EXPECT_NO_THROW(journal.write_committed(journal.read(1)));
  EXPECT_EQ(testing::read_text(journal.path_of(1)), before);
}

TEST(IndexJournal, AMarkDoneByAnotherProcessIsNoError) {
  TemporaryFolder folder;
  IndexJournal journal(folder / "journal");
  journal.write_pending(entry(1, "import"));
  EXPECT_TRUE(journal.settle(1));  // the next open, while the writer is between COMMIT and its mark
  EXPECT_NO_THROW(journal.mark_committed(1));
  EXPECT_TRUE(journal.has(1));
}

TEST(IndexJournal, AnAbortedPendingEntryIsKeptAsideEachTime) {
  TemporaryFolder folder;
  IndexJournal journal(folder / "journal");
  journal.write_pending(entry(1, "first killed"));
  journal.write_pending(entry(1, "second killed"));  // the first is set aside, not replaced
  journal.write_pending(entry(1, "committed"));
  journal.mark_committed(1);
  std::vector<std::string> kept;
  for (const auto& file : std::filesystem::directory_iterator(journal.folder() / "aborted"))
    kept.push_back(testing::read_text(file.path()));
  std::sort(kept.begin(), kept.end());
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_NE(kept[0].find("first killed"), std::string::npos);
  EXPECT_NE(kept[1].find("second killed"), std::string::npos);
  EXPECT_EQ(journal.read(1).operation, "committed");
}

}  // namespace
}  // namespace maxillo
