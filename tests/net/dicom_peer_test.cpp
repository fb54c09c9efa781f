// Peers as people write them on the command line: AE@host:port, and AE[@host] for --allow.
#include <gtest/gtest.h>

#include "core/error.h"
#include "net/dicom_peer.h"
#include "net/retrieve_client.h"

namespace maxillo::net {
namespace {

ErrorCode error_of(auto&& call) {
  try {
    call();
  } catch (const Error& error) {
    return error.code();
  }
  return ErrorCode::kProcessing;  // no error: a code the assertions never expect
}

TEST(DicomPeer, ParsesAeHostAndPort) {
  const DicomPeer peer = parse_peer("ORTHANC@127.0.0.1:4242");
  EXPECT_EQ(peer.ae_title, "ORTHANC");
  EXPECT_EQ(peer.host, "127.0.0.1");
  EXPECT_EQ(peer.port, 4242);
  EXPECT_EQ(to_string(peer), "ORTHANC@127.0.0.1:4242");
  EXPECT_EQ(parse_peer("A B@pacs-1.example:104").ae_title, "A B");  // spaces are allowed inside
}

TEST(DicomPeer, RefusesWhatIsNotAPeer) {
  for (const char* text :
       {"ORTHANC", "ORTHANC@127.0.0.1", "127.0.0.1:4242", "@127.0.0.1:4242", "ORTHANC@:4242", "ORTHANC@127.0.0.1:0",
        "ORTHANC@127.0.0.1:65536", "ORTHANC@127.0.0.1:42x", "SEVENTEEN_CHARS_X@127.0.0.1:4242",
        "BACK\\SLASH@127.0.0.1:4242", "    @127.0.0.1:4242", "ORTHANC@host/name:4242"})
    EXPECT_EQ(error_of([&] { parse_peer(text); }), ErrorCode::kUsage) << text;
}

TEST(AllowedPeer, MatchesTheTitleAndTheAddressWhenGiven) {
  const std::vector<AllowedPeer> allowed = {parse_allowed_peer("SCANNER"), parse_allowed_peer("PACS@10.0.0.5")};
  EXPECT_TRUE(is_allowed(allowed, "SCANNER", "127.0.0.1"));
  EXPECT_TRUE(is_allowed(allowed, "PACS", "10.0.0.5"));
  EXPECT_FALSE(is_allowed(allowed, "PACS", "127.0.0.1"));
  EXPECT_FALSE(is_allowed(allowed, "scanner", "127.0.0.1")) << "AE titles are case-sensitive";
  EXPECT_FALSE(is_allowed({}, "SCANNER", "127.0.0.1")) << "nobody is allowed by default";
  EXPECT_EQ(error_of([] { parse_allowed_peer(""); }), ErrorCode::kUsage);
  EXPECT_EQ(error_of([] { parse_allowed_peer("PACS@"); }), ErrorCode::kUsage);
}

// Issue 29, fault 13: a C-GET failure printed "status 49152".
TEST(RetrieveStatus, IsShownInHexadecimalWithItsMeaning) {
  EXPECT_EQ(status_text("C-GET", 0xC000).substr(0, 9), "0xC000 (F");
  EXPECT_NE(status_text("C-GET", 0xC000).find("Failed"), std::string::npos) << status_text("C-GET", 0xC000);
  EXPECT_NE(status_text("C-MOVE", 0xA801).find("0xA801"), std::string::npos);
  EXPECT_NE(status_text("C-MOVE", 0xA801).find("Refused"), std::string::npos) << status_text("C-MOVE", 0xA801);
}

}  // namespace
}  // namespace maxillo::net
