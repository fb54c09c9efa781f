#include "core/resources.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/error.h"

namespace maxillo {

const std::map<std::string_view, std::string_view>& embedded_resources();  // generated

namespace {
std::filesystem::path override_folder() {
  const char* folder = std::getenv("MAXILLO_RESOURCE_DIR");
  return folder ? std::filesystem::path(folder) : std::filesystem::path();
}
}  // namespace

std::string load_resource(std::string_view path) {
  auto folder = override_folder();
  if (!folder.empty() && std::filesystem::exists(folder / path)) {
    std::ifstream in(folder / path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  const auto& resources = embedded_resources();
  auto found = resources.find(path);
  if (found == resources.end()) throw Error(ErrorCode::kNotFound, std::string(path), "no such resource");
  return std::string(found->second);
}

std::vector<std::string> list_resources(std::string_view prefix) {
  std::vector<std::string> paths;
  for (const auto& [path, text] : embedded_resources())
    if (path.starts_with(prefix)) paths.emplace_back(path);
  return paths;  // std::map keeps them sorted
}

}  // namespace maxillo
