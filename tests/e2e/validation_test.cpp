// Issue 7 end to end on synthetic post-operative cases with known answers: two phantom patients, each planned, given
// a synthetic post-operative CT (`maxillo sample-postop`: planned bone moves, the predicted face plus a known error
// bump, the head repositioned in the scanner), then `maxillo validate` and `maxillo nightly`. One CTest test: the
// cases are built once.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <csignal>
#include <fstream>
#include <thread>
#include <regex>
#include <sstream>

#include "core/json.h"
#include "core/temporary_folder.h"
#include "support/pdf_tools.h"
#include "support/run_maxillo.h"

namespace maxillo {
namespace {

using testing::run_maxillo;

Json read_json(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return Json::parse(text.str());
}

Eigen::Isometry3d matrix_of(const Json& rows) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) t(r, c) = rows[size_t(r)][size_t(c)].get<double>();
  return t;
}

// Largest distance between where two transforms put the corners of a 200 mm cube around `centre`.
double largest_disagreement(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, const Eigen::Vector3d& centre) {
  double largest = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d p =
        centre + 100.0 * Eigen::Vector3d(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
    largest = std::max(largest, (a * p - b * p).norm());
  }
  return largest;
}

const Json& region(const Json& regions, const std::string& name) {
  for (const auto& r : regions)
    if (r["region"] == name) return r;
  throw std::runtime_error("no region " + name);
}

std::vector<std::string> case_lines(const std::string& out) {
  std::vector<std::string> lines;
  const std::regex line("case (\\d+): ");
  for (std::sregex_iterator it(out.begin(), out.end(), line), end; it != end; ++it) lines.push_back((*it)[1]);
  return lines;
}

class ValidationEndToEnd : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = folder_.path();
    archive_ = "--archive=" + (dir_ / "archive").string();
    make_case("VALIDATION-A", "6", {"--error-mm", "2", "--error-centre", "Li"});
    make_case("VALIDATION-B", "8", {"--error-mm", "1.5", "--error-centre", "Ls", "--reposition-deg", "-3"});
  }

  void run_ok(std::vector<std::string> args) {
    args.insert(args.begin(), archive_);
    const auto run = run_maxillo(args, dir_);
    ASSERT_EQ(run.exit_code, 0) << args[1] << ": " << run.err;
  }

  void make_case(const std::string& patient, const std::string& advance, std::vector<std::string> postop_options) {
    const auto sample = dir_ / patient;
    ASSERT_EQ(
        run_maxillo({"sample", "--out", sample.string(), "--spacing", "1.5", "--patient-id", patient}, dir_).exit_code,
        0);
    run_ok({"import", (sample / "ct").string()});
    run_ok({"ceph", "add", patient, "--time-point", "pre", "--date", "2026-01-02",
            (sample / "landmarks.mrk.json").string()});
    run_ok({"plan", "create", patient, "--advance", advance});
    std::vector<std::string> args{"sample-postop", patient, "--out", (dir_ / (patient + "-postop")).string(),
                                  "--import"};
    args.insert(args.end(), postop_options.begin(), postop_options.end());
    run_ok(args);
  }

  TemporaryFolder folder_{"validation-e2e"};
  std::filesystem::path dir_;
  std::string archive_;
};

