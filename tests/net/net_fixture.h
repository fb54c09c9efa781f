#pragma once
// Shared by the network tests: loopback ports, small CT series, pixel data, and child servers
// stopped by their own PID.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>

#include "dicom/dicom_series_writer.h"
#include "support/run_command.h"

namespace maxillo::testing {

// A TCP port nothing listens on now (the kernel's choice for an ephemeral bind).
inline uint16_t free_loopback_port() {
  const int s = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  bind(s, reinterpret_cast<sockaddr*>(&address), sizeof address);
  socklen_t length = sizeof address;
  getsockname(s, reinterpret_cast<sockaddr*>(&address), &length);
  close(s);
  return ntohs(address.sin_port);
}

// `count` 16 x 16 CT slices of distinct values (base shifts them, so two series differ).
inline Volume slices(int count, int16_t base) {
  Volume volume;
  volume.geometry.size = {16, 16, count};
  volume.geometry.spacing = {0.5, 0.5, 1.0};
  volume.hu.resize(size_t(volume.geometry.voxel_count()));
  for (size_t n = 0; n < volume.hu.size(); ++n) volume.hu[n] = int16_t(base + int(n % 2000) - 1000);
  return volume;
}

// A CT series of such slices for a patient, as DICOM files in `folder`.
inline WrittenSeries write_series(const std::filesystem::path& folder, const std::string& patient_id, int count,
                                  int16_t base) {
  SeriesMetadata metadata;
  metadata.patient_id = patient_id;
  metadata.patient_name = "Network^Test";
  metadata.study_date = "20261125";
  return write_ct_series(slices(count, base), metadata, folder);
}

// The pixel data of a DICOM file as bytes (empty when unreadable).
inline std::string pixel_data(const std::filesystem::path& path) {
  DcmFileFormat file;
  if (!file.loadFile(path.c_str()).good()) return {};
  const Uint8* bytes = nullptr;
  unsigned long length = 0;
  if (!file.getDataset()->findAndGetUint8Array(DCM_PixelData, bytes, &length).good()) return {};
  return std::string(reinterpret_cast<const char*>(bytes), length);
}

// The absolute path of a tool on PATH (empty when absent).
inline std::string tool_path(const std::string& name) {
  std::string path = run_command("command -v " + name).output;
  path.erase(path.find_last_not_of('\n') + 1);
  return path;
}

// SIGTERM to a child we started, by its PID; its exit code (128 + signal), or -1 after SIGKILL
// when it did not stop within 30 s.
inline int stop_process(pid_t pid) {
  kill(pid, SIGTERM);
  for (int waited = 0; waited < 300; ++waited) {
    int status = 0;
    if (waitpid(pid, &status, WNOHANG) == pid) return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
  return -1;
}

}  // namespace maxillo::testing
