// Black-box tests of the archive commands: import / list / show / verify / export, their exit
// codes, stderr lines and --json keys; crash safety under kill -9; concurrent importers. Those
// that are not about the embedded index's files also run with a PostgreSQL address
// (tests/cli/CMakeLists.txt), and ServerAddressCli checks what only a server address can get wrong.
#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <thread>

#include "archive_fixture.h"
#include "core/error.h"
#include "core/json.h"
#include "net/net_fixture.h"
#include "support/bad_dicom_files.h"
#include "support/run_command.h"
#include "support/run_maxillo.h"

namespace maxillo {
namespace {

using testing::TemporaryFolder;

size_t count_lines(const std::string& text) { return size_t(std::count(text.begin(), text.end(), '\n')); }

int64_t archived_instances(const std::filesystem::path& archive, const std::filesystem::path& scratch) {
  auto result = testing::run_maxillo({"--archive", archive.string(), "--json", "list", "series"}, scratch);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  int64_t total = 0;
  for (const auto& series : Json::parse(result.out)) total += series.at("instances").get<int64_t>();
  return total;
}

TEST(ArchiveCli, ImportReportsEachBadFileOnOneLineAndImportsTheRest) {
  TemporaryFolder folder;
  testing::write_series(folder / "in" / "good", 3);
  std::ofstream(folder / "in" / "readme.txt") << std::string(300, 'x');
  std::filesystem::create_symlink(folder / "nowhere", folder / "in" / "dangling.dcm");
  auto archive = testing::archive_at(folder / "archive").string();

  auto result = testing::run_maxillo({"--archive", archive, "import", (folder / "in").string()}, folder.path());
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(count_lines(result.err), 2u) << result.err;
  EXPECT_NE(result.err.find((folder / "in" / "readme.txt").string() + ": "), std::string::npos) << result.err;
  EXPECT_NE(result.err.find((folder / "in" / "dangling.dcm").string() + ": unreadable"), std::string::npos);
  EXPECT_NE(result.out.find("3 imported"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("2 failed"), std::string::npos) << result.out;

  auto again = testing::run_maxillo({"--archive", archive, "import", (folder / "in" / "good").string()}, folder.path());
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.out.find("3 already archived, nothing changed"), std::string::npos) << again.out;

  auto json = testing::run_maxillo({"--archive", archive, "--json", "import", (folder / "in").string()}, folder.path());
  EXPECT_EQ(json.exit_code, 1);
  Json report = Json::parse(json.out);
  EXPECT_EQ(report.at("already_archived"), 3);
  EXPECT_EQ(report.at("failed"), 2);
  EXPECT_EQ(report.at("imported"), 0);
  ASSERT_EQ(report.at("problems").size(), 2u);
  EXPECT_EQ(report.at("problems")[0].at("outcome"), "failed");
  EXPECT_TRUE(report.at("problems")[0].contains("reason"));
}

// Permission denied, as a clinic's unprivileged service account meets it. Tests run as root in
// CI, where every file is readable: the import then runs as `nobody` through setpriv.
TEST(ArchiveCli, UnreadableFileIsNamedAsPermissionDeniedAndTheRestImports) {
  TemporaryFolder folder;
  testing::write_series(folder / "in", 3);
  auto locked = folder / "in" / "locked.dcm";
  std::filesystem::copy_file(folder / "in" / "slice0000.dcm", locked);
  std::filesystem::permissions(locked, std::filesystem::perms::none);
  std::filesystem::create_directories(folder / "archive");
  std::filesystem::permissions(folder / "archive", std::filesystem::perms::all);
  std::filesystem::permissions(folder.path(), std::filesystem::perms::all);

  std::string as_user;
  if (::geteuid() == 0) {
    if (!testing::tool_available("setpriv")) GTEST_SKIP() << "running as root without setpriv";
    as_user = "setpriv --reuid=65534 --regid=65534 --clear-groups ";
  }
  auto result = testing::run_command(as_user + MAXILLO_BINARY + " --archive " + testing::quote(folder / "archive") +
                                     " import " + testing::quote(folder / "in") + " 2>&1");
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find(locked.string() + ": unreadable: Permission denied"), std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("3 imported"), std::string::npos) << result.output;
}

// Issue 29, fault 8: on an archive its user may only read, `list` failed ("attempt to write a
// readonly database", exit 45) and `export --deidentify` wanted to create deidentify.key.
// Reading works read-only, and leaves the archive exactly as it was.
TEST(ArchiveCli, AReadOnlyArchiveCanBeListedAndExportedAndIsLeftUnchanged) {
  if (::geteuid() == 0 && !testing::tool_available("setpriv")) GTEST_SKIP() << "running as root without setpriv";
  TemporaryFolder folder;
  testing::write_series(folder / "in", 3);
  const auto archive = folder / "archive";
  ASSERT_EQ(testing::run_maxillo({"--archive", archive.string(), "import", (folder / "in").string()}, folder.path())
                .exit_code,
            0);
  ASSERT_EQ(testing::run_command("chmod -R a=rX " + testing::quote(archive)).exit_code, 0);
  std::filesystem::permissions(folder.path(), std::filesystem::perms::all);
  std::filesystem::create_directories(folder / "exports");
  std::filesystem::permissions(folder / "exports", std::filesystem::perms::all);
  auto files_of = [&] {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(archive)) names.push_back(entry.path());
    std::sort(names.begin(), names.end());
    return names;
  };
  const auto before = files_of();
  const std::string as_user = ::geteuid() == 0 ? "setpriv --reuid=65534 --regid=65534 --clear-groups " : "";
  auto maxillo = [&](const std::string& arguments) {
    return testing::run_command(as_user + MAXILLO_BINARY + " --archive " + testing::quote(archive) + " " + arguments +
                                " 2>&1");
  };
  const auto listed = maxillo("list series");
  EXPECT_EQ(listed.exit_code, 0) << listed.output;
  EXPECT_NE(listed.output.find("axial"), std::string::npos) << listed.output;
  const auto exported = maxillo("export 1 --deidentify --out " + testing::quote(folder / "exports" / "anonymous"));
  EXPECT_EQ(exported.exit_code, 0) << exported.output;
  EXPECT_NE(exported.output.find("3 de-identified files"), std::string::npos) << exported.output;
  EXPECT_NE(exported.output.find("read-only"), std::string::npos) << exported.output;
  const auto imported = maxillo("import " + testing::quote(folder / "in"));
  EXPECT_NE(imported.exit_code, 0) << imported.output;  // writing cannot work, and says why
  EXPECT_EQ(files_of(), before);
  testing::run_command("chmod -R u+w " + testing::quote(archive));
}

