#include "archive/index_journal.h"

#include <algorithm>
#include <charconv>
#include <cstdio>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"
#include "core/utc_time.h"

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

std::filesystem::path IndexJournal::pending_path_of(int64_t sequence) const {
  return path_of(sequence).replace_extension(".pending");
}

bool IndexJournal::has(int64_t sequence) const {
  std::error_code ignored;
  return std::filesystem::exists(path_of(sequence), ignored);
}

bool IndexJournal::has_pending(int64_t sequence) const {
  std::error_code ignored;
  return std::filesystem::exists(pending_path_of(sequence), ignored);
}

void IndexJournal::write_pending(const JournalEntry& entry) const {
  const auto committed = path_of(entry.sequence);
  if (has(entry.sequence))
    throw Error(ErrorCode::kIndexDamaged, committed.string(),
                "the journal already holds committed entry " + std::to_string(entry.sequence) +
                    ", which the index does not have: the index is behind its journal (restored from an older "
                    "copy, or it lost a commit); nothing was written. Rebuild it with `maxillo archive rebuild-index`");
  const auto pending = pending_path_of(entry.sequence);
  if (has_pending(entry.sequence)) set_aside_aborted(entry.sequence);
  create_folders_durably(pending.parent_path());
  write_file_atomically(pending, journal_entry_text(entry), Durability::Flushed);
}

void IndexJournal::set_aside_aborted(int64_t sequence) const {
  const auto aborted = folder_ / "aborted";
  create_folders_durably(aborted);
  const std::string stem = padded(sequence, 12) + "-" + utc_stamp();
  for (int copy = 0;; ++copy) {
    const auto kept = aborted / (stem + (copy ? "-" + std::to_string(copy) : "") + ".pending");
    if (!rename_without_replacing(pending_path_of(sequence), kept)) continue;  // never over another
    sync_folder(aborted);
    log::warning("journal entry ", sequence, " was left by a transaction that stopped before its commit; kept as ",
                 kept.string());
    return;
  }
}

void IndexJournal::mark_committed(int64_t sequence) const {
  try {
    if (rename_without_replacing(pending_path_of(sequence), path_of(sequence))) return;
  } catch (const Error&) {
    if (has(sequence) && !has_pending(sequence)) return;  // marked by another process meanwhile
    throw;
  }
  throw Error(ErrorCode::kIndexDamaged, path_of(sequence).string(),
              "a committed journal entry of this number already exists beside the pending one");
}

bool IndexJournal::settle(int64_t committed_up_to) const {
  if (committed_up_to <= 0 || !has_pending(committed_up_to)) return true;
  try {
    mark_committed(committed_up_to);
    return true;
  } catch (const Error& e) {
    log::debug("journal entry ", committed_up_to, " left pending: ", e.reason());
    return false;
  }
}

void IndexJournal::write_committed(const JournalEntry& entry) const {
  const auto path = path_of(entry.sequence);
  const auto text = journal_entry_text(entry);
  if (has(entry.sequence)) {
    if (journal_entry_text(read(entry.sequence)) == text) return;
    throw Error(ErrorCode::kConflict, path.string(), "holds another journal entry of this number; it is kept");
  }
  create_folders_durably(path.parent_path());
  const auto temporary = temporary_sibling(path);
  write_file_atomically(temporary, text, Durability::Flushed);
  if (!rename_without_replacing(temporary, path)) {
    std::filesystem::remove(temporary);
    throw Error(ErrorCode::kConflict, path.string(), "was written by another process meanwhile; it is kept");
  }
  sync_folder(path.parent_path());
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
