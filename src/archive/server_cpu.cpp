#include "archive/server_cpu.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "archive/postgres.h"

namespace maxillo {
namespace {

// The fields of /proc/PID/stat after the command name (which may hold spaces): field 3 on.
std::vector<std::string> stat_fields(long pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t name_end = text.rfind(')');
  std::vector<std::string> fields;
  if (name_end == std::string::npos) return fields;
  std::istringstream rest(text.substr(name_end + 2));
  for (std::string field; rest >> field;) fields.push_back(field);
  return fields;
}

// Field N of stat(5) is fields[N - 3].
long field(const std::vector<std::string>& fields, int number) { return std::stol(fields.at(size_t(number - 3))); }

// utime + stime (fields 14, 15), with the reaped children's (16, 17) when asked, in ticks.
long ticks_of(const std::vector<std::string>& fields, bool with_children) {
  long ticks = field(fields, 14) + field(fields, 15);
  if (with_children) ticks += field(fields, 16) + field(fields, 17);
  return ticks;
}

}  // namespace

std::optional<double> server_cpu_seconds(const std::string& database) {
  postgres::Connection connection(database);
  db::Statement backend(connection, "SELECT pg_backend_pid()");
  const long own_backend = long(db::single_integer(backend));
  const auto backend_fields = stat_fields(own_backend);
  if (backend_fields.size() < 15) return std::nullopt;  // not a process of this machine
  const long postmaster = field(backend_fields, 4);
  const auto postmaster_fields = stat_fields(postmaster);
  if (postmaster_fields.size() < 15) return std::nullopt;
  long ticks = ticks_of(postmaster_fields, true);
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator("/proc", error)) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    const auto fields = stat_fields(std::stol(name));
    if (fields.size() >= 15 && field(fields, 4) == postmaster) ticks += ticks_of(fields, false);
  }
  return double(ticks) / double(::sysconf(_SC_CLK_TCK));
}

}  // namespace maxillo
