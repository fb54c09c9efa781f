#include "net/stable_study_action.h"

#include <spawn.h>
#include <sys/wait.h>

#include <cstring>
#include <vector>

#include "archive/archive.h"
#include "core/log.h"

extern char** environ;

namespace maxillo::net {
std::optional<int64_t> default_case_of_study(const std::filesystem::path& folder, const std::string& study_uid) {
  try {
    const Archive archive = Archive::open(folder);
    const ResolvedItem item = archive.resolve(study_uid);
    if (item.kind != ItemKind::Study) return std::nullopt;
    const auto found = archive.case_of_patient(archive.study(item.id)->patient);
    return found ? std::optional<int64_t>(found->id) : std::nullopt;
  } catch (const std::exception& error) {
    log::warning("serve: stable study: no case found: ", error.what());
    return std::nullopt;
  }
}

int run_stable_study_action(const std::string& command, const std::filesystem::path& archive,
                            const std::string& study_uid) {
  const auto found = default_case_of_study(archive, study_uid);
  const std::string case_id = found ? std::to_string(*found) : std::string();
  std::vector<std::string> variables = {"MAXILLO_ARCHIVE=" + std::filesystem::absolute(archive).string(),
                                        "MAXILLO_STUDY_UID=" + study_uid, "MAXILLO_CASE=" + case_id};
  std::vector<char*> environment;
  for (char** entry = environ; *entry; ++entry) {
    const bool replaced = std::strncmp(*entry, "MAXILLO_ARCHIVE=", 16) == 0 ||
                          std::strncmp(*entry, "MAXILLO_STUDY_UID=", 18) == 0 ||
                          std::strncmp(*entry, "MAXILLO_CASE=", 13) == 0;
    if (!replaced) environment.push_back(*entry);
  }
  for (auto& variable : variables) environment.push_back(variable.data());
  environment.push_back(nullptr);
  std::string shell = "/bin/sh", flag = "-c", text = command;
  char* argv[] = {shell.data(), flag.data(), text.data(), nullptr};
  log::info("serve: study stable: running the stable-study command for case ", case_id.empty() ? "(none)" : case_id);
  pid_t pid = -1;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv, environment.data()) != 0) {
    log::error("serve: cannot start the stable-study command");
    return -1;
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  if (code == 0)
    log::info("serve: stable-study command done");
  else
    log::warning("serve: stable-study command exited with status ", code);
  return code;
}

}  // namespace maxillo::net