TEST(ArchiveCli, ListShowVerifyAndExportByteIdentical) {
  TemporaryFolder folder;
  auto written = testing::write_series(folder / "in", 4);
  auto archive = testing::archive_at(folder / "archive").string();
  ASSERT_EQ(testing::run_maxillo({"--archive", archive, "import", (folder / "in").string()}, folder.path()).exit_code,
            0);

  auto patients = testing::run_maxillo({"--archive", archive, "--json", "list", "patients"}, folder.path());
  ASSERT_EQ(patients.exit_code, 0) << patients.err;
  EXPECT_EQ(Json::parse(patients.out).at(0).at("patient_id"), "P1");
  auto cases = testing::run_maxillo({"--archive", archive, "--json", "list", "cases"}, folder.path());
  EXPECT_EQ(Json::parse(cases.out).at(0).at("label"), "default");
  EXPECT_EQ(testing::run_maxillo({"--archive", archive, "list", "nonsense"}, folder.path()).exit_code, 2);

  auto show =
      testing::run_maxillo({"--archive", archive, "--json", "show", written.series_instance_uid}, folder.path());
  ASSERT_EQ(show.exit_code, 0) << show.err;
  Json shown = Json::parse(show.out);
  EXPECT_EQ(shown.at("kind"), "series");
  EXPECT_EQ(shown.at("item").at("instances"), 4);
  auto missing = testing::run_maxillo({"--archive", archive, "show", "no-such-id"}, folder.path());
  EXPECT_EQ(missing.exit_code, exit_code_for(ErrorCode::kNotFound));
  EXPECT_NE(missing.err.find("no-such-id"), std::string::npos);

  auto verify = testing::run_maxillo({"--archive", archive, "--json", "verify"}, folder.path());
  EXPECT_EQ(verify.exit_code, 0) << verify.out;
  // The 4 instances and the orientation record the import made of the case's CT (issue 28).
  EXPECT_EQ(Json::parse(verify.out).at("objects_checked"), 5);

  auto out = folder / "exported";
  auto exported = testing::run_maxillo(
      {"--archive", archive, "export", written.series_instance_uid, "--out", out.string()}, folder.path());
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  std::vector<std::filesystem::path> files(std::filesystem::directory_iterator(out), {});
  std::sort(files.begin(), files.end());
  ASSERT_EQ(files.size(), 4u);
  for (size_t k = 0; k < 4; ++k) EXPECT_EQ(testing::slurp(files[k]), testing::slurp(written.files[k]));
}

