#pragma once
// SHA-256 digests, the names of archived objects (content addressing) and of derived inputs.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace maxillo {

// Lower-case hex digest (64 characters) of a byte range.
std::string sha256_hex(std::span<const std::byte> bytes);
std::string sha256_hex(std::string_view text);

// Incremental hashing, for streams and for hashing several inputs into one key.
class Sha256 {
 public:
  Sha256();
  ~Sha256();
  Sha256(const Sha256&) = delete;
  Sha256& operator=(const Sha256&) = delete;
  void update(std::span<const std::byte> bytes);
  void update(std::string_view text);
  std::string hex_digest();  // finishes the hash; the object cannot be updated afterwards

 private:
  void* context_;  // EVP_MD_CTX, kept opaque so OpenSSL stays out of headers
};

}  // namespace maxillo
