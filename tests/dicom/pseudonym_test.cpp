// The keyed pseudonyms and UIDs of de-identified copies: valid, deterministic, and a function of
// the secret. The copies themselves, as the archive exports them: tests/archive/deidentify_test.cpp.
#include <gtest/gtest.h>

#include <regex>

#include "dicom/dicom_deidentify.h"

namespace maxillo {
namespace {

TEST(Deidentify, PseudonymousUidsAreValidDeterministicAndKeyed) {
  std::regex uid_form("2\\.25\\.[1-9][0-9]*");
  auto uid = pseudonymous_uid("secret", "1.2.3.4");
  EXPECT_TRUE(std::regex_match(uid, uid_form)) << uid;
  EXPECT_LE(uid.size(), 64u);
  EXPECT_EQ(uid, pseudonymous_uid("secret", "1.2.3.4"));
  EXPECT_NE(uid, pseudonymous_uid("other secret", "1.2.3.4"));
  EXPECT_NE(uid, pseudonymous_uid("secret", "1.2.3.5"));
  EXPECT_EQ(pseudonym_for("secret", "P1").size(), 17u);
  EXPECT_NE(pseudonym_for("secret", "P1"), pseudonym_for("secret", "P2"));
}

}  // namespace
}  // namespace maxillo
