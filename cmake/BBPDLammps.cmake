# SPDX-License-Identifier: GPL-2.0-or-later
# Where the plugin gets LAMMPS from, the way LAMMPS's own plugin examples do it:
#   * the headers from a LAMMPS source tree (LAMMPS_SOURCE_DIR): a plugin needs headers that an
#     installed LAMMPS does not ship (lammpsplugin.h, neigh_request.h, version.h, ...);
#   * the build settings (integer sizes, MPI or its serial STUBS) from the LAMMPS that will load
#     the plugin: its CMake package (find_package(LAMMPS), found through LAMMPS_DIR or
#     CMAKE_PREFIX_PATH) when there is one, else the LAMMPS_SIZES and BBPD_MPI cache variables.
# A plugin compiled with other integer sizes than its LAMMPS corrupts memory, so a mismatch is a
# configure error here and a refusal to register at run time (bbpdplugin.cpp).
# Result: the interface target bbpd_lammps.

set(LAMMPS_SOURCE_DIR "" CACHE PATH "LAMMPS source tree (the folder holding src/)")
if(NOT EXISTS "${LAMMPS_SOURCE_DIR}/src/lammps.h")
  message(FATAL_ERROR "LAMMPS_SOURCE_DIR='${LAMMPS_SOURCE_DIR}' holds no src/lammps.h: "
                      "run tools/bootstrap --for reproduce, or pass -D LAMMPS_SOURCE_DIR=/path/to/lammps")
endif()

set(BBPD_LAMMPS_SIZES_VALUES smallbig bigbig smallsmall)
find_package(LAMMPS CONFIG QUIET)
if(LAMMPS_FOUND)
  get_target_property(_lmp_defs LAMMPS::lammps INTERFACE_COMPILE_DEFINITIONS)
  set(_lmp_sizes "")
  foreach(_def IN LISTS _lmp_defs)
    if(_def MATCHES "^-?D?LAMMPS_(SMALLBIG|BIGBIG|SMALLSMALL)$")
      string(TOLOWER "${CMAKE_MATCH_1}" _lmp_sizes)
    endif()
  endforeach()
  if(NOT _lmp_sizes)
    message(FATAL_ERROR "the LAMMPS package in ${LAMMPS_DIR} names no integer sizes "
                        "(LAMMPS_SMALLBIG/BIGBIG/SMALLSMALL) in its compile definitions")
  endif()
  if(DEFINED CACHE{LAMMPS_SIZES} AND NOT LAMMPS_SIZES STREQUAL _lmp_sizes)
    message(FATAL_ERROR "LAMMPS_SIZES=${LAMMPS_SIZES} but the LAMMPS in ${LAMMPS_DIR} was built "
                        "with ${_lmp_sizes}: drop -D LAMMPS_SIZES or make them agree")
  endif()
  set(LAMMPS_SIZES "${_lmp_sizes}" CACHE STRING "LAMMPS integer sizes (from the LAMMPS package)" FORCE)
  get_target_property(_lmp_links LAMMPS::lammps INTERFACE_LINK_LIBRARIES)
  if(_lmp_links MATCHES "MPI::MPI_CXX")
    set(_lmp_mpi ON)
  else()
    set(_lmp_mpi OFF)
  endif()
  if(DEFINED CACHE{BBPD_MPI} AND NOT BBPD_MPI STREQUAL _lmp_mpi)
    message(FATAL_ERROR "BBPD_MPI=${BBPD_MPI} but the LAMMPS in ${LAMMPS_DIR} has BUILD_MPI=${_lmp_mpi}")
  endif()
  set(BBPD_MPI ${_lmp_mpi} CACHE BOOL "LAMMPS is built with MPI (OFF: serial LAMMPS, MPI STUBS)" FORCE)
  message(STATUS "BBPD: LAMMPS ${LAMMPS_VERSION} from ${LAMMPS_DIR}: sizes ${LAMMPS_SIZES}, MPI ${BBPD_MPI}")
else()
  set(LAMMPS_SIZES "smallbig" CACHE STRING
      "LAMMPS integer sizes of the LAMMPS that loads the plugin (its -D LAMMPS_SIZES)")
  option(BBPD_MPI "LAMMPS is built with MPI (OFF: serial LAMMPS, MPI STUBS)" ON)
  message(STATUS "BBPD: no LAMMPS CMake package found (set LAMMPS_DIR to <prefix>/lib/cmake/LAMMPS); "
                 "using LAMMPS_SIZES=${LAMMPS_SIZES}, BBPD_MPI=${BBPD_MPI}: they must match that LAMMPS")
endif()
if(NOT LAMMPS_SIZES IN_LIST BBPD_LAMMPS_SIZES_VALUES)
  message(FATAL_ERROR "LAMMPS_SIZES=${LAMMPS_SIZES}: use one of ${BBPD_LAMMPS_SIZES_VALUES}")
endif()

add_library(bbpd_lammps INTERFACE)
string(TOUPPER "${LAMMPS_SIZES}" _sizes_upper)
target_compile_definitions(bbpd_lammps INTERFACE LAMMPS_${_sizes_upper})
target_include_directories(bbpd_lammps INTERFACE ${LAMMPS_SOURCE_DIR}/src)
if(BBPD_MPI)
  find_package(MPI REQUIRED COMPONENTS CXX)
  target_link_libraries(bbpd_lammps INTERFACE MPI::MPI_CXX)
else()
  # serial LAMMPS: its MPI stub header; the symbols come from the LAMMPS that loads the plugin
  target_include_directories(bbpd_lammps INTERFACE ${LAMMPS_SOURCE_DIR}/src/STUBS)
endif()
