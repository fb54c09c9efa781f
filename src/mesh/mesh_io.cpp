// Mesh file I/O with VTK's readers and writers; errors are collected from VTK's error events.
#include "mesh/mesh_io.h"

#include <vtkOBJReader.h>
#include <vtkOBJWriter.h>
#include <vtkDoubleArray.h>
#include <vtkLogger.h>
#include <vtkPointData.h>
#include <vtkOutputWindow.h>
#include <vtkPLYWriter.h>
#include <vtkSTLWriter.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cctype>
#include <optional>
#include <system_error>

#include "core/atomic_file.h"
#include "core/error.h"
#include "mesh/ply_file.h"
#include "mesh/stl_file.h"
#include "mesh/vtk_bridge.h"

namespace maxillo {
namespace {

template <typename Writer>
void run_writer(Writer* writer, vtkPolyData* polydata, const std::filesystem::path& path) {
  vtkNew<vtk_bridge::ErrorCollector> errors;
  errors->observe(writer);
  writer->SetInputData(polydata);
  writer->SetFileName(path.c_str());
  int ok = writer->Write();
  if (!ok || errors->failed())
    throw Error(ErrorCode::kWriteFailed, path.string(), errors->failed() ? errors->errors : "VTK writer failed");
}

void write_as(MeshFormat format, vtkPolyData* polydata, const std::filesystem::path& path) {
  switch (format) {
    case MeshFormat::Stl: {
      vtkNew<vtkSTLWriter> writer;
      writer->SetFileTypeToBinary();
      return run_writer(writer.Get(), polydata, path);
    }
    case MeshFormat::Ply: {
      vtkNew<vtkPLYWriter> writer;
      writer->SetFileTypeToBinary();
      writer->SetDataByteOrderToLittleEndian();
      return run_writer(writer.Get(), polydata, path);
    }
    case MeshFormat::Obj: {
      vtkNew<vtkOBJWriter> writer;
      return run_writer(writer.Get(), polydata, path);
    }
    case MeshFormat::Vtp: {
      vtkNew<vtkXMLPolyDataWriter> writer;
      writer->SetDataModeToBinary();
      return run_writer(writer.Get(), polydata, path);
    }
  }
}

// Keeps VTK from printing errors of objects we cannot observe (e.g. the XML parser inside a
// reader) while a read runs; the reader's own errors still reach our ErrorCollector.
class QuietVtkOutput {
 public:
  QuietVtkOutput()
      : window_(vtkOutputWindow::GetInstance()),
        mode_(window_->GetDisplayMode()),
        verbosity_(vtkLogger::GetCurrentVerbosityCutoff()) {
    window_->SetDisplayModeToNever();
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
  ~QuietVtkOutput() {
    window_->SetDisplayMode(mode_);
    vtkLogger::SetStderrVerbosity(verbosity_);
  }
  QuietVtkOutput(const QuietVtkOutput&) = delete;
  QuietVtkOutput& operator=(const QuietVtkOutput&) = delete;

 private:
  vtkOutputWindow* window_;
  int mode_;
  vtkLogger::Verbosity verbosity_;
};

template <typename Reader>
TriangleMesh run_reader(const std::filesystem::path& path) {
  QuietVtkOutput quiet;
  vtkNew<Reader> reader;
  vtkNew<vtk_bridge::ErrorCollector> errors;
  errors->observe(reader);
  reader->SetFileName(path.c_str());
  reader->Update();
  if (errors->failed()) throw Error(ErrorCode::kBadValue, path.string(), errors->errors);
  TriangleMesh mesh = vtk_bridge::from_polydata(reader->GetOutput());
  if (mesh.face_count() == 0) throw Error(ErrorCode::kBadValue, path.string(), "no triangles in the file");
  if (!mesh.vertices.allFinite())
    throw Error(ErrorCode::kBadValue, path.string(), "vertex coordinates that are not finite numbers");
  return mesh;
}

// Our own parsers for the formats that come from outside (scanners, other planning tools):
// VTK's accept garbage (STL) or crash on it (PLY). Both are checked the same way afterwards.
TriangleMesh read_with(TriangleMesh (*parse)(std::span<const std::byte>, const std::string&),
                       const std::filesystem::path& path) {
  TriangleMesh mesh = parse(read_file(path), path.string());
  if (mesh.face_count() == 0) throw Error(ErrorCode::kBadValue, path.string(), "no triangles in the file");
  return mesh;
}

}  // namespace

namespace {

std::string lower_case_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return extension;
}

std::optional<MeshFormat> known_format(const std::filesystem::path& path) {
  const std::string extension = lower_case_extension(path);
  if (extension == ".stl") return MeshFormat::Stl;
  if (extension == ".ply") return MeshFormat::Ply;
  if (extension == ".obj") return MeshFormat::Obj;
  if (extension == ".vtp") return MeshFormat::Vtp;
  return std::nullopt;
}

}  // namespace

MeshFormat mesh_format_for(const std::filesystem::path& path) {
  if (const auto format = known_format(path)) return *format;
  throw Error(ErrorCode::kUsage, path.string(),
              "unknown mesh extension '" + lower_case_extension(path) + "' (known: .stl, .ply, .obj, .vtp)");
}

void write_mesh(const TriangleMesh& mesh, const std::filesystem::path& path) { write_mesh(mesh, path, {}); }

void write_mesh(const TriangleMesh& mesh, const std::filesystem::path& path, const std::vector<PointArray>& arrays) {
  const MeshFormat format = mesh_format_for(path);
  vtkSmartPointer<vtkPolyData> polydata = vtk_bridge::to_polydata(mesh);
  for (const auto& array : arrays) {
    if (array.values.rows() != mesh.vertex_count())
      throw Error(ErrorCode::kBadValue, path.string(), "point array '" + array.name + "' has the wrong length");
    vtkNew<vtkDoubleArray> data;
    data->SetName(array.name.c_str());
    data->SetNumberOfComponents(int(array.values.cols()));
    data->SetNumberOfTuples(array.values.rows());
    for (Eigen::Index v = 0; v < array.values.rows(); ++v)
      for (Eigen::Index c = 0; c < array.values.cols(); ++c) data->SetComponent(v, int(c), array.values(v, c));
    polydata->GetPointData()->AddArray(data);
  }
  // The temporary keeps the extension: vtkPLYWriter appends ".ply" to names without it.
  std::filesystem::path temporary = temporary_sibling(path);
  temporary += path.extension();
  try {
    write_as(format, polydata, temporary);
  } catch (const Error& e) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw Error(ErrorCode::kWriteFailed, path.string(), e.reason());
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw Error(ErrorCode::kWriteFailed, path.string(), "cannot rename the temporary file: " + error.message());
  }
}

TriangleMesh read_mesh(const std::filesystem::path& path) {
  const MeshFormat format = mesh_format_for(path);
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw Error(ErrorCode::kFileNotFound, path.string(), "no such file");
  switch (format) {
    case MeshFormat::Stl: return read_with(parse_stl, path);
    case MeshFormat::Ply: return read_with(parse_ply, path);
    case MeshFormat::Obj: return run_reader<vtkOBJReader>(path);
    case MeshFormat::Vtp: return run_reader<vtkXMLPolyDataReader>(path);
  }
  return {};
}

}  // namespace maxillo

namespace maxillo {

std::vector<TriangleMesh> read_meshes_in(const std::filesystem::path& folder) {
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error))
    throw Error(ErrorCode::kFileNotFound, folder.string(), "no such folder");
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.is_regular_file() && known_format(entry.path())) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  std::vector<TriangleMesh> meshes;
  for (const auto& file : files) meshes.push_back(read_mesh(file));
  return meshes;
}

}  // namespace maxillo
