// Issue 15: `maxillo serve` as the real program, on a free loopback port, against DCMTK's own
// network tools (echoscu, storescu) as independent clients: echo, refused AE titles, 1,000
// instances pushed over 4 associations at once (each sent twice) archived once and byte-exact,
// bad input answered with a failure status while the server goes on, SIGTERM ends it cleanly.
// Skips when the DCMTK tools are absent (scripts/setup installs them).
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcmetinf.h>
#include <dcmtk/dcmdata/dcuid.h>

#include <chrono>
#include <fstream>
#include <span>
#include <thread>

#include "archive/archive.h"
#include "core/atomic_file.h"
#include "dicom/dicom_encapsulated_pdf.h"
#include "dicom/dicom_header.h"
#include "dicom/dicom_series_writer.h"
#include "net_fixture.h"
#include "support/run_command.h"
#include "support/cthead_metaimage.h"
#include "support/run_maxillo.h"
#include "support/temporary_folder.h"

namespace maxillo {
namespace {

using testing::free_loopback_port;
using testing::pixel_data;
using testing::quote;
using testing::run_command;
using testing::slices;
using testing::write_series;

// A copy of a DICOM file changed by `edit` (DCMTK), written with its own transfer syntax.
void edited_copy(const std::filesystem::path& from, const std::filesystem::path& to, auto edit) {
  DcmFileFormat file;
  ASSERT_TRUE(file.loadFile(from.c_str()).good());
  edit(file);
  ASSERT_TRUE(file.saveFile(to.c_str(), EXS_LittleEndianExplicit).good());
}

class Serve : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!testing::tool_available("echoscu") || !testing::tool_available("storescu"))
      GTEST_SKIP() << "DCMTK's echoscu/storescu are not installed (scripts/setup installs the dcmtk package)";
    port_ = free_loopback_port();
    std::vector<std::string> arguments = {"--archive",
                                          archive().string(),
                                          "serve",
                                          "--aet",
                                          "MAXILLO",
                                          "--port",
                                          std::to_string(port_),
                                          "--allow",
                                          "STORESCU",
                                          "--allow",
                                          "ECHOSCU@127.0.0.1",
                                          "--max-associations",
                                          "6",
                                          "--timeout",
                                          "10"};
    for (auto& extra : extra_arguments()) arguments.push_back(std::move(extra));
    server_ = testing::start_maxillo(arguments, folder_ / "serve.out", folder_ / "serve.err");
    ASSERT_GT(server_, 0);
    for (int attempt = 0; attempt < 200 && echo("ECHOSCU").exit_code != 0; ++attempt) {
      int status = 0;
      if (waitpid(server_, &status, WNOHANG) == server_) {
        server_ = -1;
        FAIL() << "the server exited: " << server_errors();
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    ASSERT_EQ(echo("ECHOSCU").exit_code, 0) << "the server did not come up: " << server_errors();
  }

  void TearDown() override {
    if (server_ > 0) stop_server();
  }

  virtual std::vector<std::string> extra_arguments() { return {}; }

  // SIGTERM to the server we started (by its PID), and its exit code.
  int stop_server() {
    const int code = testing::stop_process(server_);
    server_ = -1;
    return code;
  }

  std::filesystem::path archive() const { return folder_ / "archive"; }
  std::string server_errors() const { return testing::slurp(folder_ / "serve.err"); }
  std::string server_output() const { return testing::slurp(folder_ / "serve.out"); }

  testing::CommandResult echo(const std::string& calling_ae) const {
    return run_command("echoscu -aet " + calling_ae + " -aec MAXILLO 127.0.0.1 " + std::to_string(port_) + " 2>&1");
  }
  // `proposal`: storescu's option for the transfer syntax it proposes (default: uncompressed).
  std::string storescu(const std::string& calling_ae, const std::vector<std::filesystem::path>& files,
                       const std::string& proposal = "") const {
    std::string line =
        "storescu " + proposal + " -aet " + calling_ae + " -aec MAXILLO 127.0.0.1 " + std::to_string(port_);
    for (const auto& f : files) line += " " + quote(f);
    return line + " 2>&1";
  }

  TemporaryFolder folder_{"serve"};
  uint16_t port_ = 0;
  pid_t server_ = -1;
};

TEST_F(Serve, AnswersAnEchoFromAnAllowedPeerAndRefusesAStranger) {
  const auto stranger = echo("STRANGER");
  EXPECT_NE(stranger.exit_code, 0);
  EXPECT_NE(stranger.output.find("Association Rejected"), std::string::npos) << stranger.output;
  // The same from an allowed title calling from an address it is not allowed from is covered by the
  // unit tests of is_allowed; here, our own client against our own server.
  const std::string peer = "MAXILLO@127.0.0.1:" + std::to_string(port_);
  const auto ours = testing::run_maxillo({"echo", peer, "--aet", "ECHOSCU"}, folder_.path());
  EXPECT_EQ(ours.exit_code, 0) << ours.err << server_errors();
  EXPECT_NE(ours.out.find("answered in"), std::string::npos);
  const auto refused = testing::run_maxillo({"echo", peer, "--aet", "STRANGER"}, folder_.path());
  EXPECT_EQ(refused.exit_code, exit_code_for(ErrorCode::kNetwork));
  EXPECT_NE(refused.err.find("association failed"), std::string::npos) << refused.err;
  EXPECT_NE(server_errors().find("'STRANGER' from 127.0.0.1 is not allowed"), std::string::npos) << server_errors();
  EXPECT_EQ(stop_server(), 0) << server_errors();
}

TEST_F(Serve, ArchivesWhatFourAssociationsPushOnceAndByteExact) {
  std::vector<WrittenSeries> series;
  for (int s = 0; s < 4; ++s)
    series.push_back(
        write_series(folder_ / ("series" + std::to_string(s)), "NET" + std::to_string(s % 2), 250, int16_t(s)));
  // Four senders at once, each pushing two series, so that every instance arrives twice.
  std::vector<std::thread> senders;
  std::vector<testing::CommandResult> results(4);
  for (int s = 0; s < 4; ++s)
    senders.emplace_back([&, s] {
      std::vector<std::filesystem::path> files = series[size_t(s)].files;
      const auto& next = series[size_t((s + 1) % 4)].files;
      files.insert(files.end(), next.begin(), next.end());
      // The senders without Nagle's delay (no_nagle_delay.h), or each C-STORE waits ~40 ms for an ACK.
      results[size_t(s)] = run_command("TCP_NODELAY=1 " + storescu("STORESCU", files));
    });
  for (auto& sender : senders) sender.join();
  for (const auto& result : results) EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(stop_server(), 0) << server_errors();
  EXPECT_NE(server_output().find("1000 instances archived, 1000 already archived, 0 refused"), std::string::npos)
      << server_output() << server_errors();

  Archive archive = Archive::open(this->archive());
  int64_t instances = 0;
  for (const auto& record : archive.series()) instances += int64_t(archive.instances(record.id).size());
  EXPECT_EQ(instances, 1000);
  EXPECT_EQ(archive.series().size(), 4u);
  EXPECT_EQ(archive.patients().size(), 2u);
  EXPECT_TRUE(archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never).consistent());
  const auto stored = archive.series_instance_files(archive.resolve_series(series[2].series_instance_uid));
  ASSERT_EQ(stored.size(), 250u);
  EXPECT_EQ(pixel_data(stored[17]), pixel_data(series[2].files[17]));
  EXPECT_FALSE(pixel_data(stored[17]).empty());
  EXPECT_TRUE(std::filesystem::is_empty(this->archive() / "incoming"));
}

