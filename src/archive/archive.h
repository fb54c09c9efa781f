#pragma once
// The case archive: a folder holding an SQLite index (index.sqlite) and a content-addressed
// object store (objects/ab/cdef..., named by the SHA-256 of the bytes); or, at a clinic's or a
// research group's scale, the index on a PostgreSQL server and the objects in a folder every
// node shares (archive_location.h). The archive's interface and semantics are the same on both.
//
//   ARCHIVE/index.sqlite   patients, studies, series, instances, cases, artefacts (db/*.sql)
//   ARCHIVE/objects/       original DICOM files and derived artefacts, never modified
//   ARCHIVE/store.lock     flock: importers share it, `verify --repair` takes it exclusively
//
// Invariant: every index row names an object file that exists. Objects are written (temp
// file + rename) and made durable (fdatasync or syncfs) BEFORE the rows naming them are
// committed, so a crash leaves at most orphan objects or temp files, which verify(Repair) removes.
// Several processes may use one archive at once (SQLite: WAL, busy timeout, BEGIN IMMEDIATE
// retry, one writer at a time; PostgreSQL: row locks, writers side by side).
// Implementation split: archive_open.cpp (open, schema), archive_import.cpp + import_batch.cpp,
// archive_queries.cpp, archive_cases.cpp, archive_artefacts.cpp, archive_verify.cpp,
// archive_export.cpp. The work queue the nightly workers share is a type of its
// own on the archive's index (work_queue.h).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <set>
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
  size_t identity_flags = 0;            // new identity flags raised by this import
  size_t restored = 0;                  // already archived files whose lost or damaged object file was written again
  std::vector<ImportProblem> problems;  // in the order met
  std::set<int64_t> cases_with_new_images;  // the (default) cases of the patients new instances went to
  size_t files() const { return imported + already_archived + conflicts + failed; }
  bool all_ok() const { return conflicts == 0 && failed == 0; }
};

struct ImportOptions {
  ProgressDisplay progress = ProgressDisplay::Auto;
  // Called for each problem as it is met (the CLI prints "path: reason" at once).
  std::function<void(const ImportProblem&)> on_problem{};
  // Called for each file that ends in the archive, once durable: Imported, or AlreadyArchived
  // (the same bytes were archived before). The others go to on_problem.
  std::function<void(const std::filesystem::path&, ImportOutcome)> on_archived{};
  size_t batch_files = 500;  // files per durable batch (one sync + one transaction)
  // Recorded as each new instance's source instead of its file's path, for files that are only
  // a spool: network_source(AE, ADDRESS) for what `maxillo serve` received (instance_source.h).
  std::string source_label{};
};

enum class RepairMode { ReportOnly, Repair };
enum class ExportProfile { Original, Deidentified };

struct VerifyOptions {
  RepairMode mode = RepairMode::ReportOnly;
  // Quarantine orphans even when they are more than a small share of the store (see verify).
  bool force = false;
  ProgressDisplay progress = ProgressDisplay::Auto;
  // Orphans and temporaries younger than this are reported but left in place by Repair: on
  // shared storage a file another node is writing may be seen before its row. Negative: the
  // archive's default, kServerOrphanGraceSeconds on a server archive, 0 on an embedded one
  // (the store lock is all an embedded archive needs).
  int64_t grace_seconds = -1;
};
inline constexpr int64_t kServerOrphanGraceSeconds = 600;

struct VerifyReport {
  std::string index_check = "ok";                // SQLite integrity_check's first finding
  std::vector<std::string> journal_differences;  // where the index and its journal disagree
  // Why the index could not be compared with its journal (nothing is known damaged then).
  std::string journal_check_failure;
  size_t objects_checked = 0;
  std::vector<std::string> missing;  // sha256 of indexed objects without a file: data loss
  std::vector<std::string> corrupt;  // sha256 whose file no longer hashes to its name
  // What names each missing or corrupt object: "case:3 series:5 instance:12", "case:3 artefact:7 (report)".
  std::map<std::string, std::vector<std::string>> owners;
  // What interrupted writes leave (a kill -9 or a full disk between an object's write and the
  // commit of its rows): object files no row names, and temporary files. Harmless while they
  // are few (see leftovers_are_few): the next import of the same files adopts the objects,
  // `verify --repair` adopts the DICOM ones and quarantines the rest.
  std::vector<std::filesystem::path> orphans;      // object files no row names
  std::vector<std::filesystem::path> temporaries;  // temporary files of interrupted writes
  std::vector<std::filesystem::path> adopted;      // orphan DICOM objects Repair indexed from their headers
  size_t quarantined = 0;                          // orphans + temporaries moved into quarantine by Repair
  size_t within_grace = 0;                         // orphans + temporaries Repair left: younger than the grace period
  std::vector<std::string> restored;               // missing objects Repair found in quarantine and put back
  std::string repair_refused;                      // why Repair changed nothing, when it refused
  bool index_intact() const { return index_check == "ok" && journal_differences.empty(); }
  // Orphans beyond 5 % of the store (and at least 10) are not what interrupted writes leave (an
  // import batch is 500 files, a store thousands): a lost or older index, or a large import
  // stopped half-way. Temporaries are always what an interrupted write left: verify holds the
  // store alone, so no writer is busy with one.
  bool leftovers_are_few() const;
  // Nothing damaged or lost, and no more leftovers than interrupted writes leave.
  bool consistent() const {
    return index_intact() && journal_check_failure.empty() && missing.empty() && corrupt.empty() && leftovers_are_few();
  }
  // Consistent after the repair: only what repair cannot fix remains.
  bool data_intact() const {
    return index_intact() && journal_check_failure.empty() && missing.empty() && corrupt.empty();
  }
};

