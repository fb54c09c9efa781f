// Face predictions in a real archive: the newest one comes back with the pictures stored with it;
// a picture without its name is a damaged record.
#include "records/simulation_archive.h"

#include <gtest/gtest.h>

#include <fstream>

#include "archive/artefact_kind.h"
#include "core/atomic_file.h"
#include "support/archived_case.h"
#include "support/error_of.h"

namespace maxillo::records {
namespace {

using testing::ArchivedCase;

// A PNG-named file with `content`, in `folder`.
std::filesystem::path picture_file(const std::filesystem::path& folder, const std::string& name,
                                   const std::string& content) {
  std::filesystem::create_directories(folder);
  const auto path = folder / (name + ".png");
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

SimulationToStore prediction(const ArchivedCase& c, const std::string& key, const std::string& plan_text,
                             const std::filesystem::path& folder) {
  SimulationToStore s;
  s.case_id = c.case_id;
  s.inputs_hash = key;
  s.summary.plan_text = plan_text;
  s.summary.model = "mtm";
  s.pictures = {picture_file(folder, "soft-tissue-after-lateral", plan_text + " after"),
                picture_file(folder, "soft-tissue-before-lateral", plan_text + " before")};
  return s;
}

TEST(SimulationArchive, TheNewestPredictionComesBackWithItsOwnPictures) {
  ArchivedCase c;
  EXPECT_FALSE(latest_simulation(c.archive, c.case_id));
  store_simulation(c.archive, prediction(c, "key-a", "first", c.folder.path() / "a"));
  store_simulation(c.archive, prediction(c, "key-b", "second", c.folder.path() / "b"));

  const auto newest = latest_simulation(c.archive, c.case_id);
  ASSERT_TRUE(newest);
  EXPECT_EQ(newest->summary.plan_text, "second");
  ASSERT_EQ(newest->pictures.size(), 2u);
  EXPECT_EQ(testing::read_text(newest->pictures.at("soft-tissue-after-lateral")), "second after");
  EXPECT_NE(newest->source.find("(simulation)"), std::string::npos) << newest->source;

  // The same inputs again: the pictures stored with the newer summary are the ones shown.
  store_simulation(c.archive, prediction(c, "key-a", "third", c.folder.path() / "c"));
  EXPECT_EQ(testing::read_text(latest_simulation(c.archive, c.case_id)->pictures.at("soft-tissue-before-lateral")),
            "third before");
}

TEST(SimulationArchive, APictureWithoutItsNameIsADamagedRecord) {
  ArchivedCase c;
  const auto png = picture_file(c.folder.path(), "soft-tissue-after-frontal", "x");
  c.archive.add_artefact(NewArtefact{c.case_id, kind_name(ArtefactKind::kSimulationImage),
                                     c.archive.store_object(read_file(png)), "image/png", "key", "{}"});
  SimulationToStore s;
  s.case_id = c.case_id;
  s.inputs_hash = "key";
  s.summary.model = "mtm";
  store_simulation(c.archive, s);
  const std::string error = testing::error_of([&] { latest_simulation(c.archive, c.case_id); });
  EXPECT_NE(error.find("(simulation-image): name: missing"), std::string::npos) << error;
}

}  // namespace
}  // namespace maxillo::records
