// Landmark sets of a case (records/case_landmarks.h), issue 28: an automatic set keeps its
// detection's facts through the archive, a set given by hand always takes precedence over an
// automatic one, whichever was stored first, and a reference set is never worked with.
#include <gtest/gtest.h>

#include "support/archived_case.h"
#include "records/case_landmarks.h"

namespace maxillo::records {
namespace {

AutomaticFacts facts() {
  AutomaticFacts f;
  f.method = "maxillo-landmarks 1";
  f.confidence = {{"S", 0.9}, {"OrL", 0.3}};
  f.flagged = {{"OrL", "mirror: 19.6 mm from the mirror image"}};
  f.absent = {{"U6R", "not detected by this version of the method"}};
  return f;
}

TEST(CaseLandmarks, AHandPlacedSetTakesPrecedenceOverAnAutomaticOne) {
  testing::ArchivedCase c;
  Archive& archive = c.archive;
  const int64_t case_id = c.case_id;
  EXPECT_FALSE(preferred_landmarks(archive, case_id));

  const LandmarkSet automatic = {{"S", {0, 0, 20}}, {"OrL", {33, -57, 0}}};
  attach_automatic_landmarks(archive, case_id, automatic, facts());
  auto preferred = preferred_landmarks(archive, case_id);
  ASSERT_TRUE(preferred && preferred->automatic);
  EXPECT_EQ(preferred->source, "automatic (maxillo-landmarks 1)");
  EXPECT_EQ(preferred->automatic->flagged, facts().flagged);
  EXPECT_EQ(preferred->automatic->absent, facts().absent);
  EXPECT_EQ(preferred->automatic->confidence, facts().confidence);
  EXPECT_EQ(latest_landmarks(archive, case_id).size(), 2u);

  const LandmarkSet by_hand = {{"S", {0.5, 0, 20}}, {"N", {0, -69, 28}}, {"Me", {0, -60, -92}}};
  attach_landmarks(archive, case_id, by_hand, "hand.csv");
  preferred = preferred_landmarks(archive, case_id);
  ASSERT_TRUE(preferred);
  EXPECT_FALSE(preferred->automatic);
  EXPECT_EQ(preferred->landmarks.size(), 3u);
  // A newer automatic set stored beside it does not displace it.
  attach_automatic_landmarks(archive, case_id, automatic, facts());
  EXPECT_EQ(latest_landmarks(archive, case_id).size(), 3u);
  EXPECT_EQ(landmark_history(archive, case_id).size(), 3u);
}

// A reference set (a phantom's known landmarks) is kept to measure a detection against: the case
// never works with it, whether it is the CT's or a time point's.
TEST(CaseLandmarks, AReferenceSetIsNeverTheOneTheCaseWorksWith) {
  testing::ArchivedCase c;
  Archive& archive = c.archive;
  const int64_t case_id = c.case_id;

  const LandmarkSet truth = {{"S", {0, 0, 19}}};
  attach_landmarks(archive, case_id, truth, "phantom (analytic)", {}, {}, LandmarkOrigin::kReference);
  attach_landmarks(archive, case_id, {{"S", {0, 0, 21}}}, "cohort", {"6M", "2002-01-10"}, {},
                   LandmarkOrigin::kReference);
  EXPECT_FALSE(preferred_landmarks(archive, case_id));
  EXPECT_EQ(landmark_time_points(archive, case_id).size(), 1u);  // the follow-up still reads it

  attach_automatic_landmarks(archive, case_id, {{"S", {0, 0, 20}}, {"OrL", {33, -57, 0}}}, facts());
  auto preferred = preferred_landmarks(archive, case_id);
  ASSERT_TRUE(preferred && preferred->automatic);
  EXPECT_FALSE(preferred->reference);
  auto reference = newest_reference_landmarks(archive, case_id);
  ASSERT_TRUE(reference);  // the CT's, not the time point's
  EXPECT_TRUE(reference->reference);
  EXPECT_EQ(reference->source, "phantom (analytic)");
  EXPECT_DOUBLE_EQ(reference->landmarks.at(0).position.z(), 19);

  // The same points given by hand are another artefact, and the one the case works with.
  attach_landmarks(archive, case_id, truth, "hand.csv");
  preferred = preferred_landmarks(archive, case_id);
  ASSERT_TRUE(preferred);
  EXPECT_EQ(preferred->source, "hand.csv");
  EXPECT_FALSE(preferred->reference);
  EXPECT_EQ(landmark_history(archive, case_id).size(), 4u);
}

}  // namespace
}  // namespace maxillo::records
