#include "records/mesh_artefact.h"

#include "core/atomic_file.h"
#include "core/temporary_folder.h"
#include "mesh/mesh_io.h"

namespace maxillo::records {

std::string store_mesh_object(Archive& archive, const TriangleMesh& mesh) {
  TemporaryFolder scratch("maxillo-mesh");
  auto file = scratch / "mesh.ply";
  write_mesh(mesh, file);
  return archive.store_object(read_file(file));
}

void store_mesh_artefact(Archive& archive, int64_t case_id, const std::string& kind, const std::string& key,
                         const Json& parameters, const TriangleMesh& mesh) {
  archive.add_artefact(
      NewArtefact{case_id, kind, store_mesh_object(archive, mesh), "application/ply", key, parameters.dump()});
}

TriangleMesh load_mesh_artefact(const Archive& archive, const ArtefactRecord& artefact) {
  // Objects carry no extension; the mesh reader chooses the format by extension.
  TemporaryFolder scratch("maxillo-mesh");
  auto link = scratch / "mesh.ply";
  std::filesystem::create_symlink(std::filesystem::absolute(archive.object_path(artefact.object_sha256)), link);
  return read_mesh(link);
}

}  // namespace maxillo::records
