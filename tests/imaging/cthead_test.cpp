// The real cadaver head CT (../shared/data/cthead-stanford): wrap as DICOM -> volume -> skin and
// bone surfaces. Skips when the data are absent. Prints the timings and sizes it measures.
//
// Frame after wrapping (scripts/cthead-to-dicom): x = column - 127.5, y = row - 127.5 (row 0 is
// anterior), z = 224 - 2 (slice - 1) (slice 1 is the vertex), all in mm, patient LPS.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <iostream>

#include "dicom/dicom_series_writer.h"
#include "geometry/mesh_measures.h"
#include "imaging/segmentation.h"
#include "imaging/volume_assembly.h"
#include "imaging/volume_file.h"
#include "mesh/surface_extraction.h"
#include "support/run_command.h"
#include "support/temporary_folder.h"

namespace maxillo {
namespace {

const std::filesystem::path kSlices = std::filesystem::path(MAXILLO_SHARED_DATA) / "cthead-stanford" / "slices";

double z_of_slice(double slice) { return 224 - 2 * (slice - 1); }
double y_of_row(double row) { return row - 127.5; }

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

class CadaverHead : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!std::filesystem::exists(kSlices / "CThead.113")) return;
    folder_ = new TemporaryFolder("cthead");
    // The same header and placement as scripts/cthead-to-dicom.
    std::ofstream(*folder_ / "cthead.mhd")
        << "ObjectType = Image\nNDims = 3\nDimSize = 256 256 113\nElementType = MET_USHORT\n"
           "ElementSpacing = 1.0 1.0 2.0\nElementByteOrderMSB = True\nOffset = 0 0 0\n"
           "ElementDataFile = "
        << std::filesystem::absolute(kSlices).string() << "/CThead.%d 1 113 1\n";
    Volume raw = read_volume_file(*folder_ / "cthead.mhd", {.hu_offset = -1024});
    raw.geometry.direction.col(2) = Eigen::Vector3d(0, 0, -1);
    raw.geometry.origin = {-127.5, -127.5, 224};
    files_ = new std::vector<std::filesystem::path>(write_ct_series(raw, {}, *folder_ / "dicom").files);

    auto start = std::chrono::steady_clock::now();
    volume_ = new Volume(load_series_volume(*files_));
    const double load_seconds = seconds_since(start);
    start = std::chrono::steady_clock::now();
    labels_ = new LabelVolume(segment_tissues(*volume_));
    const double segmentation_seconds = seconds_since(start);
    start = std::chrono::steady_clock::now();
    skin_ =
        new TriangleMesh(extract_surface(restrict_to_mask(*volume_, select_labels(*labels_, kSoftTissue, kTeeth), -400),
                                         -400, {.keep_largest_components = 1, .target_triangles = 200000}));
    const double skin_seconds = seconds_since(start);
    start = std::chrono::steady_clock::now();
    bone_ = new TriangleMesh(
        extract_surface(restrict_to_mask(*volume_, select_labels(*labels_, kBone, kTeeth), 300), 300,
                        {.keep_largest_components = 0, .min_component_fraction = 0.001, .target_triangles = 200000}));
    const double bone_seconds = seconds_since(start);
    std::cout << "[cthead] load 113 DICOM slices: " << load_seconds << " s; segmentation: " << segmentation_seconds
              << " s; skin surface: " << skin_seconds << " s, " << skin_->face_count()
              << " triangles; bone surface: " << bone_seconds << " s, " << bone_->face_count() << " triangles\n";
  }
  static void TearDownTestSuite() {
    delete skin_;
    delete bone_;
    delete labels_;
    delete volume_;
    delete files_;
    delete folder_;
  }
  void SetUp() override {
    if (!volume_) GTEST_SKIP() << "real data absent: " << kSlices << " (see ../shared/data/README.md)";
  }

  static inline TemporaryFolder* folder_ = nullptr;
  static inline std::vector<std::filesystem::path>* files_ = nullptr;
  static inline Volume* volume_ = nullptr;
  static inline LabelVolume* labels_ = nullptr;
  static inline TriangleMesh* skin_ = nullptr;
  static inline TriangleMesh* bone_ = nullptr;
};

TEST_F(CadaverHead, VolumeIsInPatientLps) {
  const VolumeGeometry& g = volume_->geometry;
  EXPECT_EQ(g.size, Eigen::Vector3i(256, 256, 113));
  EXPECT_TRUE(g.direction.isApprox(Eigen::Matrix3d::Identity()));  // read back along the normal
  EXPECT_TRUE(g.origin.isApprox(Eigen::Vector3d(-127.5, -127.5, 0)));
  EXPECT_TRUE(g.spacing.isApprox(Eigen::Vector3d(1, 1, 2)));
}

