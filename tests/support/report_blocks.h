#pragma once
// The blocks of one type in a report section, in order, for tests of the section builders.
#include <string>
#include <variant>
#include <vector>

#include "report/report_model.h"

namespace maxillo::testing {

template <class Block>
std::vector<const Block*> blocks_of(const report::Section& section) {
  std::vector<const Block*> found;
  for (const auto& block : section.blocks)
    if (const auto* b = std::get_if<Block>(&block)) found.push_back(b);
  return found;
}

// The text of the section's notes, one per line.
inline std::string notes_of(const report::Section& section) {
  std::string text;
  for (const auto* note : blocks_of<report::Note>(section)) text += note->text + "\n";
  return text;
}

// The text of the section's paragraphs, one per line.
inline std::string paragraphs_of(const report::Section& section) {
  std::string text;
  for (const auto* paragraph : blocks_of<report::Paragraph>(section)) text += paragraph->text + "\n";
  return text;
}

}  // namespace maxillo::testing
