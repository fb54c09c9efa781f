// Issue 15: Orthanc (Debian's `orthanc`) as the PACS, started on free loopback ports in a
// temporary folder and stopped by its PID: maxillo sends a series to it, Orthanc pushes a study to
// `maxillo serve` (its modality store), maxillo finds (C-FIND) and retrieves that study (C-GET, and
// C-MOVE by Patient ID),
// and the case's report goes back as an Encapsulated PDF that Orthanc files in the right study. Skips when Orthanc is not installed.
#include <gtest/gtest.h>

#include <fstream>

#include "archive/archive.h"
#include "core/json.h"
#include "dicom/dicom_encapsulated_pdf.h"
#include "net_fixture.h"
#include "support/run_maxillo.h"
#include "support/temporary_folder.h"

namespace maxillo {
namespace {

using testing::quote;
using testing::run_command;

class OrthancPeer : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string orthanc = testing::tool_path("Orthanc");
    if (orthanc.empty() || testing::tool_path("curl").empty())
      GTEST_SKIP() << "Orthanc or curl is not installed (scripts/setup installs them)";
    http_port_ = testing::free_loopback_port();
    dicom_port_ = testing::free_loopback_port();
    serve_port_ = testing::free_loopback_port();
    const Json config = {{"Name", "maxillo-test"},
                         {"StorageDirectory", (folder_ / "orthanc-db").string()},
                         {"IndexDirectory", (folder_ / "orthanc-db").string()},
                         {"HttpPort", http_port_},
                         {"DicomPort", dicom_port_},
                         {"DicomAet", "ORTHANC"},
                         {"RemoteAccessAllowed", false},
                         {"AuthenticationEnabled", false},
                         {"DicomCheckCalledAet", true},
                         {"DicomModalities", {{"maxillo", {"MAXILLO", "127.0.0.1", serve_port_}}}},
                         {"Plugins", Json::array()}};
    std::ofstream(folder_ / "orthanc.json") << config.dump(2);
    orthanc_ = testing::start_process({orthanc, (folder_ / "orthanc.json").string()}, folder_ / "orthanc.out",
                                      folder_ / "orthanc.err");
    for (int attempt = 0; attempt < 100 && rest("GET", "/system").empty(); ++attempt)
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    ASSERT_FALSE(rest("GET", "/system").empty()) << testing::slurp(folder_ / "orthanc.err");

    server_ = testing::start_maxillo({"--archive", archive().string(), "serve", "--aet", "MAXILLO", "--port",
                                      std::to_string(serve_port_), "--allow", "ORTHANC@127.0.0.1"},
                                     folder_ / "serve.out", folder_ / "serve.err");
    for (int attempt = 0; attempt < 100 && !serving(); ++attempt)
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    ASSERT_TRUE(serving()) << testing::slurp(folder_ / "serve.err");
  }

  void TearDown() override {
    if (server_ > 0) testing::stop_process(server_);
    if (orthanc_ > 0) testing::stop_process(orthanc_);
  }

  bool serving() const {
    return testing::run_maxillo({"echo", "MAXILLO@127.0.0.1:" + std::to_string(serve_port_), "--aet", "ORTHANC"},
                                folder_.path())
               .exit_code == 0;
  }

  // Orthanc's REST API: the response body ("" when the request failed).
  std::string rest(const std::string& method, const std::string& path, const std::string& data_option = "") const {
    return run_command("curl -sf -X " + method + " " + data_option + " http://127.0.0.1:" + std::to_string(http_port_) +
                       path)
        .output;
  }
  Json rest_json(const std::string& method, const std::string& path, const std::string& data_option = "") const {
    const std::string body = rest(method, path, data_option);
    return body.empty() ? Json() : Json::parse(body);
  }

  std::filesystem::path archive() const { return folder_ / "archive"; }
  std::string orthanc_peer() const { return "ORTHANC@127.0.0.1:" + std::to_string(dicom_port_); }

  testing::TemporaryFolder folder_{"orthanc"};
  uint16_t http_port_ = 0, dicom_port_ = 0, serve_port_ = 0;
  pid_t orthanc_ = -1, server_ = -1;
};

