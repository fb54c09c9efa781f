// The report's Landmarks section (sections/landmark_section.h): an automatic set shows its
// confidences, flags and absences; a given set with an automatic one beside it shows the
// distance of each automatic landmark from the given one.
#include <gtest/gtest.h>

#include "sections/landmark_section.h"

namespace maxillo::sections {
namespace {

records::StoredLandmarks automatic_set() {
  records::StoredLandmarks stored;
  stored.source = "automatic (maxillo-landmarks 1)";
  stored.landmarks = {{"S", {0, 0, 20.3}}, {"OrL", {33, -57, 3}}};
  stored.automatic = records::AutomaticFacts{"maxillo-landmarks 1",
                                             {{"S", 0.91}, {"OrL", 0.3}},
                                             {{"OrL", "mirror: 6.0 mm from the mirror image"}},
                                             {{"U6R", "not detected by this version of the method"}}};
  return stored;
}

const report::Table& first_table(const report::Section& section, size_t skip = 0) {
  for (const auto& block : section.blocks)
    if (const auto* table = std::get_if<report::Table>(&block))
      if (skip-- == 0) return *table;
  throw std::runtime_error("no such table");
}

TEST(LandmarkSection, AnAutomaticSetShowsItsDoubts) {
  const auto section = landmark_section(automatic_set());
  ASSERT_TRUE(section);
  const auto& table = first_table(*section);
  ASSERT_EQ(table.rows.size(), 3u);  // S, OrL, and the absent U6R
  EXPECT_EQ(table.rows[0][4], "0.91");
  EXPECT_EQ(table.rows[1][5], "FLAGGED: mirror: 6.0 mm from the mirror image");
  EXPECT_EQ(table.rows[2][0], "U6R");
  EXPECT_EQ(table.rows[2][5], "absent: not detected by this version of the method");
  EXPECT_FALSE(landmark_section(std::nullopt));
}

TEST(LandmarkSection, AGivenSetIsComparedWithTheAutomaticOneBesideIt) {
  records::StoredLandmarks given;
  given.source = "phantom (analytic)";
  given.landmarks = {{"S", {0, 0, 20}}, {"OrL", {33, -57, 0}}, {"U6R", {-29, -48, -47}}};
  const auto section = landmark_section(given, automatic_set());
  ASSERT_TRUE(section);
  const auto& comparison = first_table(*section, 1);
  ASSERT_EQ(comparison.rows.size(), 3u);
  EXPECT_EQ(comparison.rows[0][1], "0.30");  // S: 0.3 mm
  EXPECT_EQ(comparison.rows[1][1], "3.00");  // OrL: 3 mm, flagged
  EXPECT_EQ(comparison.rows[2][1], "-");     // U6R: absent from the automatic set
  bool mean_said = false;
  for (const auto& block : section->blocks)
    if (const auto* p = std::get_if<report::Paragraph>(&block))
      mean_said |=
          p->text.find("Mean distance of the automatic landmarks from the given ones: 1.65 mm") != std::string::npos;
  EXPECT_TRUE(mean_said);
}

// The demo's case: it works with the automatic set, and the phantom's design is kept beside it as
// the truth; the section measures every automatic landmark against it.
TEST(LandmarkSection, AnAutomaticSetIsMeasuredAgainstAKnownReference) {
  records::StoredLandmarks truth;
  truth.source = "phantom (analytic)";
  truth.reference = true;
  truth.landmarks = {{"S", {0, 0, 20}}, {"OrL", {33, -57, 1}}, {"U6R", {-29, -48, -47}}};
  const auto section = landmark_section(automatic_set(), std::nullopt, {}, truth);
  ASSERT_TRUE(section);
  const auto& comparison = first_table(*section, 1);
  ASSERT_EQ(comparison.rows.size(), 3u);
  EXPECT_EQ(comparison.rows[0][1], "0.30");
  EXPECT_EQ(comparison.rows[1][1], "2.00");
  EXPECT_EQ(comparison.rows[2][2], "absent: not detected by this version of the method");
  bool mean_said = false;
  for (const auto& block : section->blocks)
    if (const auto* p = std::get_if<report::Paragraph>(&block))
      mean_said |= p->text.find(
                       "(phantom (analytic)); the case works with the automatic ones. Mean distance of the "
                       "automatic landmarks from the true places: 1.15 mm") != std::string::npos;
  EXPECT_TRUE(mean_said);
  // Without a reference the automatic set's section has its table only.
  EXPECT_THROW(first_table(*landmark_section(automatic_set()), 1), std::runtime_error);
}

// Which landmarks each picture of the landmark page draws, and in which colour.
TEST(LandmarkPictures, EachViewDrawsTheLandmarksItCanShowColouredByStatus) {
  auto stored = automatic_set();
  stored.landmarks.push_back({"GoR", {-45, -10, -60}});
  using render::StandardView;
  auto labels_in = [&](StandardView view) {
    std::vector<std::string> labels;
    for (const auto& m : casework::landmark_markers(stored, view)) labels.push_back(m.label);
    return labels;
  };
  EXPECT_EQ(labels_in(StandardView::Frontal), (std::vector<std::string>{"S", "OrL", "GoR"}));
  EXPECT_EQ(labels_in(StandardView::Lateral), (std::vector<std::string>{"S", "GoR"}));
  EXPECT_EQ(labels_in(StandardView::LeftLateral), (std::vector<std::string>{"OrL"}));

  const auto frontal = casework::landmark_markers(stored, StandardView::Frontal);
  auto same = [](const render::ColourRGB& a, const render::ColourRGB& b) {
    return a.r == b.r && a.g == b.g && a.b == b.b;
  };
  EXPECT_TRUE(same(frontal[0].colour, casework::kAutomaticLandmarkColour));
  EXPECT_TRUE(same(frontal[1].colour, casework::kFlaggedLandmarkColour)) << "OrL is flagged";
  stored.automatic.reset();  // a set given by hand
  EXPECT_TRUE(
      same(casework::landmark_markers(stored, StandardView::Frontal)[1].colour, casework::kGivenLandmarkColour));
}

TEST(LandmarkSection, ThePicturesComeFirstTwoToARow) {
  const std::vector<casework::LandmarkView> pictures{
      {render::StandardView::Frontal, "/tmp/a.png", "frontal: every landmark"},
      {render::StandardView::Lateral, "/tmp/b.png", "right lateral: midline and right-sided landmarks"}};
  const auto section = landmark_section(automatic_set(), std::nullopt, pictures);
  ASSERT_TRUE(section);
  const report::ImageGrid* grid = nullptr;
  for (const auto& block : section->blocks)
    if ((grid = std::get_if<report::ImageGrid>(&block))) break;
  ASSERT_TRUE(grid);
  EXPECT_EQ(grid->per_row, 2);
  ASSERT_EQ(grid->figures.size(), 2u);
  EXPECT_EQ(grid->figures[1].caption, "right lateral: midline and right-sided landmarks");
  EXPECT_FALSE(std::holds_alternative<report::ImageGrid>(section->blocks.back())) << "the table follows the pictures";
}

}  // namespace
}  // namespace maxillo::sections
