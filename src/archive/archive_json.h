#pragma once
// Stable --json shapes of the archive's records (keys are part of the CLI contract).
#include "archive/archive.h"
#include "core/json.h"

namespace maxillo {

Json to_json(const PatientRecord& record);
Json to_json(const StudyRecord& record);
Json to_json(const SeriesRecord& record);
Json to_json(const InstanceRecord& record);
Json to_json(const CaseRecord& record);
Json to_json(const IdentityFlag& record);
Json to_json(const ArtefactRecord& record);
Json to_json(const CaseContents& contents);
Json to_json(const ImportProblem& problem);
Json to_json(const ImportReport& report);
Json to_json(const VerifyReport& report);
Json to_json(const RebuildReport& report);
Json to_json(const MigrationReport& report);

}  // namespace maxillo