// Issue 29, fault 3: `serve` accepted compressed transfer syntaxes, but every command that read
// their pixels refused them ("implausible for 0 bytes of compressed pixel data"). Each lossless
// syntax DCMTK writes, from storescu to the archive, then surfaces and a report from it.
TEST_F(Serve, EveryCompressedSyntaxReceivedEndsInSurfacesAndAReport) {
  struct Codec {
    std::string tool, options, transfer_syntax, proposal;
  };
  const std::vector<Codec> codecs = {{"dcmcjpeg", "+e1", "1.2.840.10008.1.2.4.70", "-xs"},
                                     {"dcmcrle", "", "1.2.840.10008.1.2.5", "-xr"},
                                     {"dcmcjpls", "+el", "1.2.840.10008.1.2.4.80", "-xt"}};
  for (const auto& codec : codecs)
    if (!testing::tool_available(codec.tool)) GTEST_SKIP() << codec.tool << " is not installed (the dcmtk package)";
  std::vector<std::string> patients;
  for (size_t n = 0; n < codecs.size(); ++n) {
    const std::string patient = "NETCODEC" + std::to_string(n);
    patients.push_back(patient);
    const auto sample = folder_ / patient;
    ASSERT_EQ(testing::run_maxillo({"sample", "--out", sample.string(), "--spacing", "3", "--patient-id", patient},
                                   folder_.path())
                  .exit_code,
              0);
    std::vector<std::filesystem::path> compressed;
    std::filesystem::create_directories(sample / "compressed");
    for (const auto& file : std::filesystem::directory_iterator(sample / "ct")) {
      compressed.push_back(sample / "compressed" / file.path().filename());
      const auto made = run_command(codecs[n].tool + " " + codecs[n].options + " " + quote(file.path()) + " " +
                                    quote(compressed.back()) + " 2>&1");
      ASSERT_EQ(made.exit_code, 0) << made.output;
    }
    const auto sent = run_command("TCP_NODELAY=1 " + storescu("STORESCU", compressed, codecs[n].proposal));
    ASSERT_EQ(sent.exit_code, 0) << sent.output;
  }
  ASSERT_EQ(stop_server(), 0) << server_errors();

  Archive archive = Archive::open(this->archive());
  for (size_t n = 0; n < patients.size(); ++n) {
    SCOPED_TRACE(codecs[n].tool);
    const int64_t case_id = archive.resolve_case(patients[n]);
    const auto series = archive.case_contents(case_id).series.at(0).series.id;
    const auto archived = archive.series_instance_files(series).at(0);  // kept as it was sent
    EXPECT_EQ(parse_instance_header(read_file(archived), archived).transfer_syntax_uid, codecs[n].transfer_syntax);
    const auto stored = folder_ / ("stored-" + patients[n]);
    const auto exported = testing::run_maxillo(
        {"--archive", this->archive().string(), "export", std::to_string(series), "--out", stored.string()},
        folder_.path());
    ASSERT_EQ(exported.exit_code, 0) << exported.err;
    const auto surfaces = testing::run_maxillo(
        {"surfaces", stored.string(), "--out", (folder_ / ("surfaces-" + patients[n])).string()}, folder_.path());
    EXPECT_EQ(surfaces.exit_code, 0) << surfaces.err;
    EXPECT_TRUE(std::filesystem::exists(folder_ / ("surfaces-" + patients[n]) / "skin.stl"));
    const auto report =
        testing::run_maxillo({"--archive", this->archive().string(), "report", "case:" + std::to_string(case_id),
                              "--out", (folder_ / (patients[n] + ".pdf")).string()},
                             folder_.path());
    EXPECT_EQ(report.exit_code, 0) << report.err;
    EXPECT_TRUE(std::filesystem::exists(folder_ / (patients[n] + ".pdf")));
  }
}