TEST(ArchiveCli, KilledImportLeavesAConsistentArchiveAndReimportCompletesIt) {
  TemporaryFolder folder;
  constexpr int kSeries = 4, kSlices = 150;
  for (int s = 0; s < kSeries; ++s)
    write_ct_series(testing::small_volume(kSlices, 256), testing::patient_metadata("P" + std::to_string(s)),
                    folder / "in" / std::to_string(s));
  const int64_t total = kSeries * kSlices;
  bool interrupted_mid_import = false;
  for (int delay_ms : {60, 150, 250}) {
    auto archive = (folder / ("archive" + std::to_string(delay_ms))).string();
    pid_t child = testing::start_maxillo({"--archive", archive, "import", "--batch", "40", (folder / "in").string()},
                                         folder / "child.out", folder / "child.err");
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
    ::kill(child, SIGKILL);
    testing::wait_exit_code(child);

    if (!std::filesystem::exists(std::filesystem::path(archive) / "index.sqlite")) {
      // Killed before the archive was made (a loaded machine): nothing may have been stored.
      EXPECT_FALSE(std::filesystem::exists(std::filesystem::path(archive) / "objects" / "journal"));
      interrupted_mid_import = true;
    } else {
      auto verify = testing::run_maxillo({"--archive", archive, "--json", "verify"}, folder.path());
      Json report = Json::parse(verify.out);
      EXPECT_TRUE(report.at("data_intact").get<bool>()) << verify.out;  // at most orphans / temporaries
      if (archived_instances(archive, folder.path()) < total) interrupted_mid_import = true;
      // A killed batch leaves up to 40 orphans of a few hundred objects: more than repair
      // quarantines unasked, so it explains that the import should be run again.
      auto repair = testing::run_maxillo({"--archive", archive, "verify", "--repair"}, folder.path());
      if (repair.exit_code != 0) {
        EXPECT_NE(repair.err.find("run it again"), std::string::npos) << repair.err;
      }
    }

    auto again = testing::run_maxillo({"--archive", archive, "import", (folder / "in").string()}, folder.path());
    EXPECT_EQ(again.exit_code, 0) << again.err;
    EXPECT_EQ(archived_instances(archive, folder.path()), total);
    auto repaired = testing::run_maxillo({"--archive", archive, "verify", "--repair"}, folder.path());
    EXPECT_EQ(repaired.exit_code, 0) << repaired.out << repaired.err;  // only temporaries were left
    EXPECT_EQ(testing::run_maxillo({"--archive", archive, "verify"}, folder.path()).exit_code, 0);
  }
  EXPECT_TRUE(interrupted_mid_import) << "no kill landed during the import; the machine was too fast for the delays";
}

size_t object_files(const std::filesystem::path& archive) {
  size_t count = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(archive / "objects"))
    count += entry.is_regular_file() && entry.path().string().find("/journal/") == std::string::npos;
  return count;
}

// Issue 14, defect 1: a lost index made `list` show an empty archive, `import` re-add rows
// and `verify --repair` delete every object as an orphan.
TEST(ArchiveCli, ALostIndexIsRefusedByEveryCommandAndRebuiltFromTheStore) {
  TemporaryFolder folder;
  testing::write_series(folder / "in", 12, "P1");
  auto archive = folder / "archive";
  auto a = archive.string();
  ASSERT_EQ(testing::run_maxillo({"--archive", a, "import", (folder / "in").string()}, folder.path()).exit_code, 0);
  auto listed = testing::run_maxillo({"--archive", a, "--json", "list", "series"}, folder.path());
  const size_t objects = object_files(archive);
  ASSERT_EQ(objects, 13u);  // 12 instances and the orientation record the import made of the case's CT

  for (bool truncate : {false, true}) {
    std::filesystem::remove(archive / "index.sqlite");
    if (truncate) std::ofstream(archive / "index.sqlite").close();
    for (std::vector<std::string> command : {std::vector<std::string>{"list"},
                                             {"import", (folder / "in").string()},
                                             {"verify", "--repair"},
                                             {"export", "1", "--out", (folder / "x").string()}}) {
      command.insert(command.begin(), {"--archive", a});
      auto result = testing::run_maxillo(command, folder.path());
      EXPECT_EQ(result.exit_code, exit_code_for(ErrorCode::kIndexDamaged)) << command[2] << ": " << result.err;
      EXPECT_NE(result.err.find("archive rebuild-index"), std::string::npos) << result.err;
    }
    EXPECT_EQ(object_files(archive), objects);
  }
  EXPECT_FALSE(std::filesystem::exists(folder / "x"));

  auto rebuilt = testing::run_maxillo({"--archive", a, "archive", "rebuild-index"}, folder.path());
  EXPECT_EQ(rebuilt.exit_code, 0) << rebuilt.out << rebuilt.err;
  EXPECT_EQ(testing::run_maxillo({"--archive", a, "--json", "list", "series"}, folder.path()).out, listed.out);
  EXPECT_EQ(testing::run_maxillo({"--archive", a, "verify"}, folder.path()).exit_code, 0);
}

