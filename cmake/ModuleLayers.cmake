# The module layers of docs/ARCHITECTURE.md, checked when the build is configured.
#
# Each module may link only the maxillo modules its row allows (a module links nothing above
# it), and the numerical modules may not reach a toolkit through any link, direct or inherited:
# they build and test with Eigen, nlohmann-json, OpenSSL (core's SHA-256), OpenMP and CHOLMOD
# only. DCMTK is linked by dicom and net alone, and dicom and imaging reach neither index engine
# (SQLite, libpq) through any link (issue 33; scripts/check-dicom-apart checks the sources and
# the programs' link lines). A violation stops the configuration with the module and the
# offending link named.

set(maxillo_allowed_links_core "")
set(maxillo_allowed_links_geometry core)
set(maxillo_allowed_links_ceph core geometry)
set(maxillo_allowed_links_occlusion core geometry)
set(maxillo_allowed_links_softtissue core geometry)
set(maxillo_allowed_links_validation core geometry)
set(maxillo_allowed_links_dental core geometry validation)
set(maxillo_allowed_links_planning core geometry ceph)
set(maxillo_allowed_links_sample core geometry ceph)
set(maxillo_allowed_links_dicom core)
set(maxillo_allowed_links_archive core geometry ceph dicom)
set(maxillo_allowed_links_net core geometry ceph dicom archive)
set(maxillo_allowed_links_imaging core geometry ceph dicom)
set(maxillo_allowed_links_landmarking core geometry ceph imaging)
set(maxillo_allowed_links_mesh core geometry)
set(maxillo_allowed_links_render core geometry)
set(maxillo_allowed_links_report core)
set(maxillo_allowed_links_tetmesh core geometry softtissue)
# The workflows above the toolkits: the stored records, the casework shared by the three jobs,
# the report sections, then the jobs themselves, the benchmarks and the demo.
set(maxillo_below_records core geometry ceph occlusion softtissue validation dental planning sample dicom archive net imaging
                          landmarking mesh render report tetmesh)
set(maxillo_allowed_links_records core geometry ceph archive imaging landmarking mesh occlusion planning softtissue validation)
set(maxillo_allowed_links_casework ${maxillo_below_records} records)
set(maxillo_allowed_links_sections ${maxillo_allowed_links_casework} casework)
set(maxillo_allowed_links_consultation ${maxillo_allowed_links_sections} sections)
set(maxillo_allowed_links_followup ${maxillo_allowed_links_sections} sections)
set(maxillo_allowed_links_nightly ${maxillo_allowed_links_sections} sections)
set(maxillo_allowed_links_bench ${maxillo_allowed_links_casework} casework)
set(maxillo_allowed_links_demo ${maxillo_allowed_links_sections} sections consultation followup nightly)

set(maxillo_numerical_modules core geometry ceph occlusion softtissue validation dental planning)
# Anything whose name matches is a toolkit the numerical modules must not link.
set(maxillo_toolkit_pattern "VTK|vtk|ITK|itk|OSMesa|OSMESA|CGAL|DCMTK|hpdf|SQLite|PostgreSQL|CURL")
# Issue 33: DCMTK is linked by the file codec and the network node alone, and the modules that
# read DICOM files without the archive reach neither index engine through any link.
set(maxillo_dcmtk_modules dicom net)
set(maxillo_index_free_modules dicom imaging)

# Every link item of `target`, followed through maxillo targets (both the libraries it links
# and those it passes on), generator expressions such as $<LINK_ONLY:x> unwrapped.
function(maxillo_link_closure target out_var)
  set(pending ${target})
  set(seen "")
  set(items "")
  while(pending)
    list(POP_FRONT pending current)
    if(current IN_LIST seen)
      continue()
    endif()
    list(APPEND seen ${current})
    set(links "")
    if(TARGET ${current})
      get_target_property(type ${current} TYPE)
      if(NOT type STREQUAL "INTERFACE_LIBRARY")
        get_target_property(direct ${current} LINK_LIBRARIES)
        if(direct)
          list(APPEND links ${direct})
        endif()
      endif()
      get_target_property(passed ${current} INTERFACE_LINK_LIBRARIES)
      if(passed)
        list(APPEND links ${passed})
      endif()
    endif()
    foreach(link IN LISTS links)
      string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" link "${link}")
      list(APPEND items ${link})
      if(TARGET ${link})
        list(APPEND pending ${link})
      endif()
    endforeach()
  endwhile()
  list(REMOVE_DUPLICATES items)
  set(${out_var} ${items} PARENT_SCOPE)
endfunction()

# The first link item of `target`'s closure whose name matches `pattern`, or "" when none does.
function(maxillo_reached_link target pattern out_var)
  maxillo_link_closure(${target} closure)
  foreach(link IN LISTS closure)
    if(link MATCHES "${pattern}")
      set(${out_var} ${link} PARENT_SCOPE)
      return()
    endif()
  endforeach()
  set(${out_var} "" PARENT_SCOPE)
endfunction()

function(maxillo_check_module_layers)
  foreach(module IN ITEMS core geometry ceph occlusion softtissue validation dental planning sample dicom archive net
                          imaging landmarking mesh render report tetmesh records casework sections consultation followup
                          nightly bench demo)
    if(NOT TARGET maxillo_${module})
      message(FATAL_ERROR "ModuleLayers: no target maxillo_${module}")
    endif()
    get_target_property(direct maxillo_${module} LINK_LIBRARIES)
    foreach(link IN LISTS direct)
      if(link MATCHES "^maxillo_(.*)$")
        set(other ${CMAKE_MATCH_1})
        if(other STREQUAL "warnings" OR other STREQUAL "sanitizers")
          continue()
        endif()
        if(NOT other IN_LIST maxillo_allowed_links_${module})
          message(FATAL_ERROR "ModuleLayers: maxillo_${module} links maxillo_${other}, which its row in "
                              "docs/ARCHITECTURE.md does not allow (allowed: ${maxillo_allowed_links_${module}})")
        endif()
      elseif(link MATCHES "DCMTK" AND NOT module IN_LIST maxillo_dcmtk_modules)
        message(FATAL_ERROR "ModuleLayers: maxillo_${module} links '${link}'; DCMTK belongs to the dicom "
                            "and net modules alone: read and write DICOM files through maxillo_dicom")
      endif()
    endforeach()
  endforeach()
  foreach(module IN LISTS maxillo_index_free_modules)
    maxillo_reached_link(maxillo_${module} "SQLite|PostgreSQL" link)
    if(link)
      message(FATAL_ERROR "ModuleLayers: maxillo_${module} reaches the index engine '${link}'; it reads "
                          "DICOM files through maxillo_dicom and may not link the archive or its engines")
    endif()
  endforeach()
  foreach(module IN LISTS maxillo_numerical_modules)
    maxillo_reached_link(maxillo_${module} "${maxillo_toolkit_pattern}" link)
    if(link)
      message(FATAL_ERROR "ModuleLayers: the numerical module maxillo_${module} reaches the toolkit "
                          "'${link}'; it must build and link without VTK, ITK, OSMesa or the other toolkits")
    endif()
  endforeach()
endfunction()
