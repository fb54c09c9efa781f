// Issue 13 end to end: phantom cases with post-operative CTs in an archive on a real PostgreSQL
// server with a shared object folder; the nightly validation submitted to a real single-node
// Slurm cluster (scripts/cluster/nightly-slurm.sh: an array of workers, then the summary job
// with --dependency=afterany); one worker killed with SIGKILL while it holds a case, or one
// array task cancelled. Then every case is validated exactly once, the summary lists them all,
// and verify is clean.
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
#include "archive/work_queue.h"
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

  // Submits the recipe with `workers` workers into `out`: "ARRAY,SUMMARY" job ids.
  std::string submit_nightly(const std::filesystem::path& out, int workers) {
    const auto submitted =
        shell("bash " + testing::quote(std::filesystem::path(MAXILLO_SOURCE_DIR) / "scripts/cluster/nightly-slurm.sh") +
              " " + testing::quote(out) + " " + std::to_string(workers));
    EXPECT_EQ(submitted.exit_code, 0) << submitted.output;
    std::smatch ids;
    if (!std::regex_search(submitted.output, ids, std::regex("workers: (\\d+)  summary: (\\d+)"))) {
      ADD_FAILURE() << submitted.output;
      return "";
    }
    return std::string(ids[1]) + "," + std::string(ids[2]);
  }

  // Waits up to `limit` for the jobs to end; cancels what is left after that, so that no job
  // outlives the test.
  bool jobs_ended_within(const std::string& jobs, std::chrono::minutes limit) {
    for (auto start = Clock::now(); jobs_running(jobs) && Clock::now() - start < limit;)
      std::this_thread::sleep_for(std::chrono::milliseconds(500));
    if (!jobs_running(jobs)) return true;
    shell("scancel " + jobs);
    return false;
  }

  // Every case validated once and every work item done.
  void expect_each_case_validated_once(Archive& archive, const std::vector<std::string>& patients) {
    for (const auto& patient : patients) {
      int validations = 0;
      for (const auto& artefact : archive.artefacts(archive.resolve_case(patient)))
        validations += artefact.kind == "validation";
      EXPECT_EQ(validations, 1) << patient;
    }
    for (const auto& record : WorkQueue(archive, "nightly").records())
      EXPECT_EQ(record.state, "done") << record.item << ": " << record.reason;
  }

  // The summary job's PDF lists every case.
  void expect_summary_lists(const std::filesystem::path& out, Archive& archive,
                            const std::vector<std::string>& patients) {
    ASSERT_TRUE(std::filesystem::exists(out / "validation-summary.pdf")) << testing::slurp(out / "slurm/summary.out");
    const std::string text = testing::pdf_text(out / "validation-summary.pdf");
    for (const auto& patient : patients)
      EXPECT_NE(text.find("case " + std::to_string(archive.resolve_case(patient))), std::string::npos) << text;
  }

  TemporaryFolder folder_{"cluster-e2e"};
  std::filesystem::path dir_;
  std::string address_;
};

TEST_F(ClusterEndToEnd, SlurmWorkersWithOneKilledValidateEveryCaseExactlyOnceAndTheSummaryListsThemAll) {
  const std::vector<std::string> patients = {"CLUSTER-A", "CLUSTER-B", "CLUSTER-C"};
  for (size_t n = 0; n < patients.size(); ++n) make_case(patients[n], std::to_string(5 + n));
  if (HasFatalFailure()) return;

  const auto out = dir_ / "nightly";
  const std::string jobs = submit_nightly(out, 3);
  ASSERT_FALSE(jobs.empty());

  // Kill the first worker seen holding a case, by the PID in its lease ("host:pid").
  Archive archive = Archive::open(address_);
  pid_t killed = 0;
  std::string killed_item;
  for (auto start = Clock::now(); !killed && Clock::now() - start < std::chrono::minutes(5);) {
    for (const auto& record : WorkQueue(archive, "nightly").records())
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

  ASSERT_TRUE(jobs_ended_within(jobs, std::chrono::minutes(20))) << "the jobs did not finish";

  // Every case validated exactly once: one validation artefact each, every item done once,
  // the killed worker's case claimed twice (by it, then by the worker that took it over).
  expect_each_case_validated_once(archive, patients);
  const auto records = WorkQueue(archive, "nightly").records();
  ASSERT_EQ(records.size(), patients.size());
  for (const auto& record : records) EXPECT_EQ(record.claims, record.item == killed_item ? 2 : 1) << record.item;
  expect_summary_lists(out, archive, patients);  // the summary job ran after the workers
  EXPECT_TRUE(archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never).consistent());
}

// Issue 29, fault 9: with afterok, a cancelled array task kept the summary job pending for ever
// ("DependencyNeverSatisfied") although the other worker finished every case.
TEST_F(ClusterEndToEnd, AnArrayTaskCancelledWhileItHoldsACaseStillEndsInASummaryOfEveryCase) {
  const std::vector<std::string> patients = {"CANCEL-A", "CANCEL-B"};
  for (size_t n = 0; n < patients.size(); ++n) make_case(patients[n], std::to_string(5 + n));
  if (HasFatalFailure()) return;
  const auto out = dir_ / "nightly-cancel";
  const std::string jobs = submit_nightly(out, 2);
  ASSERT_FALSE(jobs.empty());
  const std::string array = jobs.substr(0, jobs.find(','));

  // The task whose worker holds a case (its PID is in the lease, its task's PID file names it).
  Archive archive = Archive::open(address_);
  auto worker_pid_of = [&](const std::string& task_id) {
    std::string pid = testing::slurp(out / "workers" / ("task-" + task_id + ".pid"));
    return pid.substr(0, pid.find('\n'));
  };
  std::string task;
  for (auto start = Clock::now(); task.empty() && Clock::now() - start < std::chrono::minutes(5);) {
    for (const auto& record : WorkQueue(archive, "nightly").records())
      for (const std::string candidate : {"1", "2"})
        if (record.state == "pending" && !worker_pid_of(candidate).empty() &&
            record.holder.ends_with(":" + worker_pid_of(candidate)))
          task = candidate;
    if (task.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_FALSE(task.empty()) << "no worker ever held a case";
  const auto cancelled = shell("scancel " + array + "_" + task);
  ASSERT_EQ(cancelled.exit_code, 0) << cancelled.output;

  ASSERT_TRUE(jobs_ended_within(jobs, std::chrono::minutes(10)))
      << "the summary job never ran: " << shell("squeue -j " + jobs + " -o '%i %T %r'").output;
  expect_each_case_validated_once(archive, patients);
  expect_summary_lists(out, archive, patients);
  EXPECT_NE(testing::slurp(out / "slurm/summary.out").find("2 up to date, 0 failed"), std::string::npos)
      << testing::slurp(out / "slurm/summary.out");
}

}  // namespace
}  // namespace maxillo
