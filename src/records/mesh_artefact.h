#pragma once
// Surfaces stored in the archive as artefacts (binary PLY objects: unlike STL, PLY keeps the
// vertex sharing, so a manifold surface stays manifold when read back).
#include <cstdint>
#include <string>

#include "archive/archive.h"
#include "core/json.h"
#include "core/triangle_mesh.h"

namespace maxillo::records {

// Stores `mesh` as a PLY object (content-addressed: the same mesh is the same object); its SHA-256.
std::string store_mesh_object(Archive& archive, const TriangleMesh& mesh);

// Stores `mesh` as a PLY object and records it as an artefact of the case.
void store_mesh_artefact(Archive& archive, int64_t case_id, const std::string& kind, const std::string& key,
                         const Json& parameters, const TriangleMesh& mesh);

// The mesh of an artefact previously stored with store_mesh_artefact.
TriangleMesh load_mesh_artefact(const Archive& archive, const ArtefactRecord& artefact);

}  // namespace maxillo::records
