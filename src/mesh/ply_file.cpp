#include "mesh/ply_file.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string_view>
#include <vector>

#include "core/error.h"

namespace maxillo {
namespace {

enum class Format { Ascii, BinaryLittle, BinaryBig };

struct Property {
  std::string name;
  int size = 0;           // bytes of the value (binary), or of each list item
  bool is_float = false;  // float32/float64 rather than an integer type
  bool is_signed = false;
  bool is_list = false;
  int count_size = 0;         // lists: bytes of the item count (an integer type) ...
  bool count_signed = false;  // ... and whether it is signed
};

struct Element {
  std::string name;
  uint64_t count = 0;
  std::vector<Property> properties;
};

[[noreturn]] void refuse_ply(const std::string& source, const std::string& reason) {
  throw Error(ErrorCode::kBadValue, source, "not a PLY file: " + reason);
}

// Byte size and kind of a PLY scalar type name; nullopt for an unknown name.
std::optional<Property> scalar_type(std::string_view name) {
  struct Known {
    std::string_view a, b;
    int size;
    bool is_float, is_signed;
  };
  static constexpr Known kTypes[] = {{"char", "int8", 1, false, true},    {"uchar", "uint8", 1, false, false},
                                     {"short", "int16", 2, false, true},  {"ushort", "uint16", 2, false, false},
                                     {"int", "int32", 4, false, true},    {"uint", "uint32", 4, false, false},
                                     {"float", "float32", 4, true, true}, {"double", "float64", 8, true, true}};
  for (const auto& type : kTypes)
    if (name == type.a || name == type.b) {
      Property p;
      p.size = type.size;
      p.is_float = type.is_float;
      p.is_signed = type.is_signed;
      return p;
    }
  return std::nullopt;
}

std::vector<std::string_view> words_of(std::string_view line) {
  std::vector<std::string_view> words;
  size_t at = 0;
  while (at < line.size()) {
    while (at < line.size() && (line[at] == ' ' || line[at] == '\t' || line[at] == '\r')) ++at;
    const size_t start = at;
    while (at < line.size() && line[at] != ' ' && line[at] != '\t' && line[at] != '\r') ++at;
    if (at > start) words.push_back(line.substr(start, at - start));
  }
  return words;
}

struct Header {
  Format format = Format::Ascii;
  std::vector<Element> elements;
  size_t body = 0;  // offset of the first byte after end_header
};

Property parse_property(const std::vector<std::string_view>& w, const std::string& source) {
  if (w.size() == 3) {
    auto p = scalar_type(w[1]);
    if (!p) refuse_ply(source, "unknown property type \"" + std::string(w[1]) + "\"");
    p->name = w[2];
    return *p;
  }
  if (w.size() == 5 && w[1] == "list") {
    auto count = scalar_type(w[2]);
    auto item = scalar_type(w[3]);
    if (!count || !item || count->is_float) refuse_ply(source, "bad list property types");
    item->name = w[4];
    item->is_list = true;
    item->count_size = count->size;
    item->count_signed = count->is_signed;
    return *item;
  }
  refuse_ply(source, "malformed property line");
}

Header parse_header(std::string_view text, const std::string& source) {
  Header header;
  size_t at = 0;
  bool format_seen = false;
  for (int line_number = 1;; ++line_number) {
    const size_t end = text.find('\n', at);
    if (end == std::string_view::npos) refuse_ply(source, "no end_header");
    const auto w = words_of(text.substr(at, end - at));
    at = end + 1;
    if (line_number == 1) {
      if (w.size() != 1 || w[0] != "ply") refuse_ply(source, "does not begin with \"ply\"");
      continue;
    }
    if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
    if (w[0] == "end_header") break;
    if (w[0] == "format") {
      if (w.size() != 3 || w[2] != "1.0") refuse_ply(source, "unsupported format line");
      if (w[1] == "ascii")
        header.format = Format::Ascii;
      else if (w[1] == "binary_little_endian")
        header.format = Format::BinaryLittle;
      else if (w[1] == "binary_big_endian")
        header.format = Format::BinaryBig;
      else
        refuse_ply(source, "unknown format \"" + std::string(w[1]) + "\"");
      format_seen = true;
    } else if (w[0] == "element") {
      Element element;
      if (w.size() != 3) refuse_ply(source, "malformed element line");
      element.name = w[1];
      auto [ptr, status] = std::from_chars(w[2].data(), w[2].data() + w[2].size(), element.count);
      if (status != std::errc() || ptr != w[2].data() + w[2].size()) refuse_ply(source, "bad element count");
      header.elements.push_back(std::move(element));
    } else if (w[0] == "property") {
      if (header.elements.empty()) refuse_ply(source, "a property before any element");
      header.elements.back().properties.push_back(parse_property(w, source));
    } else {
      refuse_ply(source, "unknown header line \"" + std::string(w[0].substr(0, 40)) + "\"");
    }
  }
  if (!format_seen) refuse_ply(source, "no format line");
  header.body = at;
  return header;
}

// Values of the body, in the file's encoding, never read past its end.
class BodyReader {
 public:
  BodyReader(std::span<const std::byte> bytes, Format format, const std::string& source)
      : bytes_(bytes), format_(format), source_(source) {}

  size_t remaining() const { return bytes_.size() - at_; }

  double value(int size, bool is_float, bool is_signed) {
    if (format_ == Format::Ascii) return ascii_value();
    if (remaining() < size_t(size)) refuse_ply(source_, "ends inside its data");
    uint8_t raw[8] = {};
    std::memcpy(raw, bytes_.data() + at_, size_t(size));
    at_ += size_t(size);
    if ((format_ == Format::BinaryBig) == (std::endian::native == std::endian::little))
      for (int i = 0; i < size / 2; ++i) std::swap(raw[i], raw[size - 1 - i]);
    return decode(raw, size, is_float, is_signed);
  }