TEST(ArchiveCli, ReadingCommandsDoNotCreateAMissingArchive) {
  TemporaryFolder folder;
  auto missing = folder / "NONEXISTENT";
  auto result = testing::run_maxillo({"--archive", missing.string(), "list"}, folder.path());
  EXPECT_EQ(result.exit_code, exit_code_for(ErrorCode::kNotFound)) << result.err;
  EXPECT_NE(result.err.find("no archive"), std::string::npos) << result.err;
  EXPECT_FALSE(std::filesystem::exists(missing));
}

// Issue 14, defect 7: text that is not UTF-8 must never break --json output.
TEST(ArchiveCli, JsonOutputSurvivesLatin1NamesAndFileNames) {
  TemporaryFolder folder;
  auto written = testing::write_series(folder / "in", 2, "P1");
  DcmFileFormat file;
  file.loadFile(written.files[0].c_str());
  file.getDataset()->findAndDeleteElement(DCM_SpecificCharacterSet);
  file.getDataset()->putAndInsertString(DCM_PatientID, "P-LATIN");
  file.getDataset()->putAndInsertString(DCM_PatientName, "M\xFCller^J\xF6rg");
  file.getDataset()->putAndInsertString(DCM_SOPInstanceUID, "1.2.3.4.5.6");
  std::filesystem::create_directories(folder / "latin");
  ASSERT_TRUE(file.saveFile((folder / "latin" /
                             "sch\xE4"
                             "del.dcm")
                                .c_str(),
                            EXS_LittleEndianExplicit)
                  .good());
  std::ofstream(folder / "latin" / "notiz-\xFC.txt") << std::string(200, 'x');  // a failure naming a Latin-1 path
  auto a = testing::archive_at(folder / "archive").string();

  auto imported =
      testing::run_maxillo({"--archive", a, "--json", "import", (folder / "latin").string()}, folder.path());
  EXPECT_EQ(imported.exit_code, 1) << imported.err;
  Json report = Json::parse(imported.out);
  EXPECT_EQ(report.at("imported"), 1);
  for (const auto& command : {"patients", "studies", "series"}) {
    auto listed = testing::run_maxillo({"--archive", a, "--json", "list", command}, folder.path());
    EXPECT_EQ(listed.exit_code, 0) << listed.err;
    EXPECT_TRUE(Json::accept(listed.out)) << listed.out;
  }
  auto patients = Json::parse(testing::run_maxillo({"--archive", a, "--json", "list", "patients"}, folder.path()).out);
  EXPECT_EQ(patients[0].at("name"), "Müller^Jörg");
  auto shown = testing::run_maxillo({"--archive", a, "--json", "show", "P-LATIN"}, folder.path());
  EXPECT_EQ(shown.exit_code, 0) << shown.err;
  EXPECT_TRUE(Json::accept(shown.out)) << shown.out;
  // The Latin-1 file name is kept as the bytes it is (on PostgreSQL too, whose text must be
  // UTF-8), and the index still matches its journal.
  auto verify = testing::run_maxillo({"--archive", a, "verify"}, folder.path());
  EXPECT_EQ(verify.exit_code, 0) << verify.out << verify.err;
}

