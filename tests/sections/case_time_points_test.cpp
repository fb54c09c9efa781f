// Landmark sets per case and time point in a real archive: ordering by date, revisions kept as
// history, latest_landmarks unchanged, bad dates refused; the report section built from them.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "archive/archive_fixture.h"
#include "core/error.h"
#include "records/case_landmarks.h"
#include "sections/cephalometry_section.h"
#include "sample/phantom.h"

namespace maxillo::sections {
namespace {

LandmarkSet phantom_landmarks(double maxillary_advancement_mm) {
  PhantomSpec spec = phantom_spec_for_class(SkeletalClass::III);
  spec.spacing_mm = 4;
  spec.maxillary_advancement_mm = maxillary_advancement_mm;
  return make_phantom(spec).landmarks;
}

struct ArchivedCase {
  maxillo::testing::TemporaryFolder folder;
  Archive archive = Archive::open(testing::archive_at(folder.path() / "archive"), OpenMode::CreateIfMissing);
  int64_t case_id = 0;
  ArchivedCase() {
    maxillo::testing::write_series(folder.path() / "dicom", 3, "P7");
    archive.import_paths({folder.path() / "dicom"});
    case_id = archive.resolve_case("P7");
  }
};

TEST(CaseTimePoints, OrderedByDateWithHistory) {
  ArchivedCase c;
  records::attach_landmarks(c.archive, c.case_id, phantom_landmarks(8), "post.mrk.json", {"post", "2001-03-01"});
  records::attach_landmarks(c.archive, c.case_id, phantom_landmarks(-2), "pre.mrk.json", {"pre", "2001-01-10"});
  records::attach_landmarks(c.archive, c.case_id, phantom_landmarks(7.5), "6M.mrk.json", {"6M", "2001-09-01"});
  auto revised_pre = phantom_landmarks(-1);
  records::attach_landmarks(c.archive, c.case_id, revised_pre, "pre-retraced.mrk.json", {"pre", "2001-01-10"});

  auto points = records::landmark_time_points(c.archive, c.case_id);
  ASSERT_EQ(points.size(), 3u);
  EXPECT_EQ(points[0].time_point.label, "pre");
  EXPECT_EQ(points[1].time_point.label, "post");
  EXPECT_EQ(points[2].time_point.label, "6M");
  EXPECT_EQ(points[0].source, "pre-retraced.mrk.json");
  EXPECT_EQ(points[0].version, 2);
  EXPECT_EQ(points[0].time_point.date, "2001-01-10");

  auto history = records::landmark_history(c.archive, c.case_id);
  ASSERT_EQ(history.size(), 4u);
  EXPECT_EQ(history[1].source, "pre.mrk.json");
  EXPECT_EQ(history[1].version, 1);
  // The newest set of any time point is still the case's landmarks.
  auto latest = records::latest_landmarks(c.archive, c.case_id);
  ASSERT_EQ(latest.size(), revised_pre.size());
  EXPECT_TRUE(latest[0].position.isApprox(revised_pre[0].position, 1e-9));
}

TEST(CaseTimePoints, RefusesMalformedDates) {
  ArchivedCase c;
  for (const char* date : {"2001-13-01", "01-03-2001", "2001-3-1", "yesterday"})
    EXPECT_THROW(records::attach_landmarks(c.archive, c.case_id, phantom_landmarks(0), "x.csv", {"pre", date}), Error)
        << date;
  EXPECT_TRUE(records::landmark_history(c.archive, c.case_id).empty());
}

TEST(CaseTimePoints, CephalogramAxesAreKeptWithTheSet) {
  ArchivedCase c;
  LandmarkSet pixels = {{"S", {832, 994, 0}}, {"N", {1469, 1032, 0}}, {"A", {1370, 1643, 0}}};
  records::attach_landmarks(c.archive, c.case_id, pixels, "001.csv", {"pre", ""},
                            {LandmarkGeometry::kCephalogram, {0.1, ImageVerticalAxis::kDown, FacingDirection::kPlusX}});
  auto stored = records::landmark_time_points(c.archive, c.case_id).at(0);
  EXPECT_EQ(stored.frame.geometry, LandmarkGeometry::kCephalogram);
  EXPECT_DOUBLE_EQ(stored.frame.axes.pixel_spacing_mm, 0.1);
  EXPECT_EQ(stored.frame.axes.vertical, ImageVerticalAxis::kDown);
}

// Issue 17: a stored set's facts are read strictly. A cephalogram set whose pixel spacing was lost
// would be measured at a default scale; it is an error naming the artefact and the key instead.
TEST(CaseTimePoints, DamagedStoredFactsAreAnErrorNamingTheKey) {
  const std::string set =
      R"({"@schema": "https://raw.githubusercontent.com/slicer/slicer/master/Modules/Loadable/Markups/Resources/Schema/markups-schema-v1.0.3.json#", "markups": []})";
  const std::pair<const char*, const char*> damaged[] = {
      {R"({"source": "a.csv", "count": 0, "frame": {"cephalogram": {"image_y": "down", "face": "+x"}}})",
       "frame.cephalogram.pixel_spacing_mm: missing"},
      {R"({"source": "a.csv", "count": 0, "frame": {"cephalogram": {"pixel_spacing_mm": 0.1, "image_y": "sideways", "face": "+x"}}})",
       "frame.cephalogram.image_y: must be \"up\" or \"down\""},
      {R"({"count": 0, "frame": "LPS"})", "source: missing"},
      {R"({"source": "a.csv", "count": 0, "frame": "LPS", "time_point": "pre"})", "date: missing"},
      {R"({"source": "a.csv", "count": 0, "frame": "LPS", "time_point": "pre", "date": "2001-1-1"})",
       "date: must be YYYY-MM-DD or empty"},
  };
  for (const auto& [parameters, expected] : damaged) {
    ArchivedCase c;
    const int64_t id = c.archive.add_artefact(
        NewArtefact{c.case_id, "landmarks", c.archive.store_object(set), "application/json", "x", parameters});
    try {
      records::landmark_history(c.archive, c.case_id);
      ADD_FAILURE() << "accepted: " << parameters;
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::kArchiveCorrupt);
      EXPECT_EQ(std::string(e.what()), "artefact " + std::to_string(id) + " (landmarks): " + expected);
    }
  }
}

TEST(CephalometrySection, MeasurementTableAndFollowUpTable) {
  ArchivedCase c;
  records::attach_landmarks(c.archive, c.case_id, phantom_landmarks(0), "pre.csv", {"pre", "2002-05-01"});
  records::attach_landmarks(c.archive, c.case_id, phantom_landmarks(10), "post.csv", {"post", "2002-06-20"});
  auto section = case_cephalometry_section(c.archive, c.case_id);
  EXPECT_EQ(section.id, "cephalometry");
  std::vector<const report::Table*> tables;
  for (const auto& block : section.blocks)
    if (const auto* t = std::get_if<report::Table>(&block)) tables.push_back(t);
  ASSERT_EQ(tables.size(), 2u);
  // Cephalometric table: the "post" set, SNB of the Class III phantom with its norm and a flag.
  const auto& measurements = *tables[0];
  ASSERT_EQ(measurements.columns.size(), 4u);
  bool found_snb = false;
  for (const auto& row : measurements.rows)
    if (row[0] == "SNB angle") {
      found_snb = true;
      EXPECT_EQ(row[2], "80.0 \u00b1 3.0");
      EXPECT_FALSE(row[3].empty());
    }
  EXPECT_TRUE(found_snb);
  // Follow-up: one column per time point, dates in the headings.
  const auto& follow_up = *tables[1];
  ASSERT_EQ(follow_up.columns.size(), 3u);
  EXPECT_EQ(follow_up.columns[1].title, "pre 2002-05-01");
  bool found_ans = false;
  for (const auto& row : follow_up.rows)
    if (row[0] == "ANS_X") {
      found_ans = true;
      // The maxilla advanced 10 mm horizontally; X lies 1 deg above Frankfort.
      double change = std::stod(row[2]) - std::stod(row[1]);
      EXPECT_NEAR(change, 10 * std::cos(std::numbers::pi / 180), 0.11);  // table shows 1 decimal
    }
  EXPECT_TRUE(found_ans);
}

TEST(CephalometrySection, WithoutLandmarksSaysSo) {
  ArchivedCase c;
  auto section = case_cephalometry_section(c.archive, c.case_id);
  ASSERT_EQ(section.blocks.size(), 1u);
  EXPECT_TRUE(std::holds_alternative<report::Note>(section.blocks[0]));
}

}  // namespace
}  // namespace maxillo::sections
