#include "softtissue/vtu_writer.h"

#include <cassert>
#include <sstream>

#include "core/atomic_file.h"

namespace maxillo::softtissue {

void write_vtu(const std::filesystem::path& path, const TetMesh& mesh, const Eigen::MatrixX3d& displacement,
               const BoundaryConditions& bc) {
  assert(displacement.rows() == mesh.node_count() && bc.node_count() == mesh.node_count() &&
         "write_vtu: arrays and mesh differ in node count");
  constexpr int kVtkTetra = 10;
  std::ostringstream out;
  out.precision(10);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      << "<UnstructuredGrid>\n"
      << "<Piece NumberOfPoints=\"" << mesh.node_count() << "\" NumberOfCells=\"" << mesh.tet_count() << "\">\n"
      << "<PointData Vectors=\"displacement\" Scalars=\"bc\">\n"
      << "<DataArray type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (int i = 0; i < mesh.node_count(); ++i)
    out << displacement(i, 0) << ' ' << displacement(i, 1) << ' ' << displacement(i, 2) << '\n';
  out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"bc\" format=\"ascii\">\n";
  for (int i = 0; i < mesh.node_count(); ++i) out << int(bc.constraint[size_t(i)]) << '\n';
  out << "</DataArray>\n</PointData>\n<Points>\n"
      << "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (int i = 0; i < mesh.node_count(); ++i)
    out << mesh.nodes(i, 0) << ' ' << mesh.nodes(i, 1) << ' ' << mesh.nodes(i, 2) << '\n';
  out << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (int t = 0; t < mesh.tet_count(); ++t)
    out << mesh.tets(t, 0) << ' ' << mesh.tets(t, 1) << ' ' << mesh.tets(t, 2) << ' ' << mesh.tets(t, 3) << '\n';
  out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (int t = 0; t < mesh.tet_count(); ++t) out << 4 * (t + 1) << '\n';
  out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (int t = 0; t < mesh.tet_count(); ++t) out << kVtkTetra << '\n';
  out << "</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  write_file_atomically(path, out.str(), Durability::Unflushed);
}

}  // namespace maxillo::softtissue