TEST_F(Serve, AnswersBadInstancesWithAFailureAndGoesOn) {
  const auto good = write_series(folder_ / "good", "NETBAD", 3, 0);
  const auto no_study = folder_ / "no-study.dcm";
  edited_copy(good.files[0], no_study,
              [](DcmFileFormat& f) { f.getDataset()->findAndDeleteElement(DCM_StudyInstanceUID); });
  const auto rt_plan = folder_ / "rt-plan.dcm";
  edited_copy(good.files[1], rt_plan, [](DcmFileFormat& f) {
    f.getDataset()->putAndInsertString(DCM_SOPClassUID, UID_RTPlanStorage);
    f.getMetaInfo()->putAndInsertString(DCM_MediaStorageSOPClassUID, UID_RTPlanStorage);
  });

  const auto missing = run_command(storescu("STORESCU", {no_study}));
  EXPECT_NE(missing.exit_code, 0) << missing.output;
  const auto unsupported = run_command(storescu("STORESCU", {rt_plan}));
  EXPECT_NE(unsupported.exit_code, 0) << unsupported.output;
  // The server goes on: the good instances are archived afterwards.
  const auto stored = run_command(storescu("STORESCU", good.files));
  EXPECT_EQ(stored.exit_code, 0) << stored.output;
  EXPECT_EQ(stop_server(), 0);
  EXPECT_NE(server_errors().find("refused (status 0xc000)"), std::string::npos) << server_errors();
  // One line per association for the contexts refused (storescu proposes over a hundred); the
  // list itself only at -v (issue 29, fault 12).
  EXPECT_NE(server_errors().find("presentation contexts we do not accept (-v lists them)"), std::string::npos)
      << server_errors();
  EXPECT_EQ(server_errors().find("not a class we store (refused)"), std::string::npos) << server_errors();
  EXPECT_NE(server_output().find("3 instances archived, 0 already archived, 1 refused"), std::string::npos)
      << server_output();
  Archive archive = Archive::open(this->archive());
  EXPECT_EQ(archive.instances(archive.resolve_series(good.series_instance_uid)).size(), 3u);
  EXPECT_TRUE(archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never).consistent());
  // No patient name or ID in the server's log at the default level.
  EXPECT_EQ(server_errors().find("NETBAD"), std::string::npos) << server_errors();
  EXPECT_EQ(server_errors().find("Network^Test"), std::string::npos) << server_errors();
}

