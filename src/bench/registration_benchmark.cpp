// The registration benchmark's pieces (see registration_benchmark.h).
#include "bench/registration_benchmark.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/temporary_folder.h"
#include "imaging/segmentation.h"
#include "imaging/volume_file.h"
#include "mesh/surface_extraction.h"

namespace maxillo::bench {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string quoted(const std::filesystem::path& path) {
  std::string text = "'";
  for (char c : path.string()) text += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return text + "'";
}

// MetaImage header + raw little-endian voxels. TransformMatrix lists the i, j and k axis vectors
// one after the other (the columns of the direction matrix), as ITK's MetaImageIO reads them.
void write_metaimage(const std::filesystem::path& header, const VolumeGeometry& g, const char* element_type,
                     const void* voxels, size_t bytes) {
  const std::filesystem::path raw = std::filesystem::path(header).replace_extension(".raw");
  std::ofstream out(header);
  out << "ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\nCompressedData = False\n";
  out << "TransformMatrix =";
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) out << ' ' << g.direction(r, c);
  out << "\nOffset = " << g.origin.x() << ' ' << g.origin.y() << ' ' << g.origin.z() << "\n";
  out << "ElementSpacing = " << g.spacing.x() << ' ' << g.spacing.y() << ' ' << g.spacing.z() << "\n";
  out << "DimSize = " << g.size.x() << ' ' << g.size.y() << ' ' << g.size.z() << "\n";
  out << "ElementType = " << element_type << "\nElementDataFile = " << raw.filename().string() << "\n";
  std::ofstream data(raw, std::ios::binary);
  data.write(static_cast<const char*>(voxels), std::streamsize(bytes));
  if (!out || !data) throw Error(ErrorCode::kWriteFailed, header.string(), "cannot write the MetaImage for elastix");
}

void write_elastix_parameters(const std::filesystem::path& file) {
  std::ofstream(file) << R"((FixedInternalImagePixelType "float")
(MovingInternalImagePixelType "float")
(FixedImageDimension 3)
(MovingImageDimension 3)
(UseDirectionCosines "true")
(Registration "MultiResolutionRegistration")
(Interpolator "BSplineInterpolator")
(BSplineInterpolationOrder 1)
(ResampleInterpolator "FinalBSplineInterpolator")
(FinalBSplineInterpolationOrder 3)
(Resampler "DefaultResampler")
(FixedImagePyramid "FixedRecursiveImagePyramid")
(MovingImagePyramid "MovingRecursiveImagePyramid")
(NumberOfResolutions 3)
(ImagePyramidSchedule 4 4 4 2 2 2 1 1 1)
(Optimizer "AdaptiveStochasticGradientDescent")
(Transform "EulerTransform")
(Metric "AdvancedMattesMutualInformation")
(NumberOfHistogramBins 32)
(AutomaticScalesEstimation "true")
(AutomaticTransformInitialization "true")
(AutomaticTransformInitializationMethod "GeometricalCenter")
(HowToCombineTransforms "Compose")
(ErodeMask "false")
(MaximumNumberOfIterations 250)
(ImageSampler "RandomCoordinate")
(NumberOfSpatialSamples 2048)
(NewSamplesEveryIteration "true")
(CheckNumberOfSamples "true")
(DefaultPixelValue -1000)
(WriteResultImage "false")
(ResultImageFormat "mhd")
)";
}

// The values after `(name` in an elastix parameter file, as text.
std::vector<std::string> parameter_values(const std::string& text, const std::string& name,
                                          const std::filesystem::path& file) {
  const std::regex pattern("\\(" + name + "\\s+([^)]*)\\)");
  std::smatch match;
  if (!std::regex_search(text, match, pattern))
    throw Error(ErrorCode::kBadValue, file.string(), "no (" + name + " ...) in the elastix transform");
  std::istringstream in(match[1].str());
  std::vector<std::string> values;
  for (std::string value; in >> value;) {
    if (value.size() >= 2 && value.front() == '"') value = value.substr(1, value.size() - 2);
    values.push_back(value);
  }
  return values;
}

std::vector<double> numbers(const std::vector<std::string>& values, size_t expected,
                            const std::filesystem::path& file) {
  if (values.size() != expected)
    throw Error(ErrorCode::kBadValue, file.string(), "expected " + std::to_string(expected) + " values");
  std::vector<double> out;
  for (const auto& v : values) out.push_back(std::stod(v));
  return out;
}

}  // namespace

Volume read_cadaver_head(const std::filesystem::path& slices) {
  if (!std::filesystem::exists(slices / "CThead.1") || !std::filesystem::exists(slices / "CThead.113"))
    throw Error(ErrorCode::kFileNotFound, slices.string(), "the CThead slices (CThead.1 .. CThead.113) are not there");
  TemporaryFolder folder("cthead");
  std::ofstream(folder / "cthead.mhd")
      << "ObjectType = Image\nNDims = 3\nDimSize = 256 256 113\nElementType = MET_USHORT\n"
         "ElementSpacing = 1.0 1.0 2.0\nElementByteOrderMSB = True\nOffset = 0 0 0\n"
         "ElementDataFile = "
      << std::filesystem::absolute(slices).string() << "/CThead.%d 1 113 1\n";
  const Volume raw = read_volume_file(folder / "cthead.mhd", {.hu_offset = -1024});
  // Slice 1 is the vertex and slices go down: reverse them so k runs superiorly (z = 0 at the
  // lowest slice, 224 mm at the vertex), as the DICOM series reads back.
  Volume head;
  head.geometry = raw.geometry;
  head.geometry.direction = Eigen::Matrix3d::Identity();
  head.geometry.origin = {-127.5, -127.5, 0};
  head.hu.resize(raw.hu.size());
  const VolumeGeometry& g = raw.geometry;
  const size_t plane = size_t(g.size.x()) * size_t(g.size.y());
  for (int k = 0; k < g.size.z(); ++k)
    std::copy_n(raw.hu.begin() + std::ptrdiff_t(plane * size_t(k)), plane,
                head.hu.begin() + std::ptrdiff_t(plane * size_t(g.size.z() - 1 - k)));
  return head;
}

