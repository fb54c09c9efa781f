// Landmark sets of a case (records/case_landmarks.h), issue 28: an automatic set keeps its
// detection's facts through the archive, and a set given by hand always takes precedence over
// an automatic one, whichever was stored first.
#include <gtest/gtest.h>

#include "archive_fixture.h"
#include "records/case_landmarks.h"

namespace maxillo::records {
namespace {

using testing::TemporaryFolder;

AutomaticFacts facts() {
  AutomaticFacts f;
  f.method = "maxillo-landmarks 1";
  f.confidence = {{"S", 0.9}, {"OrL", 0.3}};
  f.flagged = {{"OrL", "mirror: 19.6 mm from the mirror image"}};
  f.absent = {{"U6R", "not detected by this version of the method"}};
  return f;
}

TEST(CaseLandmarks, AHandPlacedSetTakesPrecedenceOverAnAutomaticOne) {
  TemporaryFolder folder;
  testing::write_series(folder / "in", 2, "P1");
  Archive archive = Archive::open(testing::archive_at(folder / "archive"), OpenMode::CreateIfMissing);
  archive.import_paths({folder / "in"}, testing::quiet());
  const int64_t case_id = archive.resolve_case("P1");
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

}  // namespace
}  // namespace maxillo::records
