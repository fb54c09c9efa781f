// The one list of artefact kinds: unique names that parse back, unknown names not guessed.
#include "archive/artefact_kind.h"

#include <gtest/gtest.h>

#include <set>

namespace maxillo {
namespace {

TEST(ArtefactKind, NamesAreUniqueAndParseBack) {
  std::set<std::string> names;
  for (ArtefactKind kind : kAllArtefactKinds) {
    const std::string name = kind_name(kind);
    EXPECT_TRUE(names.insert(name).second) << name << " twice";
    EXPECT_EQ(parse_artefact_kind(name), kind) << name;
  }
  EXPECT_EQ(names.size(), std::size(kAllArtefactKinds));
  EXPECT_FALSE(parse_artefact_kind("render"));
  EXPECT_FALSE(parse_artefact_kind("Plan"));
  EXPECT_FALSE(parse_artefact_kind(""));
}

}  // namespace
}  // namespace maxillo
