// Issue 13 end to end: phantom cases with post-operative CTs in an archive on a real PostgreSQL
// server with a shared object folder; the nightly validation submitted to a real single-node
// Slurm cluster (scripts/cluster/nightly-slurm.sh: an array of workers, then the summary job
// with --dependency=afterok); one worker killed with SIGKILL while it holds a case. Then every
// case is validated exactly once, the summary lists them all, and verify is clean.
// The servers are CTest fixtures (scripts/test-postgres, scripts/test-slurm); without them
// the test skips.
#include <gtest/gtest.h>

#include <csignal>
#include <chrono>
#include <cstdlib>
#include <map>
#include <regex>
#include <thread>

#include "archive/archive.h"
#include "core/temporary_folder.h"
#include "support/pdf_tools.h"
#include "support/run_command.h"
#include "support/run_maxillo.h"
#include "support/test_archive.h"

namespace maxillo {
namespace {

using testing::run_command;
using testing::run_maxillo;
using Clock = std::chrono::steady_clock;

std::string slurm_conf() {
  const char* file = std::getenv("MAXILLO_TEST_SLURM");
  return file && std::filesystem::exists(file) ? file : "";
}

class ClusterEndToEnd : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!testing::on_server()) GTEST_SKIP() << "no test PostgreSQL server (MAXILLO_TEST_POSTGRES)";
    if (slurm_conf().empty()) GTEST_SKIP() << "no test Slurm cluster (MAXILLO_TEST_SLURM)";
    dir_ = folder_.path();
    std::filesystem::create_directories(dir_ / "shared-objects");
    address_ = testing::new_test_database() + "?objects=" + (dir_ / "shared-objects").string();
  }

  void run_ok(std::vector<std::string> args) {
    args.insert(args.begin(), "--archive=" + address_);
    const auto run = run_maxillo(args, dir_);
    ASSERT_EQ(run.exit_code, 0) << args[1] << ": " << run.err;
  }

  // A phantom patient, planned, with a synthetic post-operative CT: eligible for validation.
  void make_case(const std::string& patient, const std::string& advance) {
    const auto sample = dir_ / patient;
    ASSERT_EQ(
        run_maxillo({"sample", "--out", sample.string(), "--spacing", "2", "--patient-id", patient}, dir_).exit_code,
        0);
    run_ok({"import", (sample / "ct").string()});
    run_ok({"ceph", "add", patient, "--time-point", "pre", "--date", "2026-01-02",
            (sample / "landmarks.mrk.json").string()});
    run_ok({"plan", "create", patient, "--advance", advance});
    run_ok({"sample-postop", patient, "--out", (dir_ / (patient + "-postop")).string(), "--import", "--error-mm", "1"});
  }

  // Runs a shell command line with the cluster's and the archive's environment.
  testing::CommandResult shell(const std::string& command) {
    return run_command("SLURM_CONF=" + testing::quote(slurm_conf()) + " MAXILLO_ARCHIVE=" + testing::quote(address_) +
                       " MAXILLO_BIN=" + testing::quote(MAXILLO_BINARY) + " MAXILLO_LEASE=8 " + command + " 2>&1");
  }

  bool jobs_running(const std::string& ids) { return !shell("squeue -h -j " + ids).output.empty(); }

  TemporaryFolder folder_{"cluster-e2e"};
  std::filesystem::path dir_;
  std::string address_;
};

TEST_F(ClusterEndToEnd, SlurmWorkersWithOneKilledValidateEveryCaseExactlyOnceAndTheSummaryListsThemAll) {
  const std::vector<std::string> patients = {"CLUSTER-A", "CLUSTER-B", "CLUSTER-C"};
  for (size_t n = 0; n < patients.size(); ++n) make_case(patients[n], std::to_string(5 + n));
  if (HasFatalFailure()) return;

  const auto out = dir_ / "nightly";
  const auto submitted =
      shell("bash " + testing::quote(std::filesystem::path(MAXILLO_SOURCE_DIR) / "scripts/cluster/nightly-slurm.sh") +
            " " + testing::quote(out) + " 3");
  ASSERT_EQ(submitted.exit_code, 0) << submitted.output;
  std::smatch ids;
  ASSERT_TRUE(std::regex_search(submitted.output, ids, std::regex("workers: (\\d+)  summary: (\\d+)")))
      << submitted.output;
  const std::string jobs = std::string(ids[1]) + "," + std::string(ids[2]);

  // Kill the first worker seen holding a case, by the PID in its lease ("host:pid").
  Archive archive = Archive::open(address_);
  pid_t killed = 0;
  std::string killed_item;
  for (auto start = Clock::now(); !killed && Clock::now() - start < std::chrono::minutes(5);) {
    for (const auto& record : archive.work_records("nightly"))
      if (record.state == "pending" && !record.holder.empty()) {
        killed = pid_t(std::stol(record.holder.substr(record.holder.rfind(':') + 1)));
        killed_item = record.item;
        break;
      }
    if (!killed) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_GT(killed, 0) << "no worker ever held a case";
  std::this_thread::sleep_for(std::chrono::seconds(1));  // mid-case
  ASSERT_EQ(::kill(killed, SIGKILL), 0);

  for (auto start = Clock::now(); jobs_running(jobs) && Clock::now() - start < std::chrono::minutes(20);)
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
  ASSERT_FALSE(jobs_running(jobs)) << "the jobs did not finish";

  // Every case validated exactly once: one validation artefact each, every item done once,
  // the killed worker's case claimed twice (by it, then by the worker that took it over).
  for (const auto& patient : patients) {
    const int64_t case_id = archive.resolve_case(patient);
    int validations = 0;
    for (const auto& artefact : archive.artefacts(case_id)) validations += artefact.kind == "validation";
    EXPECT_EQ(validations, 1) << patient;
  }
  const auto records = archive.work_records("nightly");
  ASSERT_EQ(records.size(), patients.size());
  for (const auto& record : records) {
    EXPECT_EQ(record.state, "done") << record.item << ": " << record.reason;
    EXPECT_EQ(record.claims, record.item == killed_item ? 2 : 1) << record.item;
  }
  // The summary job ran after the workers and lists every case.
  ASSERT_TRUE(std::filesystem::exists(out / "validation-summary.pdf")) << testing::slurp(out / "slurm/summary.out");
  const std::string text = testing::pdf_text(out / "validation-summary.pdf");
  for (const auto& patient : patients)
    EXPECT_NE(text.find("case " + std::to_string(archive.resolve_case(patient))), std::string::npos) << text;
  EXPECT_TRUE(archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never).consistent());
}

}  // namespace
}  // namespace maxillo
