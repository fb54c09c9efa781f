#pragma once
// Files the program carries inside itself: the SQL migrations of db/ and the report
// templates of templates/. Embedding them means an installed binary needs no data folder.
// Setting MAXILLO_RESOURCE_DIR to a folder laid out like the source tree (db/, templates/)
// overrides them, so a clinic can adapt a template without rebuilding.
#include <string>
#include <string_view>
#include <vector>

namespace maxillo {

// Text of a resource by its path in the source tree, e.g. "db/001_initial.sql".
// Throws Error(NotFound) for an unknown path.
std::string load_resource(std::string_view path);

// Paths of the embedded resources that start with prefix, sorted, e.g. all of "db/".
std::vector<std::string> list_resources(std::string_view prefix);

}  // namespace maxillo