// A pushed instance the sender abandons half-way (storescu killed while the server receives it)
// leaves nothing: no row, no file in incoming/; the server goes on. Instances already answered
// survive a kill -9 of the server.
TEST_F(Serve, LosesNothingAcknowledgedAndKeepsNothingHalfReceived) {
  Volume large;
  large.geometry.size = {8192, 8192, 1};
  large.geometry.spacing = {0.1, 0.1, 1.0};
  large.hu.assign(size_t(large.geometry.voxel_count()), 40);
  const auto huge = write_ct_series(large, {}, folder_ / "huge");
  const pid_t sender = testing::start_process({testing::tool_path("storescu"), "-aet", "STORESCU", "-aec", "MAXILLO",
                                               "127.0.0.1", std::to_string(port_), huge.files[0].string()},
                                              folder_ / "sender.out", folder_ / "sender.err");
  bool receiving = false;
  for (int waited = 0; waited < 20000 && !receiving; ++waited) {
    for (const auto& entry : std::filesystem::directory_iterator(archive() / "incoming"))
      receiving |= entry.is_regular_file() && entry.file_size() > 0;
    if (!receiving) std::this_thread::sleep_for(std::chrono::microseconds(500));
  }
  kill(sender, SIGKILL);
  testing::wait_exit_code(sender);
  ASSERT_TRUE(receiving) << "the transfer was never seen in progress";
  for (int waited = 0; waited < 100 && !std::filesystem::is_empty(archive() / "incoming"); ++waited)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_TRUE(std::filesystem::is_empty(archive() / "incoming"));
  EXPECT_EQ(echo("ECHOSCU").exit_code, 0) << "the server goes on";

  const auto small = write_series(folder_ / "small", "NETKILL", 20, 0);
  ASSERT_EQ(run_command(storescu("STORESCU", small.files)).exit_code, 0);
  kill(server_, SIGKILL);
  testing::wait_exit_code(server_);
  server_ = -1;
  Archive archive = Archive::open(this->archive());
  EXPECT_EQ(archive.series().size(), 1u) << "the abandoned instance made no series";
  EXPECT_EQ(archive.instances(archive.resolve_series(small.series_instance_uid)).size(), 20u);
  EXPECT_TRUE(archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never).consistent());
}