// A malformed address, an unreachable server, a missing shared folder: each refused with its own
// exit code and a reason, whatever the command, and never with the password in the message.
TEST(ServerAddressCli, BadAddressesAreRefusedWithTheirExitCodeAndAReason) {
  TemporaryFolder folder;
  const int closed_port = testing::free_loopback_port();  // nobody listens there
  struct Case {
    std::string address;
    ErrorCode code;
    std::string said;
  };
  const std::vector<Case> cases = {
      {"postgresql://maxillo:secret@127.0.0.1:" + std::to_string(closed_port) + "/db?objects=" + folder.path().string(),
       ErrorCode::kArchiveUnreachable, "127.0.0.1"},
      {"postgresql://maxillo:secret@127.0.0.1/db", ErrorCode::kBadArchiveAddress, "objects"},
      {"postgresql://maxillo:secret@127.0.0.1/db?objects=" + (folder / "not-there").string(),
       ErrorCode::kBadArchiveAddress, "not-there"},
  };
  for (const auto& c : cases)
    for (const std::vector<std::string>& command :
         {std::vector<std::string>{"list", "patients"}, {"verify"}, {"import", folder.path().string()}}) {
      std::vector<std::string> args{"--archive", c.address};
      args.insert(args.end(), command.begin(), command.end());
      const auto run = testing::run_maxillo(args, folder.path());
      EXPECT_EQ(run.exit_code, exit_code_for(c.code)) << c.address << " " << command[0] << ": " << run.err;
      EXPECT_NE(run.err.find(c.said), std::string::npos) << run.err;
      EXPECT_EQ(run.err.find("secret"), std::string::npos) << "the password was shown: " << run.err;
    }
}

TEST(ArchiveCli, TwoConcurrentImportersOfOverlappingSets) {
  TemporaryFolder folder;
  for (const char* name : {"a", "b", "c"}) testing::write_series(folder / "in" / name, 120, std::string("P") + name);
  auto archive = testing::archive_at(folder / "archive").string();
  pid_t one = testing::start_maxillo(
      {"--archive", archive, "import", "--batch", "25", (folder / "in" / "a").string(), (folder / "in" / "b").string()},
      folder / "one.out", folder / "one.err");
  pid_t two = testing::start_maxillo(
      {"--archive", archive, "import", "--batch", "30", (folder / "in" / "b").string(), (folder / "in" / "c").string()},
      folder / "two.out", folder / "two.err");
  EXPECT_EQ(testing::wait_exit_code(one), 0) << testing::slurp(folder / "one.err");
  EXPECT_EQ(testing::wait_exit_code(two), 0) << testing::slurp(folder / "two.err");
  EXPECT_EQ(testing::slurp(folder / "one.err"), "");
  EXPECT_EQ(testing::slurp(folder / "two.err"), "");
  EXPECT_EQ(archived_instances(archive, folder.path()), 360);
  auto patients = testing::run_maxillo({"--archive", archive, "--json", "list", "patients"}, folder.path());
  EXPECT_EQ(Json::parse(patients.out).size(), 3u);
  EXPECT_EQ(testing::run_maxillo({"--archive", archive, "verify"}, folder.path()).exit_code, 0);
}

// Issue 31: on a server index the two write side by side; one killed in the middle of a batch
// (its transaction holding rows the other waits for, or the journal counter) must neither stop
// the other nor leave the archive anything but consistent, and running it again completes it.
TEST(ArchiveCli, TwoConcurrentImportersOneKilledLeaveAConsistentArchive) {
  TemporaryFolder folder;
  for (const char* name : {"a", "b", "c"}) testing::write_series(folder / "in" / name, 150, std::string("K") + name);
  auto archive = testing::archive_at(folder / "archive").string();
  const std::vector<std::string> killed_inputs = {(folder / "in" / "a").string(), (folder / "in" / "b").string()};
  std::vector<std::string> killed_command = {"--archive", archive, "import", "--batch", "20"};
  killed_command.insert(killed_command.end(), killed_inputs.begin(), killed_inputs.end());
  pid_t killed = testing::start_maxillo(killed_command, folder / "killed.out", folder / "killed.err");
  pid_t survivor = testing::start_maxillo(
      {"--archive", archive, "import", "--batch", "25", (folder / "in" / "b").string(), (folder / "in" / "c").string()},
      folder / "survivor.out", folder / "survivor.err");
  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  ::kill(killed, SIGKILL);
  testing::wait_exit_code(killed);
  EXPECT_EQ(testing::wait_exit_code(survivor), 0) << testing::slurp(folder / "survivor.err");
  auto verify = testing::run_maxillo({"--archive", archive, "--json", "verify"}, folder.path());
  EXPECT_TRUE(Json::parse(verify.out).at("data_intact").get<bool>()) << verify.out;  // at most orphans
  std::vector<std::string> again_command = {"--archive", archive, "import"};
  again_command.insert(again_command.end(), killed_inputs.begin(), killed_inputs.end());
  auto again = testing::run_maxillo(again_command, folder.path());
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(archived_instances(archive, folder.path()), 450);
  EXPECT_EQ(testing::run_maxillo({"--archive", archive, "verify"}, folder.path()).exit_code, 0);
}

}  // namespace
}  // namespace maxillo
