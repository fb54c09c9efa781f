// Occlusions in a real archive: the newest comes back with its occlusionogram and splint render;
// the same inputs are stored once; a result without its occlusionogram is a damaged record.
#include "records/occlusion_archive.h"

#include <gtest/gtest.h>

#include <fstream>

#include "archive/artefact_kind.h"
#include "support/archived_case.h"
#include "support/error_of.h"

namespace maxillo::records {
namespace {

using testing::ArchivedCase;

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

// A run's folder as occlude writes it, its result naming `upper`.
std::filesystem::path run_folder(const std::filesystem::path& folder, const std::string& upper) {
  OcclusionRecord record;
  record.upper_file = upper;
  record.upper_centroid = Eigen::Vector3d(1, 2, 3);
  write_text(folder / "occlusion.json", to_json(record).dump(2));
  write_text(folder / "occlusionogram.png", upper + " gram");
  write_text(folder / "splint.stl", upper + " splint");
  write_text(folder / "splint.png", upper + " render");
  return folder;
}

TEST(OcclusionArchive, TheNewestComesBackWithItsPicturesAndTheSameInputsAreStoredOnce) {
  ArchivedCase c;
  EXPECT_FALSE(latest_occlusion(c.archive, c.case_id));
  const auto a = run_folder(c.folder.path() / "a", "a.stl"), b = run_folder(c.folder.path() / "b", "b.stl");
  store_occlusion(c.archive, {c.case_id, "key-a", a, true, a / "splint.png"});
  store_occlusion(c.archive, {c.case_id, "key-b", b, false, {}});
  const size_t artefacts = c.archive.artefacts(c.case_id).size();
  EXPECT_EQ(artefacts, 6u);  // a: result, occlusionogram, splint, render; b: result, occlusionogram

  auto newest = latest_occlusion(c.archive, c.case_id);
  ASSERT_TRUE(newest);
  EXPECT_EQ(newest->record.upper_file, "b.stl");
  EXPECT_EQ(testing::read_text(newest->occlusionogram), "b.stl gram");
  EXPECT_FALSE(newest->splint_render);

  store_occlusion(c.archive, {c.case_id, "key-b", b, false, {}});  // stored already: nothing added
  EXPECT_EQ(c.archive.artefacts(c.case_id).size(), artefacts);
  store_occlusion(c.archive, {c.case_id, "key-a2", a, true, a / "splint.png"});
  newest = latest_occlusion(c.archive, c.case_id);
  ASSERT_TRUE(newest && newest->splint_render);
  EXPECT_EQ(testing::read_text(*newest->splint_render), "a.stl render");
}

TEST(OcclusionArchive, AResultWithoutItsOcclusionogramIsADamagedRecord) {
  ArchivedCase c;
  const auto folder = run_folder(c.folder.path() / "a", "a.stl");
  c.archive.add_artefact(NewArtefact{c.case_id, kind_name(ArtefactKind::kOcclusion),
                                     c.archive.store_object(testing::read_text(folder / "occlusion.json")),
                                     "application/json", "key", "{}"});
  const std::string error = testing::error_of([&] { latest_occlusion(c.archive, c.case_id); });
  EXPECT_NE(error.find("(occlusion): its occlusionogram is not stored"), std::string::npos) << error;
}

}  // namespace
}  // namespace maxillo::records
