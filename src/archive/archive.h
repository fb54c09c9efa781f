#pragma once
// The case archive: a folder holding an SQLite index (index.sqlite) and a content-addressed
// object store (objects/ab/cdef..., named by the SHA-256 of the bytes).
//
//   ARCHIVE/index.sqlite   patients, studies, series, instances, cases, artefacts (db/*.sql)
//   ARCHIVE/objects/       original DICOM files and derived artefacts, never modified
//   ARCHIVE/store.lock     flock: importers share it, `verify --repair` takes it exclusively
//
// Invariant: every index row names an object file that exists. Objects are written (temp
// file + rename) and made durable (syncfs) BEFORE the rows naming them are committed, so a
// crash leaves at most orphan objects or temp files, which verify(Repair) removes.
// Several processes may use one archive at once (WAL, busy timeout, BEGIN IMMEDIATE retry).
// Implementation split: archive_open.cpp (open, schema), archive_import.cpp + import_batch.cpp,
// archive_queries.cpp, archive_cases.cpp, archive_artefacts.cpp, archive_verify.cpp,
// archive_export.cpp.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "archive/archive_records.h"
#include "core/error.h"
#include "core/progress.h"

namespace maxillo {

enum class ImportOutcome { Imported, AlreadyArchived, Conflict, Failed };
std::string_view to_string(ImportOutcome outcome);

// One file that was not imported: a conflict (same SOP Instance UID, other bytes) or a failure.
struct ImportProblem {
  std::filesystem::path path;
  ImportOutcome outcome = ImportOutcome::Failed;
  ErrorCode code = ErrorCode::kProcessing;
  std::string reason;  // "path: reason" is what a person reads
};

struct ImportReport {
  size_t imported = 0;
  size_t already_archived = 0;
  size_t conflicts = 0;
  size_t failed = 0;
  size_t identity_flags = 0;  // new identity flags raised by this import
  size_t restored = 0;        // already archived files whose lost object file was written again
  std::vector<ImportProblem> problems;  // in the order met
  size_t files() const { return imported + already_archived + conflicts + failed; }
  bool all_ok() const { return conflicts == 0 && failed == 0; }
};

struct ImportOptions {
  ProgressDisplay progress = ProgressDisplay::Auto;
  // Called for each problem as it is met (the CLI prints "path: reason" at once).
  std::function<void(const ImportProblem&)> on_problem;
  size_t batch_files = 500;  // files per durable batch (one syncfs + one transaction)
};

enum class RepairMode { ReportOnly, Repair };
enum class ExportProfile { Original, Deidentified };

struct VerifyReport {
  size_t objects_checked = 0;
  std::vector<std::string> missing;          // sha256 of indexed objects without a file: data loss
  std::vector<std::string> corrupt;          // sha256 whose file no longer hashes to its name
  std::vector<std::filesystem::path> orphans;       // object files no row names
  std::vector<std::filesystem::path> temporaries;   // leftovers of interrupted writes
  size_t removed = 0;                        // orphans + temporaries deleted by Repair
  bool consistent() const { return missing.empty() && corrupt.empty() && orphans.empty() && temporaries.empty(); }
  // Consistent after the repair: only what repair cannot fix remains.
  bool data_intact() const { return missing.empty() && corrupt.empty(); }
};

class Archive {
 public:
  // Opens the archive in `folder`, creating it and upgrading its schema as needed.
  // Throws Error(SchemaTooNew) when the index was written by a newer program.
  static Archive open(const std::filesystem::path& folder);
  ~Archive();
  Archive(Archive&&) noexcept;
  Archive& operator=(Archive&&) noexcept;

  const std::filesystem::path& folder() const;
  int schema_version() const;
  static int newest_schema_version();

  // --- import (files or folders, recursive) ---
  ImportReport import_paths(const std::vector<std::filesystem::path>& paths, const ImportOptions& options = {});

