#include "dicom/dicom_structure.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dctag.h>
#include <dcmtk/dcmdata/dcxfer.h>
#include <zlib.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "core/error.h"
#include "dicom/dicom_uid.h"

namespace maxillo {
namespace {

constexpr size_t kPreamble = 132;  // 128 bytes + "DICM"
constexpr uint32_t kUndefinedLength = 0xFFFFFFFFu;
constexpr uint16_t kItemGroup = 0xFFFE;
constexpr uint16_t kItem = 0xE000, kItemEnd = 0xE00D, kSequenceEnd = 0xE0DD;

enum class Encoding { ExplicitLittle, ImplicitLittle, ExplicitBig };

constexpr std::array<const char*, 34> kVrs = {"AE", "AS", "AT", "CS", "DA", "DS", "DT", "FD", "FL", "IS", "LO", "LT",
                                              "OB", "OD", "OF", "OL", "OV", "OW", "PN", "SH", "SL", "SQ", "SS", "ST",
                                              "SV", "TM", "UC", "UI", "UL", "UN", "UR", "US", "UT", "UV"};
// VRs whose explicit encoding has two reserved bytes and a 32-bit length.
constexpr std::array<const char*, 13> kLongVrs = {"OB", "OD", "OF", "OL", "OV", "OW", "SQ",
                                                  "SV", "UC", "UN", "UR", "UT", "UV"};

template <size_t N>
bool listed(const std::array<const char*, N>& list, const char vr[2]) {
  for (const char* known : list)
    if (known[0] == vr[0] && known[1] == vr[1]) return true;
  return false;
}

std::string hex4(uint32_t value) {
  char text[8];
  std::snprintf(text, sizeof text, "%04X", unsigned(value & 0xFFFF));
  return text;
}

std::string tag_text(uint16_t group, uint16_t element) { return "(" + hex4(group) + "," + hex4(element) + ")"; }

std::string vr_text(const char vr[2]) {
  std::string text;
  for (int k = 0; k < 2; ++k) {
    auto c = static_cast<unsigned char>(vr[k]);
    if (c >= 0x20 && c < 0x7F)
      text += char(c);
    else
      text += "\\x" + hex4(c).substr(2);
  }
  return text;
}

// Reads integers in the data set's byte order, refusing to read past the end.
class Reader {
 public:
  Reader(std::span<const std::byte> bytes, const std::filesystem::path& path) : bytes_(bytes), path_(path) {}
  size_t size() const { return bytes_.size(); }
  uint16_t u16(size_t at, bool big) const { return uint16_t(at_byte(at, big ? 0 : 1) << 8 | at_byte(at, big ? 1 : 0)); }
  uint32_t u32(size_t at, bool big) const {
    return big ? uint32_t(u16(at, true)) << 16 | u16(at + 2, true)
               : uint32_t(u16(at + 2, false)) << 16 | u16(at, false);
  }
  void chars(size_t at, char out[2]) const {
    out[0] = char(at_byte(at, 0));
    out[1] = char(at_byte(at, 1));
  }
  std::string text(size_t at, size_t length) const {
    return std::string(reinterpret_cast<const char*>(bytes_.data()) + at, length);
  }
  [[noreturn]] void fail(ErrorCode code, size_t at, const std::string& reason) const {
    throw Error(code, path_.string(), reason + " (at byte " + std::to_string(at) + ")");
  }