// `maxillo send` from another archive into this server: the archived series arrives with its
// UIDs and pixel data; --deidentify sends pseudonymised copies (new UIDs, an ANON- patient) and
// never the patient's report.
TEST_F(Serve, ReceivesWhatMaxilloSendsOriginalAndDeidentified) {
  const auto written = write_series(folder_ / "source-files", "NETSEND", 12, 5);
  const auto source = folder_ / "source";
  Archive::open(source, OpenMode::CreateIfMissing)
      .import_paths({folder_ / "source-files"}, {.progress = ProgressDisplay::Never});
  const std::string peer = "MAXILLO@127.0.0.1:" + std::to_string(port_);
  const auto original = testing::run_maxillo(
      {"--archive", source.string(), "send", written.series_instance_uid, "--to", peer, "--aet", "STORESCU"},
      folder_.path());
  EXPECT_EQ(original.exit_code, 0) << original.err;
  EXPECT_NE(original.out.find("sent 12 instances"), std::string::npos) << original.out;
  // The patient's report, filed in the study as an Encapsulated PDF, names the patient inside
  // the document: the de-identified send withholds it, says so, and sends the CT.
  {
    Archive filed = Archive::open(source);
    const auto contents = filed.case_contents(filed.resolve_case("NETSEND"));
    const std::string pdf = "%PDF-1.4\n% report\n%%EOF\n";
    std::filesystem::create_directories(folder_ / "report");
    write_encapsulated_pdf(std::as_bytes(std::span(pdf)),
                           EncapsulatedReport{contents.patient, contents.studies.front(), "Report"},
                           folder_ / "report" / "r.dcm");
    ASSERT_TRUE(filed.import_paths({folder_ / "report"}, {.progress = ProgressDisplay::Never}).all_ok());
  }
  const auto anonymous = testing::run_maxillo(
      {"--archive", source.string(), "send", "NETSEND", "--deidentify", "--to", peer, "--aet", "STORESCU"},
      folder_.path());
  EXPECT_EQ(anonymous.exit_code, exit_code_for(ErrorCode::kBatchPartlyFailed)) << anonymous.err;
  EXPECT_NE(anonymous.out.find("sent 12 instances (de-identified)"), std::string::npos) << anonymous.out;
  EXPECT_NE(anonymous.out.find("1 series withheld"), std::string::npos) << anonymous.out;
  EXPECT_NE(anonymous.err.find("encapsulated document"), std::string::npos) << anonymous.err;
  const auto stranger = testing::run_maxillo(
      {"--archive", source.string(), "send", "NETSEND", "--to", peer, "--aet", "STRANGER"}, folder_.path());
  EXPECT_EQ(stranger.exit_code, exit_code_for(ErrorCode::kNetwork)) << stranger.err;
  EXPECT_EQ(stop_server(), 0);

  Archive archive = Archive::open(this->archive());
  const auto received = archive.series_instance_files(archive.resolve_series(written.series_instance_uid));
  ASSERT_EQ(received.size(), 12u);
  for (size_t i = 0; i < received.size(); ++i) EXPECT_EQ(pixel_data(received[i]), pixel_data(written.files[i])) << i;
  ASSERT_EQ(archive.patients().size(), 2u);
  bool pseudonym = false;
  for (const auto& patient : archive.patients()) pseudonym |= patient.patient_id.rfind("ANON-", 0) == 0;
  EXPECT_TRUE(pseudonym);
  EXPECT_EQ(archive.series().size(), 2u);
}

