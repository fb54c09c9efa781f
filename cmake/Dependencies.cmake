# Every third-party library comes from Debian 12's packages (scripts/setup installs them).
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(SQLite3 REQUIRED)
find_package(PostgreSQL REQUIRED)       # libpq: the archive index on a PostgreSQL server (issue 13)
find_package(OpenSSL REQUIRED)            # SHA-256 of archived objects (uses SHA-NI where present)
find_package(nlohmann_json 3 REQUIRED)
find_package(CLI11 REQUIRED)
find_package(DCMTK REQUIRED)
find_package(ZLIB REQUIRED)             # deflated DICOM data sets, inflated for the structure check
find_package(ITK 5.2 REQUIRED COMPONENTS
  ITKCommon ITKIOImageBase ITKIOMeta ITKIONRRD ITKThresholding ITKConnectedComponents
  ITKBinaryMathematicalMorphology ITKMathematicalMorphology ITKLabelMap ITKImageFilterBase
  ITKSmoothing ITKImageGrid
  ITKRegistrationMethodsv4 ITKOptimizersv4 ITKMetricsv4 ITKOptimizers ITKSpatialObjects ITKTransform ITKStatistics)
find_package(VTK 9.1 REQUIRED COMPONENTS
  CommonCore CommonDataModel CommonTransforms CommonExecutionModel
  FiltersCore FiltersGeneral FiltersModeling FiltersSources FiltersGeometry
  ImagingCore IOGeometry IOPLY IOXML IOImage
  RenderingCore RenderingOpenGL2 RenderingAnnotation RenderingFreeType InteractionStyle
  ChartsCore RenderingContext2D RenderingContextOpenGL2)  # charts (render/chart_*.cpp)

find_library(HPDF_LIBRARY NAMES hpdf REQUIRED)
find_path(HPDF_INCLUDE_DIR hpdf.h REQUIRED)
find_library(OSMESA_LIBRARY NAMES OSMesa REQUIRED)
find_path(OSMESA_INCLUDE_DIR GL/osmesa.h REQUIRED)

find_package(GTest)
find_package(benchmark)
