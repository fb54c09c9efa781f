#include "records/dental_scans.h"

#include <algorithm>

#include "archive/artefact_kind.h"
#include "core/error.h"
#include "occlusion/occlusion_files.h"
#include "records/mesh_artefact.h"
#include "records/stored_artefact.h"

namespace maxillo::records {
namespace {

std::optional<DentalArch> parse_arch(std::string_view name) {
  for (DentalArch arch : kBothArches)
    if (name_of(arch) == name) return arch;
  return std::nullopt;
}

// The arch named in an artefact's parameters; nullopt for another kind or damaged parameters.
std::optional<DentalArch> arch_of(const ArtefactRecord& artefact) {
  const Json parameters = Json::parse(artefact.parameters_json, nullptr, false);
  if (parameters.is_discarded() || !parameters.is_object() || !parameters.contains("arch")) return std::nullopt;
  return parse_arch(parameters["arch"].get<std::string>());
}

StoredDentalScan stored_scan(const ArtefactRecord& artefact, DentalArch arch, int version) {
  const Json parameters = Json::parse(artefact.parameters_json, nullptr, false);
  StoredDentalScan scan;
  scan.artefact_id = artefact.id;
  scan.arch = arch;
  scan.source = parameters.value("source", "");
  scan.object_sha256 = artefact.object_sha256;
  scan.created_at = artefact.created_at;
  scan.version = version;
  scan.warnings = parameters.value("warnings", std::vector<std::string>{});
  return scan;
}

double number(const Json& json, const char* key, const std::string& subject) {
  if (!json.contains(key) || !json[key].is_number())
    throw Error(ErrorCode::kArchiveCorrupt, subject, std::string("its dental registration has no number ") + key);
  return json[key].get<double>();
}

}  // namespace

std::string_view name_of(DentalArch arch) { return arch == DentalArch::kUpper ? "upper" : "lower"; }

StoredDentalScan store_dental_scan(Archive& archive, int64_t case_id, DentalArch arch, const TriangleMesh& scan,
                                   const std::string& source, const std::vector<std::string>& warnings) {
  const Json parameters{
      {"arch", name_of(arch)}, {"source", source}, {"triangles", scan.face_count()}, {"warnings", warnings}};
  const std::string sha = store_mesh_object(archive, scan);
  if (auto newest = latest_dental_scan(archive, case_id, arch); newest && newest->object_sha256 == sha) {
    newest->already_stored = true;
    return *newest;
  }
  archive.add_artefact(
      NewArtefact{case_id, kind_name(ArtefactKind::kDentalScan), sha, "application/ply", "", parameters.dump()});
  return *latest_dental_scan(archive, case_id, arch);
}

std::vector<StoredDentalScan> dental_scan_history(const Archive& archive, int64_t case_id, DentalArch arch) {
  std::vector<StoredDentalScan> history;
  for (const ArtefactRecord& artefact : archive.artefacts(case_id))  // by id: oldest first
    if (artefact.kind == kind_name(ArtefactKind::kDentalScan) && arch_of(artefact) == arch)
      history.push_back(stored_scan(artefact, arch, int(history.size()) + 1));
  return history;
}

std::optional<StoredDentalScan> latest_dental_scan(const Archive& archive, int64_t case_id, DentalArch arch) {
  auto history = dental_scan_history(archive, case_id, arch);
  if (history.empty()) return std::nullopt;
  return history.back();
}

TriangleMesh load_dental_scan(const Archive& archive, const StoredDentalScan& scan) {
  ArtefactRecord artefact;
  artefact.id = scan.artefact_id;
  artefact.object_sha256 = scan.object_sha256;
  return load_mesh_artefact(archive, artefact);
}

Json to_json(const DentalRegistrationRecord& r) {
  return Json{{"arch", name_of(r.arch)},
              {"scan_artefact", r.scan_artefact_id},
              {"series", r.series_id},
              {"scan_to_ct", occlusion::transform_to_json(r.scan_to_ct)},
              {"on_teeth_share", r.on_teeth_share},
              {"rms_mm", r.rms_mm},
              {"p95_mm", r.p95_mm},
              {"within_0_3_share", r.within_0_3_share},
              {"confidence", r.confidence},
              {"start", r.start},
              {"seconds", r.seconds}};
}

DentalRegistrationRecord read_dental_registration(const Json& json, const std::string& subject) {
  if (!json.is_object() || !json.contains("arch") || !json["arch"].is_string() ||
      !parse_arch(json["arch"].get<std::string>()))
    throw Error(ErrorCode::kArchiveCorrupt, subject, "not a dental registration (no arch \"upper\" or \"lower\")");
  DentalRegistrationRecord r;
  r.arch = *parse_arch(json["arch"].get<std::string>());
  r.scan_artefact_id = int64_t(number(json, "scan_artefact", subject));
  r.series_id = int64_t(number(json, "series", subject));
  if (!json.contains("scan_to_ct"))
    throw Error(ErrorCode::kArchiveCorrupt, subject, "its dental registration has no pose");
  r.scan_to_ct = occlusion::transform_from_json(json["scan_to_ct"], subject);
  r.on_teeth_share = number(json, "on_teeth_share", subject);
  r.rms_mm = number(json, "rms_mm", subject);
  r.p95_mm = number(json, "p95_mm", subject);
  r.within_0_3_share = number(json, "within_0_3_share", subject);
  r.confidence = number(json, "confidence", subject);
  r.start = json.value("start", "");
  r.seconds = json.value("seconds", 0.0);
  return r;
}

void store_dental_registration(Archive& archive, int64_t case_id, const DentalRegistrationRecord& record,
                               const std::string& key) {
  const std::string sha = archive.store_object(json_text(to_json(record)) + "\n");
  archive.add_artefact(NewArtefact{case_id, kind_name(ArtefactKind::kDentalRegistration), sha, "application/json", key,
                                   Json{{"arch", name_of(record.arch)}}.dump()});
}

std::optional<StoredDentalRegistration> current_dental_registration(const Archive& archive, int64_t case_id,
                                                                    DentalArch arch) {
  const auto scan = latest_dental_scan(archive, case_id, arch);
  if (!scan) return std::nullopt;
  const auto artefacts = archive.artefacts(case_id);
  for (auto it = artefacts.rbegin(); it != artefacts.rend(); ++it) {  // newest first
    if (it->kind != kind_name(ArtefactKind::kDentalRegistration) || arch_of(*it) != arch) continue;
    StoredDentalRegistration stored{read_dental_registration(artefact_json(archive, *it), artefact_source(*it)),
                                    it->inputs_hash, artefact_source(*it)};
    if (stored.record.scan_artefact_id == scan->artefact_id) return stored;
  }
  return std::nullopt;
}

std::optional<TriangleMesh> current_augmented_dentition(const Archive& archive, int64_t case_id, DentalArch arch) {
  const auto registration = current_dental_registration(archive, case_id, arch);
  if (!registration) return std::nullopt;
  const auto artefacts = archive.artefacts(case_id);
  const ArtefactRecord* model = newest_with_key(artefacts, ArtefactKind::kAugmentedDentition, registration->key);
  if (!model) return std::nullopt;
  return load_mesh_artefact(archive, *model);
}

std::string fit_picture_name(DentalArch arch) { return "dental-fit-" + std::string(name_of(arch)); }

CaseDentalScans case_dental_scans(const Archive& archive, int64_t case_id) {
  CaseDentalScans out;
  std::vector<CaseDentalArch>& arches = out.arches;
  const auto artefacts = archive.artefacts(case_id);
  for (DentalArch arch : kBothArches) {
    const auto scan = latest_dental_scan(archive, case_id, arch);
    if (!scan) continue;
    CaseDentalArch entry{*scan, current_dental_registration(archive, case_id, arch), std::nullopt};
    if (entry.registration)
      if (const ArtefactRecord* picture =
              newest_with_key(artefacts, ArtefactKind::kDentalRender, entry.registration->key, fit_picture_name(arch)))
        entry.fit_picture = archive.object_path(picture->object_sha256);
    arches.push_back(std::move(entry));
  }
  // The augmented model's pictures of the newest registration run that made them.
  for (const char* name : {"augmented-frontal", "augmented-lateral"}) {
    const ArtefactRecord* newest = nullptr;
    for (const ArtefactRecord& a : artefacts)
      if (a.kind == kind_name(ArtefactKind::kDentalRender) && picture_name(a) == name) newest = &a;
    if (newest && !arches.empty()) out.augmented_pictures.push_back(archive.object_path(newest->object_sha256));
  }
  return out;
}

}  // namespace maxillo::records
