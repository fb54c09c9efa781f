#pragma once
// The configuration file of `maxillo serve` (JSON), for what a clinic sets once:
//
//   {
//     "ae_title": "MAXILLO",
//     "port": 11112,
//     "allow": ["CBCT_ROOM2", "PACS@10.1.2.3"],
//     "max_associations": 8,
//     "timeout_seconds": 30,
//     "stable_study": {"after_seconds": 60, "command": "..."},
//     "tls": {"certificate": "server.pem", "private_key": "server.key", "trusted": ["clinic-ca.pem"]}
//   }
//
// Every key is optional (defaults as StorageServerOptions); an unknown key or a value of the
// wrong type or range is an error naming the file and the key, so a typo is never ignored.
// Relative paths in "tls" are read from the configuration file's folder.
#include <filesystem>

#include "net/storage_server.h"

namespace maxillo::net {

// Error(kFileNotFound / kBadValue) naming the file (and the key).
StorageServerOptions read_serve_config(const std::filesystem::path& file);

}  // namespace maxillo::net
