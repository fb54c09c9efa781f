#pragma once
// The real PDF tools (poppler-utils, qpdf) on files the tests write. poppler's warnings about
// libharu's ToUnicode CMaps go to standard error, so the parsers below discard it.
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

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

// What an image embedded in a PDF holds: its size, how many distinct colours (capped at
// 100,000) and the fraction of pixels that differ from the top-left (background) pixel.
struct ImageContent {
  std::filesystem::path file;
  int width = 0, height = 0;
  size_t distinct_colours = 0;
  double foreground_fraction = 0;
};

// Reads a binary PPM (P6, 8-bit) as pdfimages writes it.
inline ImageContent inspect_ppm(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  int max_value = 0;
  ImageContent content;
  content.file = path;
  in >> magic >> content.width >> content.height >> max_value;
  in.get();
  if (magic != "P6" || max_value != 255) return content;
  std::vector<unsigned char> rgb(size_t(content.width) * content.height * 3);
  in.read(reinterpret_cast<char*>(rgb.data()), std::streamsize(rgb.size()));
  std::set<uint32_t> colours;
  size_t foreground = 0;
  for (size_t p = 0; p + 2 < rgb.size(); p += 3) {
    uint32_t colour = (uint32_t(rgb[p]) << 16) | (uint32_t(rgb[p + 1]) << 8) | rgb[p + 2];
    if (colours.size() < 100000) colours.insert(colour);
    if (rgb[p] != rgb[0] || rgb[p + 1] != rgb[1] || rgb[p + 2] != rgb[2]) ++foreground;
  }
  content.distinct_colours = colours.size();
  content.foreground_fraction = double(foreground) / (double(content.width) * content.height);
  return content;
}

// Extracts the PDF's images with pdfimages into `folder` and inspects those at least
// min_width pixels wide (rendered views, not colour bars or logos).
inline std::vector<ImageContent> pdf_images(const std::filesystem::path& pdf, const std::filesystem::path& folder,
                                            int min_width = 256) {
  std::filesystem::create_directories(folder);
  std::vector<ImageContent> images;
  if (run_command("pdfimages " + quote(pdf) + " " + quote(folder / "img") + " 2>/dev/null").exit_code != 0)
    return images;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() != ".ppm") continue;
    auto content = inspect_ppm(entry.path());
    if (content.width >= min_width) images.push_back(content);
  }
  return images;
}

}  // namespace maxillo::testing
