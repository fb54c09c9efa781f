// Bytes carried through UTF-8-only media (JSON, PostgreSQL text) and back unchanged.
#include <gtest/gtest.h>

#include "core/json.h"
#include "core/utf8.h"

namespace maxillo {
namespace {

TEST(BytesAsUtf8, ValidTextPassesAsItIs) {
  for (std::string text : {"", "/data/P1/1.dcm", "Müller^Jörg", "1.2.840.10008.1.2.1"})
    EXPECT_EQ(bytes_as_utf8(text), text);
}

TEST(BytesAsUtf8, AnyBytesComeBackUnchangedAndThroughJson) {
  const std::string latin1_path =
      "/share/sch\xE4"
      "del.dcm";
  const std::string with_nul("a\0b", 3);
  const std::string marker_lookalike = std::string(kBytesMarker) + "41";
  std::string every_byte;
  for (int b = 0; b < 256; ++b) every_byte += char(b);
  for (const auto& bytes : {latin1_path, with_nul, marker_lookalike, every_byte}) {
    const std::string text = bytes_as_utf8(bytes);
    EXPECT_TRUE(is_valid_utf8(text));
    EXPECT_EQ(text.find('\0'), std::string::npos);
    EXPECT_NE(text, bytes);
    EXPECT_EQ(bytes_from_utf8(text), bytes);
    // A strict JSON dump (which throws on invalid UTF-8) and a parse keep them.
    const Json parsed = Json::parse(Json{{"path", text}}.dump());
    EXPECT_EQ(bytes_from_utf8(parsed.at("path").get<std::string>()), bytes);
  }
  EXPECT_EQ(bytes_as_utf8(latin1_path), bytes_as_utf8(latin1_path));  // equal bytes, equal text
  EXPECT_NE(bytes_as_utf8(latin1_path), bytes_as_utf8("/share/sch\xC3\xA4"
                                                      "del.dcm"));  // not the "repaired" name
}

}  // namespace
}  // namespace maxillo
