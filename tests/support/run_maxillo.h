#pragma once
// Runs the real maxillo binary (MAXILLO_BINARY) as a child process, capturing its output.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern char** environ;

namespace maxillo::testing {

struct RunResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// Starts the program argv[0] (a path) with its arguments; stdout and stderr go to the given
// files. Returns the child's pid.
inline pid_t start_process(std::vector<std::string> all, const std::filesystem::path& out,
                           const std::filesystem::path& err) {
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

// Starts maxillo with args, as start_process.
inline pid_t start_maxillo(const std::vector<std::string>& args, const std::filesystem::path& out,
                           const std::filesystem::path& err) {
  std::vector<std::string> all = {MAXILLO_BINARY};
  all.insert(all.end(), args.begin(), args.end());
  return start_process(std::move(all), out, err);
}

inline int wait_exit_code(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

inline std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

inline RunResult run_maxillo(const std::vector<std::string>& args, const std::filesystem::path& scratch) {
  auto out = scratch / "stdout.txt", err = scratch / "stderr.txt";
  RunResult result;
  result.exit_code = wait_exit_code(start_maxillo(args, out, err));
  result.out = slurp(out);
  result.err = slurp(err);
  return result;
}

}  // namespace maxillo::testing