// A peer that connects and says nothing (a dead scanner, a port scanner) does not hold up the
// others beyond a few seconds: echoscu, which gives up after 8 s, is answered while the silent
// connection is still open (the server's --timeout is 10 s).
TEST_F(Serve, ASilentConnectionDoesNotHoldUpOtherPeers) {
  const int silent = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(port_);
  ASSERT_EQ(connect(silent, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the server is now reading from it
  const auto answered =
      run_command("echoscu -ta 8 -aet ECHOSCU -aec MAXILLO 127.0.0.1 " + std::to_string(port_) + " 2>&1");
  close(silent);
  EXPECT_EQ(answered.exit_code, 0) << answered.output;
  EXPECT_EQ(stop_server(), 0);
}

// Retrieving from a peer that offers no query/retrieve (our own server only stores) says which
// service is missing; a C-MOVE port already taken is named before anything is asked.
TEST_F(Serve, RetrieveNamesTheMissingServiceAndATakenMovePort) {
  const std::string peer = "MAXILLO@127.0.0.1:" + std::to_string(port_);
  const auto by_get = testing::run_maxillo(
      {"--archive", (folder_ / "fetched").string(), "retrieve", "--from", peer, "--aet", "STORESCU", "1.2.3.4"},
      folder_.path());
  EXPECT_EQ(by_get.exit_code, exit_code_for(ErrorCode::kNetwork));
  EXPECT_NE(by_get.err.find("does not offer C-GET"), std::string::npos) << by_get.err;
  const auto by_move =
      testing::run_maxillo({"--archive", (folder_ / "fetched").string(), "retrieve", "--from", peer, "--aet",
                            "STORESCU", "--move-port", std::to_string(free_loopback_port()), "1.2.3.4"},
                           folder_.path());
  EXPECT_EQ(by_move.exit_code, exit_code_for(ErrorCode::kNetwork));
  EXPECT_NE(by_move.err.find("does not offer C-MOVE"), std::string::npos) << by_move.err;
  const auto taken = testing::run_maxillo({"--archive", (folder_ / "fetched").string(), "retrieve", "--from", peer,
                                           "--aet", "STORESCU", "--move-port", std::to_string(port_), "1.2.3.4"},
                                          folder_.path());
  EXPECT_EQ(taken.exit_code, exit_code_for(ErrorCode::kWriteFailed));
  EXPECT_NE(taken.err.find("port " + std::to_string(port_)), std::string::npos) << taken.err;
  const auto neither = testing::run_maxillo({"retrieve", "--from", peer}, folder_.path());
  EXPECT_EQ(neither.exit_code, exit_code_for(ErrorCode::kUsage)) << neither.err;
}

// The stable-study action, configured in a configuration file beside command-line options: run
// once when a study has been quiet for a second, not again for instances received again, again
// when a new series arrives in the study.
class ServeWithStableAction : public Serve {
 protected:
  std::vector<std::string> extra_arguments() override {
    std::ofstream(folder_ / "serve.json")
        << R"({"ae_title": "IGNORED", "stable_study": {"after_seconds": 1, "command": "echo \"$MAXILLO_STUDY_UID case:$MAXILLO_CASE\" >> )"
        << (folder_ / "stable.txt").string() << R"("}})";
    return {"--config", (folder_ / "serve.json").string()};
  }

  std::vector<std::string> actions_after(size_t count) const {
    std::vector<std::string> lines;
    for (int waited = 0; waited < 100; ++waited) {
      lines.clear();
      std::ifstream in(folder_ / "stable.txt");
      for (std::string line; std::getline(in, line);) lines.push_back(line);
      if (lines.size() >= count) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return lines;
  }
};

TEST_F(ServeWithStableAction, RunsOncePerChangeOfAStudy) {
  const auto first = write_series(folder_ / "first", "NETSTABLE", 3, 0);
  ASSERT_EQ(run_command(storescu("STORESCU", first.files)).exit_code, 0);
  auto lines = actions_after(1);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].rfind(first.study_instance_uid + " case:", 0), 0u) << lines[0];
  EXPECT_GT(lines[0].size(), first.study_instance_uid.size() + 6) << "the case id is given";

  ASSERT_EQ(run_command(storescu("STORESCU", first.files)).exit_code, 0);  // already archived: no change
  std::this_thread::sleep_for(std::chrono::milliseconds(2500));
  EXPECT_EQ(actions_after(1).size(), 1u);

  SeriesMetadata metadata;
  metadata.patient_id = "NETSTABLE";
  metadata.study_instance_uid = first.study_instance_uid;
  metadata.series_number = 2;
  const auto second = write_ct_series(slices(2, 7), metadata, folder_ / "second");
  ASSERT_EQ(run_command(storescu("STORESCU", second.files)).exit_code, 0);
  lines = actions_after(2);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[1], lines[0]);
  EXPECT_EQ(stop_server(), 0);
  EXPECT_NE(server_output().find("2 stable-study actions (0 failed)"), std::string::npos) << server_output();
}

// Issue 28: a study received is checked like one imported, once it has arrived. The cadaver head
// converted with its raw axes (the vertex inferior: a header that contradicts the anatomy) is
// pushed as a scanner would; with no other command run on the case, `list cases` then shows the
// flag the server recorded.
class ServeStableAfterASecond : public Serve {
 protected:
  std::vector<std::string> extra_arguments() override { return {"--stable-seconds", "1"}; }
};

