#pragma once
// The real PDF tools (poppler-utils, qpdf) on files the tests write. poppler's warnings about
// libharu's ToUnicode CMaps go to standard error, so the parsers below discard it.
#include <filesystem>
#include <string>

#include "support/run_command.h"

namespace maxillo::testing {

inline int pdf_page_count(const std::filesystem::path& pdf) {
  auto info = run_command("pdfinfo " + quote(pdf) + " 2>/dev/null");
  auto at = info.output.find("Pages:");
  return at == std::string::npos ? -1 : std::stoi(info.output.substr(at + 6));
}

inline std::string pdf_text(const std::filesystem::path& pdf) {
  return run_command("pdftotext -enc UTF-8 " + quote(pdf) + " - 2>/dev/null").output;
}

// pdfimages -list prints two header lines, then one line per image.
inline int pdf_image_count(const std::filesystem::path& pdf) {
  auto list = run_command("pdfimages -list " + quote(pdf) + " 2>/dev/null").output;
  int lines = 0;
  for (char c : list) lines += c == '\n';
  return lines - 2;
}

inline std::size_t count_of(const std::string& text, const std::string& needle) {
  std::size_t count = 0;
  for (auto at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++count;
  return count;
}

}  // namespace maxillo::testing
