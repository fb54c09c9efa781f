#pragma once
// The command `maxillo serve --on-stable-study` runs for a study that has become stable.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace maxillo::net {

// The archive id of the study's patient's default case; nullopt when there is none (logged).
std::optional<int64_t> default_case_of_study(const std::filesystem::path& archive, const std::string& study_uid);

// Runs `command` with /bin/sh, its environment extended by MAXILLO_ARCHIVE (the archive folder),
// MAXILLO_STUDY_UID and MAXILLO_CASE (the archive id of the study's patient's default case, empty
// when there is none), and waits for it. Returns its exit status (128 + signal when killed, -1
// when it could not be started). Logs the start and the outcome, naming no patient.
int run_stable_study_action(const std::string& command, const std::filesystem::path& archive,
                            const std::string& study_uid);

}  // namespace maxillo::net
