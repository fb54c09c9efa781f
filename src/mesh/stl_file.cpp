#include "mesh/stl_file.h"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <string_view>
#include <vector>

#include "core/error.h"

namespace maxillo {
namespace {

using Corner = std::array<float, 3>;

// Triangles as corner coordinates -> a mesh whose equal corners share a vertex.
class CornerMerger {
 public:
  void add_triangle(const std::array<Corner, 3>& corners) {
    std::array<int, 3> face{};
    for (int c = 0; c < 3; ++c) {
      auto [it, inserted] = index_.emplace(corners[size_t(c)], int(vertices_.size()));
      if (inserted) vertices_.push_back(corners[size_t(c)]);
      face[size_t(c)] = it->second;
    }
    faces_.push_back(face);
  }
  TriangleMesh mesh() const {
    TriangleMesh mesh;
    mesh.vertices.resize(Eigen::Index(vertices_.size()), 3);
    for (size_t v = 0; v < vertices_.size(); ++v)
      for (int a = 0; a < 3; ++a) mesh.vertices(Eigen::Index(v), a) = vertices_[v][size_t(a)];
    mesh.faces.resize(Eigen::Index(faces_.size()), 3);
    for (size_t f = 0; f < faces_.size(); ++f)
      for (int c = 0; c < 3; ++c) mesh.faces(Eigen::Index(f), c) = faces_[f][size_t(c)];
    return mesh;
  }

 private:
  std::map<Corner, int> index_;
  std::vector<Corner> vertices_;
  std::vector<std::array<int, 3>> faces_;
};

[[noreturn]] void refuse_stl(const std::string& source, const std::string& reason) {
  throw Error(ErrorCode::kBadValue, source, "not an STL file: " + reason);
}

Corner finite_corner(const Corner& corner, const std::string& source) {
  for (float value : corner)
    if (!std::isfinite(value))
      throw Error(ErrorCode::kBadValue, source, "vertex coordinates that are not finite numbers");
  return corner;
}

bool is_text(std::span<const std::byte> bytes) {
  for (std::byte b : bytes) {
    const auto c = std::to_integer<unsigned char>(b);
    if (c >= 0x7F || (c < 0x20 && c != '\n' && c != '\r' && c != '\t')) return false;
  }
  return true;
}

TriangleMesh parse_binary(std::span<const std::byte> bytes, const std::string& source) {
  if (bytes.size() < 84) refuse_stl(source, "shorter than the 84-byte header of a binary STL");
  uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);  // little endian, as the format and x86 are
  const uint64_t expected = 84 + 50 * uint64_t(count);
  if (expected != bytes.size())
    refuse_stl(source, "a binary STL of " + std::to_string(count) + " triangles is " + std::to_string(expected) +
                           " bytes, this file " + std::to_string(bytes.size()));
  CornerMerger merger;
  for (uint32_t t = 0; t < count; ++t) {
    std::array<Corner, 3> corners{};
    const std::byte* record = bytes.data() + 84 + 50 * size_t(t) + 12;  // after the normal
    for (int c = 0; c < 3; ++c) {
      std::memcpy(corners[size_t(c)].data(), record + 12 * c, 12);
      finite_corner(corners[size_t(c)], source);
    }
    merger.add_triangle(corners);
  }
  return merger.mesh();
}

// Whitespace-separated words of an ASCII STL, read one at a time.
class Words {
 public:
  explicit Words(std::string_view text) : text_(text) {}
  std::string_view next() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
    const size_t start = at_;
    while (at_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
    return text_.substr(start, at_ - start);
  }
  void skip_line() {
    while (at_ < text_.size() && text_[at_] != '\n') ++at_;
  }

 private:
  std::string_view text_;
  size_t at_ = 0;
};

TriangleMesh parse_ascii(std::string_view text, const std::string& source) {
  Words words(text);
  words.next();       // "solid"
  words.skip_line();  // the solid's name, any text
  auto expect = [&](std::string_view word) {
    const auto got = words.next();
    if (got != word)
      refuse_stl(source, "expected \"" + std::string(word) + "\", found \"" + std::string(got.substr(0, 40)) + "\"");
  };
  auto number = [&] {
    const auto word = words.next();
    float value = 0;
    auto [end, status] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (status != std::errc() || end != word.data() + word.size())
      refuse_stl(source, "\"" + std::string(word.substr(0, 40)) + "\" is not a number");
    return value;
  };
  CornerMerger merger;
  for (;;) {
    const auto word = words.next();
    if (word == "endsolid") break;
    if (word != "facet")
      refuse_stl(source, word.empty() ? "no endsolid"
                                      : "expected \"facet\", found \"" + std::string(word.substr(0, 40)) + "\"");
    expect("normal");
    for (int a = 0; a < 3; ++a) number();
    expect("outer");
    expect("loop");
    std::array<Corner, 3> corners{};
    for (auto& corner : corners) {
      expect("vertex");
      for (float& value : corner) value = number();
      finite_corner(corner, source);
    }
    expect("endloop");
    expect("endfacet");
    merger.add_triangle(corners);
  }
  return merger.mesh();
}

}  // namespace

TriangleMesh parse_stl(std::span<const std::byte> bytes, const std::string& source) {
  const bool starts_solid = bytes.size() >= 5 && std::memcmp(bytes.data(), "solid", 5) == 0;
  // Some binary files begin their header with "solid" too; only text is read as ASCII.
  if (starts_solid && is_text(bytes))
    return parse_ascii(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), source);
  return parse_binary(bytes, source);
}

}  // namespace maxillo