TEST_F(ValidationEndToEnd, ValidateFindsTheKnownAnswerAndNightlySummarisesEveryCaseOnce) {
  // 1. maxillo validate on case A recovers what the synthetic post-operative CT was made from.
  const auto run =
      run_maxillo({archive_, "--json", "validate", "VALIDATION-A", "--out", (dir_ / "validate-A").string()}, dir_);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json result = Json::parse(run.out);
  const Json truth = read_json(dir_ / "VALIDATION-A-postop" / "truth.json");

  // The head's repositioning in the scanner is undone (registration on the cranium).
  const Eigen::Vector3d head_centre = matrix_of(truth["postop_to_preop"]).translation();
  EXPECT_LT(largest_disagreement(matrix_of(result["registration"]["moving_to_fixed"]),
                                 matrix_of(truth["postop_to_preop"]), head_centre),
            0.3);
  // The maxilla moved as planned, and ICP finds it so.
  ASSERT_EQ(result["segments"].size(), 1u);
  EXPECT_EQ(result["segments"][0]["segment"], "maxilla");
  EXPECT_LT(result["segments"][0]["mean_difference_mm"].get<double>(), 0.3);
  // The errors found are the known bump: the prediction lies behind the real face by it.
  const auto& found = region(result["regions"], "face")["closest"];
  const auto& known = region(truth["regions"], "face")["known_error"];
  EXPECT_EQ(found["count"], known["count"]);
  EXPECT_NEAR(found["mean_signed"].get<double>(), known["mean_signed"].get<double>(), 0.15);
  EXPECT_NEAR(found["p5"].get<double>(), known["p5"].get<double>(), 0.3);
  EXPECT_NEAR(found["p50"].get<double>(), known["p50"].get<double>(), 0.15);
  EXPECT_NEAR(found["within_tolerance_percent"].get<double>(), known["within_tolerance_percent"].get<double>(), 3.0);
  const auto& known_lip = region(truth["regions"], "lower lip")["known_error"];
  EXPECT_LT(known_lip["p5"].get<double>(),
            -1.0);  // the bump is there to be found, on the lower lip
  const auto& lip = region(result["regions"], "lower lip")["closest"];
  EXPECT_NEAR(lip["mean_signed"].get<double>(), known_lip["mean_signed"].get<double>(), 0.2);
  EXPECT_NEAR(lip["p5"].get<double>(), known_lip["p5"].get<double>(), 0.3);
  // The corresponding-point distance sees the same error, sign included.
  EXPECT_NEAR(region(result["regions"], "lower lip")["corresponding"]["mean_signed"].get<double>(),
              known_lip["mean_signed"].get<double>(), 0.25);
  for (const char* file : {"error-map-frontal.png", "error-map-lateral.png", "profile.png", "predicted-skin.vtp",
                           "actual-skin.vtp", "validation.json"})
    EXPECT_TRUE(std::filesystem::exists(dir_ / "validate-A" / file)) << file;
  // Stored with its inputs' hash: asking again recomputes nothing.
  const auto again = run_maxillo({archive_, "validate", "VALIDATION-A"}, dir_);
  EXPECT_NE(again.out.find("up to date"), std::string::npos) << again.out;

  // 2. maxillo nightly, killed while it validates case B (A is up to date), keeps nothing half-made
  //    and resumes: the next run validates B only and writes the summary.
  const auto night = (dir_ / "night").string();
  const auto killed_err = dir_ / "killed-stderr.txt";
  const pid_t pid =
      testing::start_maxillo({archive_, "nightly", "--out", night}, dir_ / "killed-stdout.txt", killed_err);
  for (int waited = 0; waited < 600 && testing::slurp(killed_err).find("registering") == std::string::npos; ++waited)
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
  kill(pid, SIGKILL);
  testing::wait_exit_code(pid);
  EXPECT_EQ(run_maxillo({archive_, "verify"}, dir_).exit_code, 0);
  const auto first = run_maxillo({archive_, "nightly", "--out", night}, dir_);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_NE(first.out.find("1 validated, 1 up to date, 0 failed"), std::string::npos) << first.out;
  const auto pdf = dir_ / "night" / "validation-summary.pdf";
  ASSERT_TRUE(std::filesystem::exists(pdf));
  // Issue 14: the log names the report a reader opens, not a temporary file.
  EXPECT_NE(first.err.find("validation-summary.pdf"), std::string::npos) << first.err;
  EXPECT_EQ(first.err.find(".partial"), std::string::npos) << first.err;
  EXPECT_EQ(first.err.find(".tmp-"), std::string::npos) << first.err;
  const std::string text = testing::pdf_text(pdf);
  for (const char* needle : {"Validation summary", "case 1", "case 2", "lower lip", "Error map", "Mid-sagittal"})
    EXPECT_NE(text.find(needle), std::string::npos) << needle;
  EXPECT_GE(testing::pdf_page_count(pdf),
            3);  // the cohort page and a page per case
  // 3. A second run finds everything up to date and leaves the summary as it is.
  const auto modified = std::filesystem::last_write_time(pdf);
  const auto second = run_maxillo({archive_, "nightly", "--out", night}, dir_);
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_NE(second.out.find("0 validated, 2 up to date, 0 failed"), std::string::npos) << second.out;
  EXPECT_NE(second.out.find("summary up to date"), std::string::npos) << second.out;
  EXPECT_EQ(std::filesystem::last_write_time(pdf), modified);
  // 4. Shards split the cases: every case in exactly one slice.
  const auto one = run_maxillo({archive_, "nightly", "--out", night, "--shard", "1/2", "--summary-only"}, dir_);
  const auto two = run_maxillo({archive_, "nightly", "--out", night, "--shard", "2/2", "--summary-only"}, dir_);
  auto cases = case_lines(one.out);
  for (const auto& c : case_lines(two.out)) cases.push_back(c);
  std::sort(cases.begin(), cases.end());
  EXPECT_EQ(cases, (std::vector<std::string>{"1", "2"})) << one.out << two.out;
}

}  // namespace
}  // namespace maxillo