 private:
  static double decode(const uint8_t* raw, int size, bool is_float, bool is_signed) {
    if (is_float && size == 4) {
      float value = 0;
      std::memcpy(&value, raw, 4);
      return value;
    }
    if (is_float) {
      double value = 0;
      std::memcpy(&value, raw, 8);
      return value;
    }
    uint64_t u = 0;
    std::memcpy(&u, raw, size_t(size));
    if (!is_signed) return double(u);
    const int shift = 64 - 8 * size;
    return double(int64_t(u << shift) >> shift);  // sign-extend
  }

  double ascii_value() {
    while (at_ < bytes_.size() && std::isspace(std::to_integer<unsigned char>(bytes_[at_]))) ++at_;
    const char* start = reinterpret_cast<const char*>(bytes_.data()) + at_;
    const char* end = reinterpret_cast<const char*>(bytes_.data()) + bytes_.size();
    double value = 0;
    auto [ptr, status] = std::from_chars(start, end, value);
    if (status != std::errc() || ptr == start) refuse_ply(source_, "a value of the data is not a number");
    at_ += size_t(ptr - start);
    return value;
  }

  std::span<const std::byte> bytes_;
  Format format_;
  const std::string& source_;
  size_t at_ = 0;
};

// The fewest bytes one instance of the element can take: to refuse impossible counts early.
size_t smallest_record(const Element& element, Format format) {
  size_t bytes = 0;
  for (const auto& p : element.properties)
    bytes += format == Format::Ascii ? 2 : size_t(p.is_list ? p.count_size : p.size);
  return std::max<size_t>(bytes, 1);
}

int index_of(const Element& element, std::string_view name) {
  for (size_t i = 0; i < element.properties.size(); ++i)
    if (element.properties[i].name == name) return int(i);
  return -1;
}

}  // namespace

TriangleMesh parse_ply(std::span<const std::byte> bytes, const std::string& source) {
  const Header header =
      parse_header(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), source);
  BodyReader body(bytes.subspan(header.body), header.format, source);
  std::vector<double> coordinates;
  std::vector<std::array<int64_t, 3>> triangles;
  bool vertices_seen = false, faces_seen = false;
  for (const Element& element : header.elements) {
    if (element.count > body.remaining() / smallest_record(element, header.format))
      refuse_ply(source, "element " + element.name + " claims more records than the file holds");
    const bool is_vertex = element.name == "vertex", is_face = element.name == "face";
    const int x = index_of(element, "x"), y = index_of(element, "y"), z = index_of(element, "z");
    int list = index_of(element, "vertex_indices");
    if (list < 0) list = index_of(element, "vertex_index");
    if (is_vertex && (x < 0 || y < 0 || z < 0)) refuse_ply(source, "vertices without x, y and z");
    if (is_face && (list < 0 || !element.properties[size_t(list)].is_list))
      refuse_ply(source, "faces without vertex_indices");
    vertices_seen |= is_vertex;
    faces_seen |= is_face;
    if (is_vertex) coordinates.reserve(size_t(element.count) * 3);
    for (uint64_t record = 0; record < element.count; ++record) {
      double xyz[3] = {};
      for (size_t p = 0; p < element.properties.size(); ++p) {
        const Property& property = element.properties[p];
        if (!property.is_list) {
          const double v = body.value(property.size, property.is_float, property.is_signed);
          for (int a = 0; a < 3; ++a)
            if (int(p) == (a == 0 ? x : a == 1 ? y : z)) xyz[a] = v;
          continue;
        }
        const double n = body.value(property.count_size, false, property.count_signed);
        if (!(n >= 0) || n > double(body.remaining())) refuse_ply(source, "a list longer than the file");
        std::vector<int64_t> items(static_cast<size_t>(n));
        for (auto& item : items) {
          const double v = body.value(property.size, property.is_float, property.is_signed);
          if (!(std::abs(v) < 1e15)) refuse_ply(source, "a vertex index that is not a number in range");  // NaN too
          item = int64_t(v);
        }
        if (is_face && int(p) == list) {
          if (items.size() < 3) refuse_ply(source, "a face with fewer than 3 vertices");
          for (size_t k = 1; k + 1 < items.size(); ++k) triangles.push_back({items[0], items[k], items[k + 1]});
        }
      }
      if (is_vertex) coordinates.insert(coordinates.end(), xyz, xyz + 3);
    }
  }
  if (!vertices_seen || !faces_seen) refuse_ply(source, "no vertex or no face element");
  TriangleMesh mesh;
  const auto vertex_count = Eigen::Index(coordinates.size() / 3);
  mesh.vertices = Eigen::Map<const VertexMatrix>(coordinates.data(), vertex_count, 3);
  if (!mesh.vertices.allFinite())
    throw Error(ErrorCode::kBadValue, source, "vertex coordinates that are not finite numbers");
  mesh.faces.resize(Eigen::Index(triangles.size()), 3);
  for (size_t f = 0; f < triangles.size(); ++f)
    for (int c = 0; c < 3; ++c) {
      const int64_t index = triangles[f][size_t(c)];
      if (index < 0 || index >= vertex_count)
        refuse_ply(source, "a face names vertex " + std::to_string(index) + " of " + std::to_string(vertex_count));
      mesh.faces(Eigen::Index(f), c) = int(index);
    }
  return mesh;
}

}  // namespace maxillo
