#pragma once
// Whole-file reads and crash-safe writes. A file written here is either absent or complete:
// it is written to a temporary name in the same folder, flushed to disk, then renamed.
#include <cstddef>
#include <filesystem>
#include <span>
#include <string_view>
#include <vector>

namespace maxillo {

// Reads a whole file; throws Error (FileNotFound, PermissionDenied, ...) naming the path.
std::vector<std::byte> read_file(const std::filesystem::path& path);

enum class Durability { Flushed, Unflushed };

// Writes bytes to path through a temporary file and rename(2). With Durability::Flushed the
// data and the folder entry are fsync'ed before returning. Throws Error(WriteFailed).
void write_file_atomically(const std::filesystem::path& path, std::span<const std::byte> bytes,
                           Durability durability = Durability::Flushed);
void write_file_atomically(const std::filesystem::path& path, std::string_view text,
                           Durability durability = Durability::Flushed);

// Creates `folder` and any missing parents, each made durable (its parent folder fsync'ed), so
// a file later written durably inside it cannot vanish with its folder in a crash.
// Throws Error(WriteFailed).
void create_folders_durably(const std::filesystem::path& folder);

// fsync(2) of a folder: its entries (created, renamed, removed files) reach stable storage.
void sync_folder(const std::filesystem::path& folder);

// rename(2) that never replaces: false (nothing changed) when `to` exists. renameat2's
// RENAME_NOREPLACE where the file system has it, else link(2) then unlink(2), which refuse an
// existing name the same way. Throws Error(WriteFailed) on any other failure.
bool rename_without_replacing(const std::filesystem::path& from, const std::filesystem::path& to);

// A unique name beside `path` for a temporary file (same folder, so rename is atomic).
std::filesystem::path temporary_sibling(const std::filesystem::path& path);

}  // namespace maxillo
