// Reads of many cases or series at once (the nightly scan's): the same records as reading each
// alone, whatever the number of ids, on both index engines.
#include <gtest/gtest.h>

#include <sstream>

#include "archive/archive.h"
#include "archive/synthetic_index.h"
#include "support/temporary_folder.h"
#include "support/test_archive.h"

namespace maxillo {
namespace {

using testing::TemporaryFolder;

// Every field a case's contents hold, in their order: equal texts, equal contents.
std::string describe(const CaseContents& c) {
  std::ostringstream out;
  out << "case " << c.record.id << " " << c.record.patient << " " << c.record.label << " " << c.record.created_at
      << "; patient " << c.patient.id << " " << c.patient.patient_id << " " << c.patient.study_count << "; studies";
  for (const auto& s : c.studies) out << " " << s.id << "/" << s.study_uid << "/" << s.date << "/" << s.series_count;
  out << "; series";
  for (const auto& m : c.series) out << " " << m.series.id << "/" << m.role << "/" << m.series.instance_count;
  return out.str();
}

std::string describe(const std::vector<ArtefactRecord>& artefacts) {
  std::ostringstream out;
  for (const auto& a : artefacts) out << a.id << "/" << a.case_id << "/" << a.kind << "/" << a.object_sha256 << " ";
  return out.str();
}

// 600 cases (1,200 series), asked for among 5,000 ids: more than one IN list takes (4,096), so
// the reads come in chunks, the last one padded.
class BatchReads : public ::testing::Test {
 protected:
  void SetUp() override {
    fill_synthetic_index(testing::archive_at(folder_ / "archive"), {600, 2400});
    archive_.emplace(Archive::open(testing::archive_at(folder_ / "archive")));
    for (const auto& c : archive_->cases()) case_ids_.push_back(c.id);
  }
  TemporaryFolder folder_;
  std::optional<Archive> archive_;
  std::vector<int64_t> case_ids_;
};

TEST_F(BatchReads, ManyCasesContentsAreEachCasesOwnAndMissingIdsAreLeftOut) {
  ASSERT_EQ(case_ids_.size(), 600u);
  std::vector<int64_t> asked;
  for (int64_t id = 1; id <= 5000; ++id) asked.push_back(id);  // most name no case
  asked.push_back(case_ids_.front());                          // asked twice
  const auto contents = archive_->case_contents(asked);
  ASSERT_EQ(contents.size(), 600u);
  for (int64_t id : case_ids_) {
    const auto alone = archive_->case_contents(id);
    ASSERT_EQ(alone.studies.size(), 1u);  // both series are in one study: listed once
    ASSERT_EQ(alone.series.size(), 2u);
    EXPECT_EQ(describe(contents.at(id)), describe(alone));
  }
  EXPECT_THROW(archive_->case_contents(case_ids_.back() + 1000), Error);
}

TEST_F(BatchReads, ManyCasesArtefactsAreEachCasesOwnInOrder) {
  for (size_t n = 0; n < case_ids_.size(); n += 3)
    for (int k = 0; k < 2; ++k)
      archive_->add_artefact(
          NewArtefact{case_ids_[n], k ? "plan" : "landmarks",
                      archive_->store_object("artefact " + std::to_string(n) + "/" + std::to_string(k)),
                      "application/json", "inputs", "{}"});
  const auto artefacts = archive_->artefacts(case_ids_);
  ASSERT_EQ(artefacts.size(), case_ids_.size());
  for (size_t n = 0; n < case_ids_.size(); ++n) {
    const auto& found = artefacts.at(case_ids_[n]);
    EXPECT_EQ(found.size(), n % 3 == 0 ? 2u : 0u);
    EXPECT_EQ(describe(found), describe(archive_->artefacts(case_ids_[n])));
  }
}

TEST_F(BatchReads, ManySeriesObjectHashesAreEachSeriesOwnInInstanceOrder) {
  std::vector<int64_t> series;
  for (const auto& s : archive_->series()) series.push_back(s.id);
  ASSERT_EQ(series.size(), 1200u);
  auto asked = series;
  for (int64_t id = 1; id <= 5000; ++id) asked.push_back(id);  // each real series asked twice, and 3,800 that are not
  const auto hashes = archive_->series_object_hashes(asked);
  ASSERT_EQ(hashes.size(), 5000u);
  EXPECT_TRUE(hashes.at(4999).empty());
  for (int64_t id : series) {
    EXPECT_EQ(hashes.at(id).size(), 2u);
    EXPECT_EQ(hashes.at(id), archive_->series_object_hashes(id));
  }
}

}  // namespace
}  // namespace maxillo
