// Issue 28, section 3: `maxillo orientation CASE --reorient` on an archived phantom whose header
// flipped its y axis (the face at +y), with landmarks a person placed on that volume. The case
// gets a corrected copy of its CT that is the phantom as designed, voxel for voxel; the
// original series stays; the landmarks are mapped back onto the anatomy they were placed on.
#include <gtest/gtest.h>

#include "archive_fixture.h"
#include "casework/landmarks/case_orientation.h"
#include "casework/landmarks/case_reorientation.h"
#include "casework/sample/sample_case.h"
#include "core/error.h"
#include "dicom/dicom_series_writer.h"
#include "imaging/axis_flip.h"
#include "imaging/volume_assembly.h"
#include "records/archived_series.h"
#include "records/case_landmarks.h"
#include "records/derivation.h"
#include "support/temporary_folder.h"

namespace maxillo::casework {
namespace {

const Eigen::Matrix3d kFlipY = Eigen::Vector3d(1, -1, 1).asDiagonal();
const Eigen::Matrix3d kQuarterAboutZ = (Eigen::Matrix3d() << 0, -1, 0, 1, 0, 0, 0, 0, 1).finished();

struct FaultyCase {
  Archive archive;
  int64_t case_id = 0;
  Volume designed;         // the phantom's CT as it should read
  LandmarkSet truth;       // its landmarks
  Eigen::Vector3d centre;  // of the grid, which the fault and its correction keep
};

// The phantom written with its patient frame changed by `fault` about the grid's centre, and
// its landmarks as a person would have placed them on that volume.
FaultyCase archived_with_fault(const testing::TemporaryFolder& folder, const Eigen::Matrix3d& fault) {
  const SampleCase sample = write_sample_case(SkeletalClass::I, 2.0, folder / "sample");
  FaultyCase c{Archive::open(folder / "archive", OpenMode::CreateIfMissing), 0, load_series_volume(sample.series.files),
               sample.landmarks, Eigen::Vector3d::Zero()};
  c.centre = grid_centre(c.designed.geometry);
  Volume faulty = c.designed;
  faulty.geometry = flipped_about_centre(c.designed.geometry, fault);
  SeriesMetadata metadata = phantom_series_metadata({.spacing_mm = 2.0});
  metadata.series_instance_uid = "1.2.826.0.1.3680043.8.498.77";  // another series than the sample's
  write_ct_series(faulty, metadata, folder / "faulty");
  if (!c.archive.import_paths({folder / "faulty"}, testing::quiet()).all_ok())
    throw std::runtime_error("the faulty phantom did not import");
  c.case_id = c.archive.resolve_case(kPhantomPatientId);
  LandmarkSet placed = sample.landmarks;
  for (auto& l : placed) l.position = c.centre + fault * (l.position - c.centre);
  records::attach_landmarks(c.archive, c.case_id, placed, "placed by hand");
  return c;
}

TEST(CaseReorientation, AFlippedAxisIsUndoneOnACopyAndTheLandmarksFollow) {
  testing::TemporaryFolder folder("maxillo-reorient");
  FaultyCase c = archived_with_fault(folder, kFlipY);
  ASSERT_FALSE(case_orientation(c.archive, c.case_id).trusted());

  const ReorientedCase r = reorient_case(c.archive, c.case_id);
  EXPECT_EQ(r.flipped_axes, "y");
  EXPECT_TRUE(r.record.trusted());
  EXPECT_FALSE(r.record.contradicts_header) << r.record.finding;
  EXPECT_TRUE(r.landmarks_mapped);
  EXPECT_FALSE(r.landmarks_detected);

  // The corrected copy is the case's CT; the original is kept, unassigned.
  const auto contents = c.archive.case_contents(c.case_id);
  EXPECT_EQ(records::primary_series(contents), r.corrected_series);
  ASSERT_EQ(contents.series.size(), 2u);
  for (const auto& entry : contents.series)
    EXPECT_EQ(entry.role, entry.series.id == r.corrected_series ? "preop" : "unassigned");

  // Voxel for voxel the designed phantom: the same value at the same patient position.
  const Volume corrected = records::load_archived_series(c.archive, r.corrected_series);
  ASSERT_EQ(corrected.geometry.voxel_count(), c.designed.geometry.voxel_count());
  for (const Eigen::Vector3i& ijk :
       {Eigen::Vector3i(0, 0, 0), Eigen::Vector3i(40, 60, 50), Eigen::Vector3i(80, 10, 100)}) {
    const Eigen::Vector3d p = c.designed.geometry.world(ijk.cast<double>());
    const Eigen::Vector3d at = corrected.geometry.continuous_index(p);
    const Eigen::Vector3i k = at.array().round().cast<int>();
    EXPECT_LT((at - k.cast<double>()).norm(), 1e-3) << "voxel centres coincide";
    EXPECT_EQ(corrected.at(k.x(), k.y(), k.z()), c.designed.at(ijk.x(), ijk.y(), ijk.z()));
  }

  // The landmarks given by hand, mapped: back on the anatomy they were placed on.
  const auto preferred = records::preferred_landmarks(c.archive, c.case_id);
  ASSERT_TRUE(preferred && !preferred->automatic);
  ASSERT_EQ(preferred->landmarks.size(), c.truth.size());
  for (size_t i = 0; i < c.truth.size(); ++i)
    EXPECT_LT((preferred->landmarks[i].position - c.truth[i].position).norm(), 1e-3) << c.truth[i].label;
  EXPECT_NE(preferred->source.find("mapped with the reoriented CT"), std::string::npos) << preferred->source;

  // Nothing more to undo.
  EXPECT_THROW(reorient_case(c.archive, c.case_id), Error);
}

TEST(CaseReorientation, AFaceTurnedSidewaysIsNoAxisFlipAndIsRefused) {
  testing::TemporaryFolder folder("maxillo-reorient-sideways");
  FaultyCase c = archived_with_fault(folder, kQuarterAboutZ);
  try {
    reorient_case(c.archive, c.case_id);
    FAIL() << "reoriented a face turned sideways";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kBadValue);
    EXPECT_NE(std::string(e.what()).find("not an axis flip"), std::string::npos) << e.what();
  }
  EXPECT_EQ(c.archive.case_contents(c.case_id).series.size(), 1u) << "nothing stored";
}

}  // namespace
}  // namespace maxillo::casework