TEST_F(ServeStableAfterASecond, ChecksTheOrientationOfWhatItReceived) {
  if (!std::filesystem::exists(testing::cthead_slices() / "CThead.113"))
    GTEST_SKIP() << "real data absent: " << testing::cthead_slices();
  testing::write_cthead_metaimage(folder_.path(), "raw.mhd");
  const std::string maxillo = std::string(MAXILLO_BINARY) + " --archive " + quote(folder_ / "elsewhere");
  const auto converted =
      run_command(maxillo + " convert " + quote(folder_ / "raw.mhd") + " --out " + quote(folder_ / "dicom") + " 2>&1");
  ASSERT_EQ(converted.exit_code, 0) << converted.output;
  ASSERT_EQ(run_command("storescu +sd -aet STORESCU -aec MAXILLO 127.0.0.1 " + std::to_string(port_) + " " +
                        quote(folder_ / "dicom") + " 2>&1")
                .exit_code,
            0);
  const std::string list = std::string(MAXILLO_BINARY) + " --archive " + quote(archive()) + " list cases";
  std::string cases;
  for (int waited = 0; waited < 300 && cases.find("CONTRADICTS") == std::string::npos; ++waited) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    cases = run_command(list).output;
  }
  EXPECT_NE(cases.find("CONTRADICTS"), std::string::npos) << cases;
  EXPECT_EQ(stop_server(), 0);
  EXPECT_NE(server_errors().find("the header contradicts the anatomy"), std::string::npos) << server_errors();
}

// A server killed before a study's quiet period ended still owes its action: the restarted server
// runs it (once), and a third start finds nothing owed.
TEST(ServeStableAcrossRestarts, AnActionOwedBeforeAKillRunsAfterTheRestart) {
  if (!testing::tool_available("echoscu") || !testing::tool_available("storescu"))
    GTEST_SKIP() << "DCMTK's echoscu/storescu are not installed";
  TemporaryFolder folder("serve-restart");
  const auto actions = folder / "actions.txt";
  const uint16_t port = free_loopback_port();
  auto start = [&](int stable_seconds) {
    const pid_t pid = testing::start_maxillo(
        {"--archive", (folder / "archive").string(), "serve", "--port", std::to_string(port), "--allow", "STORESCU",
         "--allow", "ECHOSCU", "--stable-seconds", std::to_string(stable_seconds), "--on-stable-study",
         "echo \"$MAXILLO_STUDY_UID\" >> " + quote(actions)},
        folder / "serve.out", folder / "serve.err");
    for (int attempt = 0; attempt < 200; ++attempt) {
      if (run_command("echoscu -aet ECHOSCU -aec MAXILLO 127.0.0.1 " + std::to_string(port) + " 2>&1").exit_code == 0)
        break;
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return pid;
  };
  auto lines = [&] {
    std::vector<std::string> found;
    std::ifstream in(actions);
    for (std::string line; std::getline(in, line);) found.push_back(line);
    return found;
  };
  const auto series = write_series(folder / "series", "NETRESTART", 3, 0);

  pid_t server = start(3600);
  std::string push = "storescu -aet STORESCU -aec MAXILLO 127.0.0.1 " + std::to_string(port);
  for (const auto& file : series.files) push += " " + quote(file);
  ASSERT_EQ(run_command(push).exit_code, 0);
  kill(server, SIGKILL);  // long before the hour of quiet
  waitpid(server, nullptr, 0);
  EXPECT_TRUE(lines().empty());

  server = start(1);
  for (int waited = 0; waited < 100 && lines().empty(); ++waited)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_EQ(testing::stop_process(server), 0);
  ASSERT_EQ(lines().size(), 1u);
  EXPECT_EQ(lines()[0], series.study_instance_uid);

  server = start(1);
  std::this_thread::sleep_for(std::chrono::milliseconds(2500));
  EXPECT_EQ(testing::stop_process(server), 0);
  EXPECT_EQ(lines().size(), 1u) << "nothing owed any more";
}

// Issue 29, fault 12: "listening on port N" was printed before the bind failed.
TEST(ServeStart, APortTakenByAnotherIsAnErrorBeforeAnythingSaysListening) {
  TemporaryFolder folder{"serve-port"};
  const int holder = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_ANY);
  ASSERT_EQ(bind(holder, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  ASSERT_EQ(listen(holder, 1), 0);
  socklen_t length = sizeof address;
  getsockname(holder, reinterpret_cast<sockaddr*>(&address), &length);
  const std::string port = std::to_string(ntohs(address.sin_port));
  const auto run = testing::run_maxillo(
      {"--archive", (folder / "archive").string(), "serve", "--aet", "MAXILLO", "--port", port, "--allow", "X"},
      folder.path());
  close(holder);
  EXPECT_EQ(run.exit_code, exit_code_for(ErrorCode::kWriteFailed)) << run.err;
  EXPECT_NE(run.err.find("port " + port), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("in use"), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("listening"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace maxillo