 private:
  uint32_t at_byte(size_t at, size_t k) const { return std::to_integer<uint32_t>(bytes_[at + k]); }
  std::span<const std::byte> bytes_;
  const std::filesystem::path& path_;
};

struct MetaInformation {
  size_t end = kPreamble;  // first byte of the data set
  std::string transfer_syntax;
};

// Group 0002 is always explicit VR little endian (PS3.10 7.1).
MetaInformation read_meta(const Reader& in) {
  MetaInformation meta;
  size_t at = kPreamble;
  int previous = -1;
  while (at + 8 <= in.size() && in.u16(at, false) == 0x0002) {
    const uint16_t element = in.u16(at + 2, false);
    // Elements ascend (PS3.5 7.1). A repeated Transfer Syntax UID would let this walk check the
    // data set under one syntax while DCMTK reads it under another (a fuzzing finding: deflated
    // here, raw there, and a 2.9 GB allocation).
    if (int(element) <= previous)
      in.fail(ErrorCode::kNotDicom, at, "file meta element " + tag_text(2, element) + " repeats or is out of order");
    previous = element;
    char vr[2];
    in.chars(at + 4, vr);
    if (!listed(kVrs, vr))
      in.fail(ErrorCode::kNotDicom, at,
              "file meta element " + tag_text(2, element) + " has no valid VR ('" + vr_text(vr) + "')");
    const bool long_form = listed(kLongVrs, vr);
    const size_t header = long_form ? 12 : 8;
    if (at + header > in.size()) in.fail(ErrorCode::kTruncated, at, "file ends inside the file meta information");
    const uint32_t length = long_form ? in.u32(at + 8, false) : in.u16(at + 6, false);
    if (length == kUndefinedLength || length > in.size() - at - header)
      in.fail(ErrorCode::kTruncated, at,
              "file meta element " + tag_text(2, element) + " claims more bytes than remain");
    if (element == 0x0010) {
      if (vr[0] != 'U' || vr[1] != 'I')
        in.fail(ErrorCode::kNotDicom, at, "Transfer Syntax UID (0002,0010) is not of VR UI");
      std::string uid = in.text(at + header, length);
      while (!uid.empty() && (uid.back() == '\0' || uid.back() == ' ')) uid.pop_back();
      // Strictly (a fuzzing finding: "1.2.840.10008.14.2..80" passed a digits-and-dots check, this
      // walk read the data set as explicit VR while DCMTK, not knowing the syntax, guessed another
      // encoding and allocated 3.2 GB for a length it read from the wrong bytes).
      if (auto fault = uid_fault(uid))
        in.fail(ErrorCode::kNotDicom, at, "Transfer Syntax UID (0002,0010) is not a UID: " + *fault);
      meta.transfer_syntax = uid;
    }
    at += header + length;
  }
  if (at == kPreamble) in.fail(ErrorCode::kNotDicom, at, "no file meta information (group 0002)");
  meta.end = at;
  return meta;
}

std::vector<std::byte> inflate_data_set(std::span<const std::byte> deflated, const std::filesystem::path& path) {
  z_stream stream{};
  if (inflateInit2(&stream, -MAX_WBITS) != Z_OK) throw Error(ErrorCode::kProcessing, path.string(), "zlib unavailable");
  std::vector<std::byte> out;
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<std::byte*>(deflated.data()));
  stream.avail_in = uInt(deflated.size());
  int status = Z_OK;
  while (status == Z_OK) {
    if (out.size() >= kMaxInflatedBytes) {
      inflateEnd(&stream);
      throw Error(ErrorCode::kBadValue, path.string(), "deflated data set inflates beyond 1 GiB");
    }
    const size_t done = out.size();
    out.resize(std::min(kMaxInflatedBytes, std::max<size_t>(done * 2, 1 << 16)));
    stream.next_out = reinterpret_cast<Bytef*>(out.data() + done);
    stream.avail_out = uInt(out.size() - done);
    status = inflate(&stream, Z_NO_FLUSH);
    out.resize(out.size() - stream.avail_out);
    if (status == Z_BUF_ERROR && stream.avail_in == 0) break;  // no more input: ends short
    if (status == Z_BUF_ERROR) status = Z_OK;
  }
  inflateEnd(&stream);
  if (status != Z_STREAM_END && status != Z_BUF_ERROR)
    throw Error(ErrorCode::kNotDicom, path.string(), "deflated data set cannot be inflated");
  return out;
}

// One open sequence, item or run of pixel data fragments.
struct Container {
  enum class Kind { Sequence, Item, Fragments } kind;
  size_t limit;  // the end of this container if its length is defined, else the enclosing limit
  bool undefined;
  Encoding encoding;
};

class DataSetWalk {
 public:
  DataSetWalk(const Reader& in, size_t start, Encoding encoding) : in_(in), at_(start), encoding_(encoding) {}

