#pragma once
// Where an archive lives, as given to --archive or MAXILLO_ARCHIVE:
//
//   /data/maxillo                 embedded: a folder holding index.sqlite and objects/
//   postgresql://user@host:5432/maxillo?objects=/shared/maxillo-objects
//                                 a PostgreSQL index and the object folder every node shares
//
// The `objects` parameter is taken out of the URI; the rest goes to libpq unchanged (so every
// libpq parameter, sslmode or connect_timeout among them, works as libpq documents it).
#include <filesystem>
#include <string>
#include <string_view>

namespace maxillo {

struct ArchiveLocation {
  enum class Kind { Folder, Server };
  Kind kind = Kind::Folder;
  // Folder: the archive folder. Server: the shared object folder (the `objects` parameter).
  std::filesystem::path folder;
  std::string server_uri;  // Server: the libpq URI without `objects`
  // What messages name: the folder, or the URI without its password.
  std::string shown;

  bool embedded() const { return kind == Kind::Folder; }
  // The content-addressed store: FOLDER/objects, or the shared folder itself.
  std::filesystem::path objects_folder() const { return embedded() ? folder / "objects" : folder; }
};

// The address as messages and logs may show it: a password in the URI or as password=... removed.
std::string without_password(std::string_view address);

// True when `text` is a PostgreSQL connection URI (postgresql:// or postgres://).
bool names_index_server(std::string_view text);

// A folder path is taken as it is. A URI must name a database and an absolute `objects`
// folder; Error(kBadArchiveAddress) says what is wrong with one that does not.
ArchiveLocation parse_archive_location(std::string_view text);

}  // namespace maxillo
