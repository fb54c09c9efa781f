#include "archive/index_journal.h"

#include <algorithm>
#include <charconv>
#include <cstdio>

#include "core/atomic_file.h"
#include "core/error.h"

namespace maxillo {
namespace {

constexpr const char* kFormat = "maxillo-index-journal";
constexpr int kFormatVersion = 1;
constexpr int64_t kEntriesPerFolder = 10000;  // keeps folders small at millions of entries

std::string padded(int64_t number, int digits) {
  char text[32];
  std::snprintf(text, sizeof text, "%0*lld", digits, static_cast<long long>(number));
  return text;
}

std::optional<int64_t> number_of(const std::string& name, size_t digits) {
  if (name.size() != digits) return std::nullopt;
  int64_t number = 0;
  auto [end, status] = std::from_chars(name.data(), name.data() + name.size(), number);
  if (status != std::errc() || end != name.data() + name.size()) return std::nullopt;
  return number;
}

[[noreturn]] void damaged(const std::filesystem::path& path, const std::string& reason) {
  throw Error(ErrorCode::kIndexDamaged, path.string(), "journal entry unreadable: " + reason);
}

}  // namespace

std::string journal_entry_text(const JournalEntry& entry) {
  Json rows = Json::array();
  for (const auto& row : entry.rows) rows.push_back({{"table", row.table}, {"values", row.values}});
  Json json = {{"format", kFormat},      {"version", kFormatVersion},    {"sequence", entry.sequence},
               {"at", entry.at},         {"operation", entry.operation}, {"program_version", entry.program_version},
               {"rows", std::move(rows)}};
  // Text was decoded to UTF-8 on import; replace, never fail, should anything else slip in.
  return json.dump(1, ' ', false, Json::error_handler_t::replace) + "\n";
}

JournalEntry parse_journal_entry(std::string_view text, const std::filesystem::path& path) {
  Json json = Json::parse(text, nullptr, false);
  if (json.is_discarded() || !json.is_object()) damaged(path, "not JSON");
  if (json.value("format", "") != kFormat) damaged(path, "not a maxillo index journal entry");
  if (!json.contains("version") || !json["version"].is_number_integer() || json["version"].get<int>() != kFormatVersion)
    damaged(path, "unknown journal format version");
  try {
    JournalEntry entry;
    entry.sequence = json.at("sequence").get<int64_t>();
    entry.at = json.at("at").get<std::string>();
    entry.operation = json.at("operation").get<std::string>();
    entry.program_version = json.at("program_version").get<std::string>();
    for (const auto& row : json.at("rows")) {
      if (!row.at("values").is_object()) damaged(path, "a row is not an object");
      entry.rows.push_back({row.at("table").get<std::string>(), row.at("values")});
    }
    return entry;
  } catch (const Json::exception& e) {
    damaged(path, e.what());
  }
}

IndexJournal::IndexJournal(std::filesystem::path folder) : folder_(std::move(folder)) {}

std::filesystem::path IndexJournal::path_of(int64_t sequence) const {
  return folder_ / padded(sequence / kEntriesPerFolder, 8) / (padded(sequence, 12) + ".json");
}

bool IndexJournal::has(int64_t sequence) const {
  std::error_code ignored;
  return std::filesystem::exists(path_of(sequence), ignored);
}

void IndexJournal::write(const JournalEntry& entry) const {
  auto path = path_of(entry.sequence);
  create_folders_durably(path.parent_path());
  write_file_atomically(path, journal_entry_text(entry), Durability::Flushed);
}

JournalEntry IndexJournal::read(int64_t sequence) const {
  auto path = path_of(sequence);
  std::vector<std::byte> bytes;
  try {
    bytes = read_file(path);
  } catch (const Error& e) {
    damaged(path, e.reason());
  }
  JournalEntry entry =
      parse_journal_entry(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), path);
  if (entry.sequence != sequence) damaged(path, "holds entry " + std::to_string(entry.sequence));
  return entry;
}

std::vector<int64_t> IndexJournal::sequences() const {
  std::vector<int64_t> found;
  std::error_code error;
  for (const auto& chunk : std::filesystem::directory_iterator(folder_, error)) {
    if (!chunk.is_directory() || !number_of(chunk.path().filename().string(), 8)) continue;
    for (const auto& file : std::filesystem::directory_iterator(chunk.path(), error)) {
      if (file.path().extension() != ".json") continue;  // temporaries of an interrupted write
      if (auto number = number_of(file.path().stem().string(), 12)) found.push_back(*number);
    }
  }
  std::sort(found.begin(), found.end());
  return found;
}

bool IndexJournal::empty() const {
  std::error_code error;
  for (const auto& chunk : std::filesystem::directory_iterator(folder_, error))
    for (const auto& file : std::filesystem::directory_iterator(chunk.path(), error))
      if (file.path().extension() == ".json") return false;
  return true;
}

}  // namespace maxillo