  // --- listing ---
  std::vector<PatientRecord> patients() const;
  std::vector<StudyRecord> studies(std::optional<int64_t> patient = std::nullopt) const;
  std::vector<SeriesRecord> series(std::optional<int64_t> study = std::nullopt) const;
  std::vector<InstanceRecord> instances(int64_t series) const;  // by instance number
  std::vector<CaseRecord> cases() const;
  std::vector<IdentityFlag> identity_flags() const;
  std::optional<PatientRecord> patient(int64_t id) const;
  std::optional<StudyRecord> study(int64_t id) const;
  std::optional<SeriesRecord> series_by_id(int64_t id) const;
  std::optional<InstanceRecord> instance(int64_t id) const;

  // What a user-given ID names: a typed archive id ("patient:3", "study:3", "series:3",
  // "instance:3", "case:3"), a bare archive id (tried as series, study, patient, case in that
  // order), a Patient ID, or a Study/Series/SOP Instance UID. Throws Error(NotFound).
  ResolvedItem resolve(std::string_view text) const;
  // A series by archive id or Series Instance UID. Throws Error(NotFound).
  int64_t resolve_series(std::string_view text) const;

  // Stored object files of a series, ordered by instance number (the volume loader reads them).
  std::vector<std::filesystem::path> series_instance_files(int64_t series) const;

  // --- cases ---
  std::optional<CaseRecord> case_of_patient(int64_t patient, std::string_view label = "default") const;
  // A case id (bare or typed "case:N"), or a Patient ID (its "default" case, else its only case).
  // Throws Error(NotFound).
  int64_t resolve_case(std::string_view text) const;
  CaseContents case_contents(int64_t case_id) const;
  // The case `label` of the patient with this Patient ID, the patient and the case created when
  // missing (idempotent): for cases without images, e.g. a follow-up cohort's landmark sets. A
  // patient made here has no name, birth date or sex (DICOM files arriving later for that Patient
  // ID therefore raise identity flags to confirm). Error(kBadValue) for an empty ID or label.
  int64_t ensure_case(std::string_view patient_id, std::string_view label);
  // Changes the role of a series in a case ("preop", "postop", "follow-up", "report", "unassigned").
  void set_series_role(int64_t case_id, int64_t series, std::string_view role);

  // --- objects and derived artefacts ---
  // Stores bytes durably; returns their sha256. Idempotent.
  std::string store_object(std::span<const std::byte> bytes);
  std::string store_object(std::string_view text);
  std::filesystem::path object_path(std::string_view sha256) const;
  std::vector<std::byte> read_object(std::string_view sha256) const;
  int64_t add_artefact(const NewArtefact& artefact);
  // The newest artefact of this case and kind made from these inputs, if any.
  std::optional<ArtefactRecord> find_artefact(int64_t case_id, std::string_view kind,
                                              std::string_view inputs_hash) const;
  std::vector<ArtefactRecord> artefacts(int64_t case_id) const;

  // --- integrity and export ---
  // Re-hashes every object. Repair removes orphan and temporary files only, never rows.
  VerifyReport verify(RepairMode mode, ProgressDisplay progress = ProgressDisplay::Auto);
  // Writes the series' files into out_dir (created), named <instance number>_<SOP UID>.dcm:
  // Original = the archived bytes; Deidentified = copies without identifying attributes, with
  // pseudonyms and new UIDs (archive/dicom_deidentify.h) keyed by deidentification_secret().
  // Returns the written paths in instance order. Throws Error(NotFound / WriteFailed / ArchiveCorrupt).
  std::vector<std::filesystem::path> export_series(int64_t series, const std::filesystem::path& out_dir,
                                                   ExportProfile profile = ExportProfile::Original) const;
  // This archive's secret for pseudonyms (ARCHIVE/deidentify.key, 256 random bits, mode 0600,
  // made on first use). The same secret gives the same pseudonyms: keep it with the archive.
  std::string deidentification_secret() const;

  struct State;  // private: connection, prepared statements, object store

 private:
  explicit Archive(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

}  // namespace maxillo