TEST_F(OrthancPeer, SendReceiveFindRetrieveAndTheReportBack) {
  // maxillo -> Orthanc: an archived series.
  const auto ours = testing::write_series(folder_ / "ours", "NETPACS", 6, 3);
  const auto source = folder_ / "source";
  Archive::open(source, OpenMode::CreateIfMissing)
      .import_paths({folder_ / "ours"}, {.progress = ProgressDisplay::Never});
  const auto sent = testing::run_maxillo(
      {"--archive", source.string(), "send", ours.series_instance_uid, "--to", orthanc_peer()}, folder_.path());
  ASSERT_EQ(sent.exit_code, 0) << sent.err;
  EXPECT_EQ(rest_json("GET", "/instances").size(), 6u);

  // Orthanc -> maxillo serve: a study uploaded to Orthanc, pushed by its modality store.
  const auto theirs = testing::write_series(folder_ / "theirs", "NETPACS2", 4, 9);
  std::string orthanc_series;
  for (const auto& file : theirs.files)
    orthanc_series = rest_json("POST", "/instances", "--data-binary @" + quote(file)).value("ParentSeries", "");
  ASSERT_FALSE(orthanc_series.empty());
  const Json pushed = rest_json("POST", "/modalities/maxillo/store", "-d " + quote(orthanc_series));
  ASSERT_FALSE(pushed.is_null()) << testing::slurp(folder_ / "serve.err");
  ASSERT_EQ(testing::stop_process(server_), 0);
  server_ = -1;
  {
    Archive received = Archive::open(archive());
    const auto files = received.series_instance_files(received.resolve_series(theirs.series_instance_uid));
    ASSERT_EQ(files.size(), 4u);
    for (size_t i = 0; i < files.size(); ++i)
      EXPECT_EQ(testing::pixel_data(files[i]), testing::pixel_data(theirs.files[i]))
          << "byte-identical pixel data " << i;
  }

  // Query and retrieve: the study Orthanc holds, found by Patient ID, fetched by C-GET into a new archive.
  const auto found_json =
      testing::run_maxillo({"--json", "find", "--from", orthanc_peer(), "--patient-id", "NETPACS2"}, folder_.path());
  ASSERT_EQ(found_json.exit_code, 0) << found_json.err;
  const Json studies = Json::parse(found_json.out);
  ASSERT_EQ(studies.size(), 1u) << found_json.out;
  EXPECT_EQ(studies[0]["study_uid"], theirs.study_instance_uid);
  EXPECT_EQ(studies[0]["instances"], 4);
  const auto fetched = folder_ / "fetched";
  const auto retrieved = testing::run_maxillo(
      {"--archive", fetched.string(), "retrieve", "--from", orthanc_peer(), theirs.study_instance_uid}, folder_.path());
  ASSERT_EQ(retrieved.exit_code, 0) << retrieved.err;
  {
    Archive archive = Archive::open(fetched);
    const auto files = archive.series_instance_files(archive.resolve_series(theirs.series_instance_uid));
    ASSERT_EQ(files.size(), 4u);
    for (size_t i = 0; i < files.size(); ++i)
      EXPECT_EQ(testing::pixel_data(files[i]), testing::pixel_data(theirs.files[i]));
    EXPECT_TRUE(archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never).consistent());
  }
  // The same study by C-MOVE, found by Patient ID: Orthanc delivers to MAXILLO at serve_port_
  // (its configured modality; the server is stopped, so the retrieve listens there itself).
  const auto moved = folder_ / "moved";
  const auto by_move = testing::run_maxillo({"--archive", moved.string(), "retrieve", "--from", orthanc_peer(),
                                             "--patient-id", "NETPACS2", "--move-port", std::to_string(serve_port_)},
                                            folder_.path());
  ASSERT_EQ(by_move.exit_code, 0) << by_move.err;
  EXPECT_NE(by_move.out.find("4 instances received, 4 archived"), std::string::npos) << by_move.out;
  {
    Archive archive = Archive::open(moved);
    const auto files = archive.series_instance_files(archive.resolve_series(theirs.series_instance_uid));
    ASSERT_EQ(files.size(), 4u);
    for (size_t i = 0; i < files.size(); ++i)
      EXPECT_EQ(testing::pixel_data(files[i]), testing::pixel_data(theirs.files[i]));
  }

  // The report back: an Encapsulated PDF in the study of the series sent first.
  Archive archive = Archive::open(source);
  const int64_t case_id = archive.resolve_case("NETPACS");
  const auto contents = archive.case_contents(case_id);
  const std::string pdf = "%PDF-1.4\n% a stand-in for the consultation report\n%%EOF\n";
  const auto report_file = folder_ / "report.dcm";
  write_encapsulated_pdf(std::as_bytes(std::span(pdf)),
                         EncapsulatedReport{contents.patient, contents.studies.front(), "Consultation report"},
                         report_file);
  ASSERT_TRUE(archive.import_paths({report_file}, {.progress = ProgressDisplay::Never}).all_ok());
  for (const auto& series : archive.case_contents(case_id).series)
    if (series.series.modality == "DOC") archive.set_series_role(case_id, series.series.id, "report");
  const auto report = testing::run_maxillo(
      {"--archive", source.string(), "send", "--report", std::to_string(case_id), "--to", orthanc_peer()},
      folder_.path());
  ASSERT_EQ(report.exit_code, 0) << report.err;
  const Json found =
      rest_json("POST", "/tools/find",
                "-d " + quote(Json{{"Level", "Series"},
                                   {"Query", {{"StudyInstanceUID", ours.study_instance_uid}, {"Modality", "DOC"}}}}
                                  .dump()));
  EXPECT_EQ(found.size(), 1u) << "the report is in the study it belongs to";
}

// Issue 29, fault 13: the PACS delivered the C-MOVE to the port it knows for our AE title (here
// a running `maxillo serve`), not to the --move-port we listened on; the retrieve said "the peer
// sent nothing (no such study there?)".
TEST_F(OrthancPeer, AMoveDeliveredToAnotherPortOfOursIsNamedAsSuch) {
  const auto theirs = testing::write_series(folder_ / "theirs", "NETMOVE", 2, 5);
  for (const auto& file : theirs.files) rest_json("POST", "/instances", "--data-binary @" + quote(file));
  const auto elsewhere =
      testing::run_maxillo({"--archive", (folder_ / "elsewhere").string(), "retrieve", "--from", orthanc_peer(),
                            theirs.study_instance_uid, "--move-port", std::to_string(testing::free_loopback_port())},
                           folder_.path());
  EXPECT_NE(elsewhere.exit_code, 0);
  EXPECT_NE(elsewhere.err.find("the peer says it sent 2 instances, but none reached"), std::string::npos)
      << elsewhere.err;
  EXPECT_EQ(elsewhere.err.find("no such study"), std::string::npos) << elsewhere.err;
}

}  // namespace
}  // namespace maxillo