struct RebuildOptions {
  bool force = false;  // rebuild even an intact index (it is kept beside the new one)
  ProgressDisplay progress = ProgressDisplay::Auto;
};

struct RebuildReport {
  size_t journal_entries = 0;                      // entries replayed
  std::vector<std::string> journal_problems;       // entries missing or unreadable (skipped)
  size_t restored_from_quarantine = 0;             // objects rows name, found in quarantine and put back
  size_t instances_checked = 0;                    // instance rows whose DICOM object was re-parsed
  size_t instances_without_object = 0;             // instance rows whose object file is missing
  std::vector<std::string> disagreements;          // instance rows their object contradicts
  size_t dicom_adopted = 0;                        // DICOM objects no journal entry named, indexed anew
  std::vector<std::filesystem::path> unexplained;  // objects neither named by a row nor DICOM
  std::filesystem::path previous_index;            // where the replaced index was kept (empty if none)
  std::map<std::string, int64_t> rows;             // rows per table in the rebuilt index
};

struct MigrationOptions {
  ProgressDisplay progress = ProgressDisplay::Auto;
};

struct MigrationReport {
  size_t objects_copied = 0;                 // written into the target's store
  size_t objects_present = 0;                // already there, intact (a resumed migration)
  std::vector<std::string> damaged_sources;  // source objects that no longer hash to their name (not copied)
  size_t journal_entries = 0;                // entries copied and replayed
  std::vector<std::string> journal_problems;
  std::map<std::string, int64_t> rows;  // rows per table in the target index
  // Row-by-row comparison of the source index with the target's: empty when they agree.
  std::vector<std::string> differences;
  bool verified() const { return damaged_sources.empty() && journal_problems.empty() && differences.empty(); }
};

// Existing: the archive must be there (Error kNotFound otherwise). CreateIfMissing: a missing
// folder becomes a new, empty archive (import and the demo create archives; nothing else does).
// MigrationTarget: CreateIfMissing for `archive migrate`, which alone may open an archive that
// an unfinished migration is filling (every other opening refuses it, archive_health.h).
enum class OpenMode { Existing, CreateIfMissing, MigrationTarget };

class Archive {
 public:
  // ==== Opening, and what the archive is ====
  // Opens the archive in `folder` and upgrades its schema as needed. Refuses, with
  // Error(kIndexDamaged) and how to recover, an index that is missing or empty while objects
  // exist, damaged (SQLite quick_check), or behind its journal (archive_health.h).
  // Throws Error(SchemaTooNew) when the index was written by a newer program.
  static Archive open(const std::filesystem::path& folder, OpenMode mode = OpenMode::Existing);
  ~Archive();
  Archive(Archive&&) noexcept;
  Archive& operator=(Archive&&) noexcept;

  // The archive's folder; for an archive on a server, its shared object folder.
  const std::filesystem::path& folder() const;
  // What open() was given: another connection (a thread, a child process) opens this.
  const std::filesystem::path& address() const;
  // False for an archive whose index is on a PostgreSQL server.
  bool embedded() const;
  int schema_version() const;
  static int newest_schema_version();

  // ==== The store: DICOM files in, objects by their hash, series out ====
  // What the object store holds and how files enter and leave it; every object is named by its
  // SHA-256 and never modified.

  // Imports files or folders (recursive).
  ImportReport import_paths(const std::vector<std::filesystem::path>& paths, const ImportOptions& options = {});

  // Stores bytes durably; returns their sha256. Idempotent.
  std::string store_object(std::span<const std::byte> bytes);
  std::string store_object(std::string_view text);
  std::filesystem::path object_path(std::string_view sha256) const;
  std::vector<std::byte> read_object(std::string_view sha256) const;

  // Writes the series' files into out_dir (created), named <instance number>_<SOP UID>.dcm:
  // Original = the archived bytes; Deidentified = copies without identifying attributes, with
  // pseudonyms and new UIDs (dicom/dicom_deidentify.h) keyed by deidentification_secret().
  // Returns the written paths in instance order. Throws Error(NotFound / WriteFailed / ArchiveCorrupt).
  std::vector<std::filesystem::path> export_series(int64_t series, const std::filesystem::path& out_dir,
                                                   ExportProfile profile = ExportProfile::Original) const;
  // This archive's secret for pseudonyms (ARCHIVE/deidentify.key, 256 random bits, mode 0600,
  // made on first use). The same secret gives the same pseudonyms: keep it with the archive.
  std::string deidentification_secret() const;

