# Unity builds (issue 32): each target compiles its sources in batches of eight, one translation
# unit per batch, so the standard library, Eigen, nlohmann-json, CLI11 and VTK headers are parsed
# and their templates instantiated once per batch instead of once per file. docs/ARCHITECTURE.md
# ("Conventions") has the figures, and why not precompiled headers.
#
# For a developer's incremental work a batch of eight recompiles for one edited file: configure
# with -DMAXILLO_UNITY_BUILD=OFF there. CI and a first build keep it on.
#
# A unity batch shares one scope, so two files of a target may not both define a helper of the
# same name in an anonymous namespace: a shared helper belongs in a header (core/angles.h,
# render/chart_canvas.h...), a private one gets a name of its own.
option(MAXILLO_UNITY_BUILD "Compile each target's sources in batches (faster cold builds)" ON)
set(CMAKE_UNITY_BUILD ${MAXILLO_UNITY_BUILD})
if(NOT DEFINED CMAKE_UNITY_BUILD_BATCH_SIZE)
  set(CMAKE_UNITY_BUILD_BATCH_SIZE 8)
endif()

# maxillo_keep_itk_apart(target): the target's sources that include an ITK header, directly or
# through imaging/itk_*.h, compile on their own. ITK 5.2 bundles Eigen 3.3 under the same include
# guards as the system's Eigen 3.4, so an ITK source must never share a translation unit with one
# that includes Eigen (docs/ARCHITECTURE.md, "Volumes and surfaces").
function(maxillo_keep_itk_apart target)
  get_target_property(sources ${target} SOURCES)
  get_target_property(source_dir ${target} SOURCE_DIR)
  foreach(source IN LISTS sources)
    cmake_path(ABSOLUTE_PATH source BASE_DIRECTORY ${source_dir})
    if(EXISTS ${source})
      file(STRINGS ${source} itk_includes REGEX "#include [<\"](itk[A-Z]|imaging/itk_)")
      if(itk_includes)
        set_source_files_properties(${source} TARGET_DIRECTORY ${target} PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
      endif()
    endif()
  endforeach()
endfunction()