TEST_F(CadaverHead, SkinIsOneClosedSurfaceFacingForwardAndUp) {
  EXPECT_EQ(connected_components(*skin_).face_counts.size(), 1u);
  EXPECT_TRUE(is_watertight(*skin_));
  EXPECT_GT(signed_volume(*skin_), 2.0e6) << "a head holds a few litres";
  EXPECT_LT(signed_volume(*skin_), 6.0e6);
  // The nose tip is the most anterior (smallest y) skin point, in slices ~57-61.
  Eigen::Index nose = 0;
  skin_->vertices.col(1).minCoeff(&nose);
  const double nose_z = skin_->vertices(nose, 2);
  EXPECT_LT(nose_z, z_of_slice(50));
  EXPECT_GT(nose_z, z_of_slice(68));
  // The vertex of the skull is the top of the volume.
  EXPECT_GT(skin_->vertices.col(2).maxCoeff(), z_of_slice(12));
}

TEST_F(CadaverHead, HeadRestIsGone) {
  // Looked up in the data: behind the head in every slice lie a pad hugging the scalp (HU ~ -300
  // to -150, ~3 mm, touching it under the occiput at rows ~235-237), then ~3 mm of air, then the
  // dense table arc (rows ~240-243 at the lowest point) whose arms rise to rows ~212. From
  // slice 90 down the head ends before row ~195 while the arc is still at rows 212-230.
  // The pad is kept where it touches the scalp (within the 3 mm opening radius, see
  // segmentation.h); everything beyond that must be gone.
  int64_t behind_lower_head = 0, at_table = 0;
  for (Eigen::Index v = 0; v < skin_->vertex_count(); ++v) {
    const double y = skin_->vertices(v, 1), z = skin_->vertices(v, 2);
    if (z < z_of_slice(90) && y > y_of_row(205)) ++behind_lower_head;
    if (y > y_of_row(239.5)) ++at_table;
  }
  EXPECT_EQ(behind_lower_head, 0);
  EXPECT_EQ(at_table, 0);
  EXPECT_GT(skin_->vertices.col(1).maxCoeff(), y_of_row(230)) << "the back of the head is still there";
  // No voxel of the arc below slice 90 is labelled as body.
  const VolumeGeometry& g = labels_->geometry;
  int64_t arc_voxels_in_body = 0, arc_voxels = 0;
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 205; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i)
        if (g.world(Eigen::Vector3d(i, j, k)).z() < z_of_slice(90) && volume_->at(i, j, k) >= -400) {
          ++arc_voxels;
          arc_voxels_in_body += labels_->labels[size_t(g.index(i, j, k))] != kBackground;
        }
  EXPECT_GT(arc_voxels, 1000) << "the head rest arc is where we looked";
  EXPECT_EQ(arc_voxels_in_body, 0);
}

TEST_F(CadaverHead, BoneReachesTheTeeth) {
  EXPECT_GT(bone_->face_count(), 10000);
  EXPECT_TRUE(is_watertight(*bone_));
  EXPECT_GT(signed_volume(*bone_), 0.3e6) << "skull and mandible: several hundred cm3";
  // Teeth: dense voxels in slices 70-88, in front of the head's centre.
  const VolumeGeometry& g = labels_->geometry;
  int64_t teeth = 0;
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        const Eigen::Vector3d p = g.world(Eigen::Vector3d(i, j, k));
        if (labels_->labels[size_t(g.index(i, j, k))] == kTeeth && p.z() < z_of_slice(70) && p.z() > z_of_slice(88) &&
            p.y() < y_of_row(110))
          ++teeth;
      }
  EXPECT_GT(teeth, 500) << "teeth voxels at the occlusal level";
  int64_t bone_at_teeth_level = 0;
  for (Eigen::Index v = 0; v < bone_->vertex_count(); ++v)
    if (bone_->vertices(v, 2) < z_of_slice(70) && bone_->vertices(v, 2) > z_of_slice(88) &&
        bone_->vertices(v, 1) < y_of_row(110))
      ++bone_at_teeth_level;
  EXPECT_GT(bone_at_teeth_level, 1000);
}

TEST_F(CadaverHead, ScriptWrapsTheSameSeries) {
  const std::filesystem::path maxillo = MAXILLO_BINARY;
  if (!std::filesystem::exists(maxillo)) GTEST_SKIP() << maxillo << " is not built";
  TemporaryFolder out("cthead-script");
  auto run =
      testing::run_command(testing::quote(std::filesystem::path(MAXILLO_SOURCE_DIR) / "scripts" / "cthead-to-dicom") +
                           " " + testing::quote(out / "series") + " --data " + testing::quote(kSlices) + " --maxillo " +
                           testing::quote(maxillo) + " 2>&1");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(out / "series")) files.push_back(entry.path());
  ASSERT_EQ(files.size(), 113u);
  const Volume wrapped = load_series_volume(files);
  EXPECT_TRUE(wrapped.geometry.origin.isApprox(volume_->geometry.origin));
  EXPECT_TRUE(wrapped.geometry.direction.isApprox(volume_->geometry.direction));
  EXPECT_EQ(wrapped.hu, volume_->hu);
}

}  // namespace
}  // namespace maxillo