  void run() {
    for (;;) {
      while (!open_.empty() && !open_.back().undefined && at_ == open_.back().limit) close();
      const size_t limit = open_.empty() ? in_.size() : open_.back().limit;
      if (at_ == limit) {
        if (open_.empty()) return;
        in_.fail(ErrorCode::kTruncated, at_, "file ends inside a sequence");
      }
      if (limit - at_ < 8) in_.fail(ErrorCode::kTruncated, at_, "file ends inside an element header");
      step(limit);
    }
  }

 private:
  Encoding encoding() const { return open_.empty() ? encoding_ : open_.back().encoding; }
  bool big() const { return encoding() == Encoding::ExplicitBig; }

  void close() {
    if (open_.back().kind == Container::Kind::Sequence) --depth_;
    open_.pop_back();
  }

  void open(Container::Kind kind, size_t limit, bool undefined, Encoding encoding) {
    if (kind == Container::Kind::Sequence && ++depth_ > kMaxSequenceNesting)
      in_.fail(ErrorCode::kBadValue, at_,
               "sequences nested deeper than " + std::to_string(kMaxSequenceNesting) + " levels");
    open_.push_back({kind, limit, undefined, encoding});
  }

  void step(size_t limit) {
    const uint16_t group = in_.u16(at_, big()), element = in_.u16(at_ + 2, big());
    if (group == kItemGroup) return item_tag(element, in_.u32(at_ + 4, big()), limit);
    if (!open_.empty() && open_.back().kind != Container::Kind::Item)
      in_.fail(ErrorCode::kNotDicom, at_, "element " + tag_text(group, element) + " outside an item of its sequence");
    char vr[2] = {'?', '?'};
    size_t header = 8;
    uint32_t length = 0;
    if (encoding() == Encoding::ImplicitLittle) {
      length = in_.u32(at_ + 4, false);
      if (DcmTag(group, element).getEVR() == EVR_SQ) vr[0] = 'S', vr[1] = 'Q';
    } else {
      in_.chars(at_ + 4, vr);
      if (!listed(kVrs, vr))
        in_.fail(ErrorCode::kNotDicom, at_,
                 "element " + tag_text(group, element) + " has no valid VR ('" + vr_text(vr) + "')");
      if (listed(kLongVrs, vr)) {
        header = 12;
        if (limit - at_ < header) in_.fail(ErrorCode::kTruncated, at_, "file ends inside an element header");
        length = in_.u32(at_ + 8, big());
      } else {
        length = in_.u16(at_ + 6, big());
      }
    }
    const size_t start = at_;
    at_ += header;
    const bool sequence = vr[0] == 'S' && vr[1] == 'Q';
    if (length == kUndefinedLength) return undefined_length(group, element, vr, sequence, start, limit);
    if (length > limit - at_)
      in_.fail(ErrorCode::kTruncated, start,
               "element " + tag_text(group, element) + " claims " + std::to_string(length) + " bytes, " +
                   std::to_string(limit - at_) + " remain");
    if (sequence)
      open(Container::Kind::Sequence, at_ + length, false, encoding());
    else
      at_ += length;
  }

  void undefined_length(uint16_t group, uint16_t element, const char vr[2], bool sequence, size_t start, size_t limit) {
    const bool unknown = vr[0] == 'U' && vr[1] == 'N';
    const bool implicit = encoding() == Encoding::ImplicitLittle;
    if (group == 0x7FE0 && element == 0x0010) return open(Container::Kind::Fragments, limit, true, encoding());
    if (!(sequence || unknown || implicit))
      in_.fail(ErrorCode::kNotDicom, start,
               "element " + tag_text(group, element) + " of VR " + vr_text(vr) + " has an undefined length");
    // UN of undefined length holds a sequence in implicit VR little endian (PS3.5 6.2.2).
    open(Container::Kind::Sequence, limit, true, unknown ? Encoding::ImplicitLittle : encoding());
  }