Eigen::Isometry3d known_rigid_move(const VolumeGeometry& geometry, double rotation_deg, double translation_mm) {
  const Eigen::Vector3d centre = geometry.world(0.5 * (geometry.size.cast<double>() - Eigen::Vector3d::Ones()));
  const Eigen::AngleAxisd rotation(rotation_deg * kPi / 180, Eigen::Vector3d(1, 2, 3).normalized());
  Eigen::Isometry3d move = Eigen::Isometry3d::Identity();
  move.translate(centre + translation_mm * Eigen::Vector3d(2, -3, 6) / 7.0).rotate(rotation).translate(-centre);
  return move;
}

Eigen::MatrixX3d skin_vertices(const Volume& ct) {
  const LabelVolume labels = segment_tissues(ct);
  const TriangleMesh skin =
      extract_region_surface(ct, labels, {kSoftTissue, kTeeth}, -400,
                             {.keep_largest_components = 1, .target_triangles = 50000, .grid = SurfaceGrid::Native});
  if (skin.vertex_count() == 0) throw Error(ErrorCode::kEmptyResult, "skin", "no skin surface in the CT");
  return skin.vertices;
}

double rms_error_mm(const Eigen::MatrixX3d& points, const Eigen::Isometry3d& moving_to_fixed,
                    const Eigen::Isometry3d& fixed_to_moving) {
  const Eigen::Isometry3d round_trip = moving_to_fixed * fixed_to_moving;
  double sum = 0;
  for (Eigen::Index v = 0; v < points.rows(); ++v) {
    const Eigen::Vector3d p = points.row(v).transpose();
    sum += (round_trip * p - p).squaredNorm();
  }
  return std::sqrt(sum / double(std::max<Eigen::Index>(1, points.rows())));
}

bool elastix_available() { return std::system("command -v elastix > /dev/null 2>&1") == 0; }

std::optional<ElastixRun> run_elastix(const Volume& fixed, const Volume& moving, const RegistrationBox& box,
                                      const std::filesystem::path& workdir) {
  if (!elastix_available()) return std::nullopt;
  std::filesystem::create_directories(workdir / "out");
  write_metaimage(workdir / "fixed.mhd", fixed.geometry, "MET_SHORT", fixed.hu.data(), fixed.hu.size() * 2);
  write_metaimage(workdir / "moving.mhd", moving.geometry, "MET_SHORT", moving.hu.data(), moving.hu.size() * 2);
  const VolumeGeometry& g = fixed.geometry;
  std::vector<uint8_t> mask(size_t(g.voxel_count()), 0);
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        const Eigen::Vector3d p = g.world(Eigen::Vector3d(i, j, k));
        mask[size_t(g.index(i, j, k))] = (p.array() >= box.min.array()).all() && (p.array() <= box.max.array()).all();
      }
  write_metaimage(workdir / "mask.mhd", g, "MET_UCHAR", mask.data(), mask.size());
  write_elastix_parameters(workdir / "rigid.txt");

  const std::string command = "elastix -f " + quoted(workdir / "fixed.mhd") + " -m " + quoted(workdir / "moving.mhd") +
                              " -fMask " + quoted(workdir / "mask.mhd") + " -p " + quoted(workdir / "rigid.txt") +
                              " -out " + quoted(workdir / "out") + " > " + quoted(workdir / "elastix-stdout.txt") +
                              " 2>&1";
  const auto start = std::chrono::steady_clock::now();
  const int status = std::system(command.c_str());
  ElastixRun run;
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (status != 0)
    throw Error(ErrorCode::kProcessing, (workdir / "out" / "elastix.log").string(), "elastix failed (see its log)");
  run.moving_to_fixed = read_elastix_euler(workdir / "out" / "TransformParameters.0.txt");
  return run;
}

Eigen::Isometry3d read_elastix_euler(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw Error(ErrorCode::kFileNotFound, file.string(), "no elastix transform");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (parameter_values(text, "Transform", file) != std::vector<std::string>{"EulerTransform"})
    throw Error(ErrorCode::kBadValue, file.string(), "not an EulerTransform");
  const auto p = numbers(parameter_values(text, "TransformParameters", file), 6, file);
  const auto c = numbers(parameter_values(text, "CenterOfRotationPoint", file), 3, file);
  bool zyx = false;
  if (std::regex_search(text, std::regex("\\(ComputeZYX")))
    zyx = parameter_values(text, "ComputeZYX", file) == std::vector<std::string>{"true"};
  const Eigen::Matrix3d rx = Eigen::AngleAxisd(p[0], Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Matrix3d ry = Eigen::AngleAxisd(p[1], Eigen::Vector3d::UnitY()).toRotationMatrix();
  const Eigen::Matrix3d rz = Eigen::AngleAxisd(p[2], Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector3d centre(c[0], c[1], c[2]);
  Eigen::Isometry3d fixed_to_moving = Eigen::Isometry3d::Identity();
  fixed_to_moving.linear() = zyx ? Eigen::Matrix3d(rz * ry * rx) : Eigen::Matrix3d(rz * rx * ry);
  fixed_to_moving.translation() = centre + Eigen::Vector3d(p[3], p[4], p[5]) - fixed_to_moving.linear() * centre;
  return fixed_to_moving.inverse();
}

}  // namespace maxillo::bench
