#include "fuzz_entries.h"

#include <unistd.h>

#include <string>

#include "ceph/follow_up.h"
#include "ceph/landmark_io.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "dicom/dicom_header.h"
#include "dicom/dicom_slice_reader.h"
#include "mesh/mesh_io.h"
#include "planning/plan.h"

namespace maxillo::fuzzing {
namespace {

std::string_view text_of(std::span<const std::byte> bytes) {
  return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

// Bad input is expected; only maxillo::Error may say so.
template <typename Body>
void expecting_errors(Body&& body) {
  try {
    body();
  } catch (const Error&) {}
}

// VTK's readers take file names: the input goes to a file of this process's own (on tmpfs
// when there is one, /dev/shm, so that a million runs do not wear a disk).
std::filesystem::path scratch_file(const char* extension) {
  const std::filesystem::path folder =
      std::filesystem::exists("/dev/shm") ? "/dev/shm" : std::filesystem::temp_directory_path();
  return folder / ("maxillo-fuzz-" + std::to_string(::getpid()) + extension);
}

}  // namespace

void dicom_header(std::span<const std::byte> bytes) {
  expecting_errors([&] { parse_instance_header(bytes, "fuzz.dcm"); });
}

void dicom_slice(std::span<const std::byte> bytes) {
  expecting_errors([&] { decode_dicom_slice(bytes, "fuzz.dcm"); });
}

void landmarks(std::span<const std::byte> bytes) {
  if (bytes.empty()) return;
  constexpr LandmarkFormat kFormats[] = {LandmarkFormat::kCsv, LandmarkFormat::kSlicerFcsv,
                                         LandmarkFormat::kSlicerMarkupsJson};
  const auto format = kFormats[std::to_integer<unsigned>(bytes[0]) % 3];
  expecting_errors([&] { parse_landmarks(text_of(bytes.subspan(1)), format, "fuzz"); });
}

void plan_json(std::span<const std::byte> bytes) {
  expecting_errors([&] { planning::parse_plan(text_of(bytes), "fuzz.json"); });
}

void mesh_file(std::span<const std::byte> bytes) {
  if (bytes.empty()) return;
  const auto file = scratch_file(std::to_integer<unsigned>(bytes[0]) % 2 ? ".ply" : ".stl");
  write_file_atomically(file, bytes.subspan(1), Durability::Unflushed);
  expecting_errors([&] { read_mesh(file); });
  std::error_code ignored;
  std::filesystem::remove(file, ignored);
}

void cohort_csv(std::span<const std::byte> bytes) {
  expecting_errors([&] { ceph::parse_cohort_csv(text_of(bytes), "fuzz.csv"); });
}

}  // namespace maxillo::fuzzing