  // ==== Index queries: patients, studies, series, instances and cases ====
  // What the index says of the images and the cases they belong to, and the two edits of a case.

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
  // Their sha256 names, in the same order, read from the index alone (what a series' content
  // hash is made of; the nightly scan computes it for every case).
  std::vector<std::string> series_object_hashes(int64_t series) const;
  // The same for many series in a few queries: series id -> hashes.
  std::map<int64_t, std::vector<std::string>> series_object_hashes(const std::vector<int64_t>& series) const;

  // The patient's case of this label, if any.
  std::optional<CaseRecord> case_of_patient(int64_t patient, std::string_view label = "default") const;
  // A case id (bare or typed "case:N"), or a Patient ID (its "default" case, else its only case).
  // Throws Error(NotFound).
  int64_t resolve_case(std::string_view text) const;
  CaseContents case_contents(int64_t case_id) const;  // Error(kNotFound) when there is no such case
  // The same for many cases in a few queries (the nightly scan reads every case's): case id ->
  // contents; ids with no case are left out.
  std::map<int64_t, CaseContents> case_contents(const std::vector<int64_t>& case_ids) const;
  // The case `label` of the patient with this Patient ID, the patient and the case created when
  // missing (idempotent): for cases without images, e.g. a follow-up cohort's landmark sets. A
  // patient made here has no name, birth date or sex (DICOM files arriving later for that Patient
  // ID therefore raise identity flags to confirm). Error(kBadValue) for an empty ID or label.
  int64_t ensure_case(std::string_view patient_id, std::string_view label);
  // Changes the role of a series in a case ("preop", "postop", "follow-up", "report", "unassigned").
  void set_series_role(int64_t case_id, int64_t series, std::string_view role);

  // ==== Derived artefacts ====
  // What the workflows made from a case's images (surfaces, plans, predictions, reports), kept
  // as objects, each keyed by the hash of its inputs.

  int64_t add_artefact(const NewArtefact& artefact);
  // The newest artefact of this case and kind made from these inputs, if any.
  std::optional<ArtefactRecord> find_artefact(int64_t case_id, std::string_view kind,
                                              std::string_view inputs_hash) const;
  std::vector<ArtefactRecord> artefacts(int64_t case_id) const;  // by id
  // The same for many cases in a few queries: case id -> artefacts (empty for a case without).
  std::map<int64_t, std::vector<ArtefactRecord>> artefacts(const std::vector<int64_t>& case_ids) const;

  // ==== Health: verify and repair, rebuild the index, migrate ====
  // Whether every row's object is there and intact, and the ways back when it is not.

  // Checks the index (SQLite integrity_check, and a replay of its journal compared row by row)
  // and re-hashes every object. Repair never deletes: it moves orphan and temporary files into
  // the quarantine (object_store.h) and puts back quarantined objects that rows name. It refuses,
  // changing nothing (report.repair_refused says why), when the index is damaged or disagrees
  // with its journal, or when orphans are more than 5 % of the store (and at least 10) unless
  // options.force: that many unindexed objects mean a lost or old index, not interrupted writes.
  VerifyReport verify(const VerifyOptions& options);
  VerifyReport verify(RepairMode mode, ProgressDisplay progress = ProgressDisplay::Auto) {
    return verify(VerifyOptions{mode, false, progress});
  }
  // Deletes the quarantine (what `verify --repair` set aside); returns the files deleted.
  size_t purge_quarantine();

  // Re-creates ARCHIVE/index.sqlite from the object store alone: the journal is replayed (every
  // row the index ever committed, ids included), every instance row is checked against its
  // re-parsed DICOM object, and DICOM objects no entry names (archives older than the journal,
  // a lost journal entry) are indexed anew from their own headers. The old index, if any, is
  // kept as index.sqlite.damaged-<time> (or .replaced-<time> with force), never deleted.
  // Refuses (Error kConflict) an intact index unless options.force. A server archive's index
  // is rebuilt the same way into the new, empty database its address names (never over a
  // database that holds an index, forced or not).
  static RebuildReport rebuild_index(const std::filesystem::path& folder, const RebuildOptions& options = {});

  // Copies the embedded archive in `source` into the archive at `target` (typically a
  // PostgreSQL index with its shared object folder): every object, re-hashed as it is copied,
  // and the index journal, which is then replayed into the target index, so rows and ids are
  // the source's. Verified by comparing both indexes row by row. Idempotent and resumable: a
  // run killed half-way is run again. The source is only read. Refuses (kConflict) a target
  // that already holds another history, and a source whose index is not the newest schema.
  static MigrationReport migrate(const std::filesystem::path& source, const std::filesystem::path& target,
                                 const MigrationOptions& options = {});

  struct State;  // private: connection, prepared statements, object store

 private:
  friend class WorkQueue;  // works on the index's connection (archive/work_queue.h)
  explicit Archive(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

}  // namespace maxillo