  void item_tag(uint16_t element, uint32_t length, size_t limit) {
    const size_t start = at_;
    at_ += 8;
    const Container* parent = open_.empty() ? nullptr : &open_.back();
    if (element == kItem) {
      if (!parent || parent->kind == Container::Kind::Item)
        in_.fail(ErrorCode::kNotDicom, start, "item outside a sequence");
      if (parent->kind == Container::Kind::Fragments) {  // compressed pixel data: raw bytes
        if (length == kUndefinedLength || length > limit - at_)
          in_.fail(ErrorCode::kTruncated, start, "pixel data fragment runs past the end");
        at_ += length;
        return;
      }
      if (length == kUndefinedLength) return open(Container::Kind::Item, limit, true, parent->encoding);
      if (length > limit - at_) in_.fail(ErrorCode::kTruncated, start, "item claims more bytes than remain");
      return open(Container::Kind::Item, at_ + length, false, parent->encoding);
    }
    const bool ends_item = element == kItemEnd && parent && parent->kind == Container::Kind::Item && parent->undefined;
    const bool ends_sequence =
        element == kSequenceEnd && parent && parent->kind != Container::Kind::Item && parent->undefined;
    if (!ends_item && !ends_sequence)
      in_.fail(ErrorCode::kNotDicom, start, "misplaced delimiter " + tag_text(kItemGroup, element));
    close();
  }

  const Reader& in_;
  size_t at_;
  Encoding encoding_;
  std::vector<Container> open_;
  int depth_ = 0;
};

// The encoding DCMTK reads the data set of a syntax it knows in.
Encoding encoding_of(const DcmXfer& xfer) {
  if (!xfer.isExplicitVR()) return Encoding::ImplicitLittle;
  return xfer.isBigEndian() ? Encoding::ExplicitBig : Encoding::ExplicitLittle;
}

}  // namespace

void check_dicom_structure(std::span<const std::byte> bytes, const std::filesystem::path& path) {
  Reader in(bytes, path);
  if (bytes.size() < kPreamble || std::memcmp(bytes.data() + 128, "DICM", 4) != 0)
    throw Error(ErrorCode::kNotDicom, path.string(), "no DICM prefix at byte 128 (not a DICOM Part 10 file)");
  MetaInformation meta = read_meta(in);
  if (meta.transfer_syntax.empty())
    throw Error(ErrorCode::kMissingAttribute, path.string(), "no Transfer Syntax UID (0002,0010)");
  // A syntax DCMTK does not know is refused: DCMTK would guess the encoding from the data set's
  // first bytes (a fuzzing finding: "1.2.3.4" with a first group of 0x0800 was guessed big endian
  // while this walk read little endian; DCMTK's reading drifted into a value and allocated 2 GiB
  // for a length it found there).
  const DcmXfer xfer(meta.transfer_syntax.c_str());
  if (xfer.getXfer() == EXS_Unknown)
    throw Error(ErrorCode::kUnsupportedSyntax, path.string(), "unknown transfer syntax " + meta.transfer_syntax);
  const Encoding encoding = encoding_of(xfer);
  // Deflated explicit VR little endian, and JPIP referenced deflate: DCMTK inflates both.
  if (xfer.getStreamCompression() == ESC_zlib) {
    auto inflated = inflate_data_set(bytes.subspan(meta.end), path);
    Reader data(inflated, path);
    DataSetWalk(data, 0, encoding).run();
    return;
  }
  DataSetWalk(in, meta.end, encoding).run();
}

}  // namespace maxillo
