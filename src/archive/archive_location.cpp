#include "archive/archive_location.h"

#include <regex>

#include "core/error.h"

namespace maxillo {
namespace {

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// RFC 3986 percent-decoding of a query value (a folder may hold spaces or '&').
std::string percent_decoded(std::string_view text, std::string_view shown) {
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '%') {
      out += text[i];
      continue;
    }
    if (i + 2 >= text.size() || hex_digit(text[i + 1]) < 0 || hex_digit(text[i + 2]) < 0)
      throw Error(ErrorCode::kBadArchiveAddress, std::string(shown),
                  "a '%' in the objects folder is not followed by two hex digits");
    out += char(hex_digit(text[i + 1]) * 16 + hex_digit(text[i + 2]));
    i += 2;
  }
  return out;
}

}  // namespace

std::string without_password(std::string_view address) {
  static const std::regex in_uri(R"(^(postgres(?:ql)?://[^:/@]*):[^@]*@)");
  static const std::regex as_keyword(R"(password\s*=\s*\S+)");
  return std::regex_replace(std::regex_replace(std::string(address), in_uri, "$1@"), as_keyword, "password=***");
}

bool names_index_server(std::string_view text) {
  return text.starts_with("postgresql://") || text.starts_with("postgres://");
}

ArchiveLocation parse_archive_location(std::string_view text) {
  ArchiveLocation location;
  if (!names_index_server(text)) {
    location.folder = std::filesystem::path(text);
    location.shown = std::string(text);
    return location;
  }
  location.kind = ArchiveLocation::Kind::Server;
  location.shown = without_password(text);
  const auto fail = [&](const std::string& reason) {
    throw Error(ErrorCode::kBadArchiveAddress, location.shown, reason);
  };
  const size_t query_start = text.find('?');
  std::string_view base = text.substr(0, query_start);
  std::string_view query = query_start == std::string_view::npos ? "" : text.substr(query_start + 1);
  const size_t authority = base.find("://") + 3;
  const size_t path = base.find('/', authority);
  if (path == std::string_view::npos || path + 1 == base.size())
    fail("names no database (postgresql://user@host:port/DATABASE?objects=/shared/folder)");
  std::string kept;
  std::string objects;
  while (!query.empty()) {
    const size_t end = query.find('&');
    std::string_view parameter = query.substr(0, end);
    query = end == std::string_view::npos ? "" : query.substr(end + 1);
    if (parameter.starts_with("objects="))
      objects = percent_decoded(parameter.substr(8), location.shown);
    else if (!parameter.empty())
      kept += (kept.empty() ? "?" : "&") + std::string(parameter);
  }
  if (objects.empty())
    fail("has no objects parameter: the shared object folder is part of the address (...?objects=/shared/folder)");
  if (!std::filesystem::path(objects).is_absolute())
    fail("objects must be an absolute folder, not \"" + objects + "\"");
  // A server that does not answer should fail in seconds, not in libpq's default of forever.
  if (kept.find("connect_timeout=") == std::string::npos)
    kept += (kept.empty() ? "?" : "&") + std::string("connect_timeout=10");
  location.server_uri = std::string(base) + kept;
  location.folder = objects;
  return location;
}

}  // namespace maxillo
