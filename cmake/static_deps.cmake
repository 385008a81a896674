# The program's dependencies (included from the top CMakeLists.txt; docs/performance.md,
# "What remains outside the engine", docs/development.md). The reelsim program links the
# library's objects (reelsim_app) with HDF5 and LAPACKE/OpenBLAS as static archives where
# Debian ships them: the shared libhdf5_serial brings 25 more libraries (its ROS3 driver's
# curl, OpenSSL, GnuTLS, Kerberos, LDAP; the archive's objects that reelsim uses reference
# none of that driver) and the shared LAPACKE/OpenBLAS huge symbol tables to relocate:
# about 15 ms and 6 ms of a start-up that was 33-44 ms of CPU. libreelsim.so (the Python
# package's, a C program's), the tests and the benchmarks link the shared ones as before.
#   REELSIM_STATIC_DEPS  AUTO: each archive when found and a test program links with it
#                        (not in the fuzzing build: its LeakSanitizer suppressions name
#                        libhdf5.so); ON: the HDF5 archive is required; OFF: the shared
#                        libraries, the program linking libreelsim.
# Sets RS_APP_HDF5, RS_APP_LAPACKE, RS_APP_YAML, RS_APP_UDUNITS (what the program links for
# each) and RS_STATIC_APPS (ON when HDF5 or LAPACKE is an archive: the program then links
# reelsim_app; libyaml and UDUNITS-2 are archives only then).
set(REELSIM_STATIC_DEPS AUTO CACHE STRING
    "Link the reelsim program with static HDF5 and LAPACKE/OpenBLAS: AUTO (when found), ON, OFF")
set_property(CACHE REELSIM_STATIC_DEPS PROPERTY STRINGS AUTO ON OFF)

set(RS_APP_HDF5 hdf5::hdf5)
set(RS_APP_LAPACKE PkgConfig::RS_LAPACKE)
set(RS_APP_YAML PkgConfig::RS_YAML_0_1)
set(RS_APP_UDUNITS PkgConfig::RS_UDUNITS)
set(RS_STATIC_APPS OFF)

if(REELSIM_STATIC_DEPS STREQUAL "ON" OR (REELSIM_STATIC_DEPS STREQUAL "AUTO" AND NOT REELSIM_FUZZ))
  include(CheckCSourceCompiles)
  include(CMakePushCheckState)

  # rs_archives(VAR name...): the archives lib<name>.a of every name, or empty if one is
  # missing (then the shared libraries serve)
  function(rs_archives var)
    set(found "")
    foreach(n IN LISTS ARGN)
      find_library(RS_ARCHIVE_${n} NAMES lib${n}.a)
      if(NOT RS_ARCHIVE_${n})
        set(${var} "" PARENT_SCOPE)
        return()
      endif()
      list(APPEND found ${RS_ARCHIVE_${n}})
    endforeach()
    set(${var} ${found} PARENT_SCOPE)
  endfunction()

  # HDF5: the archive beside the shared library CMake found (Debian: hdf5/serial/libhdf5.a),
  # with the compression libraries its filters call (their archives too: libaec-dev,
  # zlib1g-dev; 0.2 ms each as shared libraries).
  get_filename_component(rs_hdf5_dir "${HDF5_C_LIBRARY_hdf5}" DIRECTORY)
  find_library(RS_HDF5_ARCHIVE NAMES libhdf5.a PATHS "${rs_hdf5_dir}" NO_DEFAULT_PATH)
  rs_archives(rs_hdf5_deps sz aec z)
  set(RS_HDF5_DEPS_STATIC ${rs_hdf5_deps}) # for tests/cli/startup.cmake
  if(NOT rs_hdf5_deps)
    foreach(l sz z)
      find_library(RS_HDF5_DEP_${l} NAMES ${l})
      if(RS_HDF5_DEP_${l})
        list(APPEND rs_hdf5_deps ${RS_HDF5_DEP_${l}})
      endif()
    endforeach()
  endif()
  set(rs_hdf5_libs ${RS_HDF5_ARCHIVE} ${rs_hdf5_deps} Threads::Threads m ${CMAKE_DL_LIBS})
  if(RS_HDF5_ARCHIVE)
    cmake_push_check_state(RESET)
    set(CMAKE_REQUIRED_INCLUDES ${HDF5_C_INCLUDE_DIRS} ${HDF5_INCLUDE_DIRS})
    set(CMAKE_REQUIRED_LIBRARIES ${rs_hdf5_libs})
    set(CMAKE_REQUIRED_QUIET ON)
    check_c_source_compiles([[
      #include <hdf5.h>
      int main(void) {
        hid_t p = H5Pcreate(H5P_DATASET_CREATE);
        H5Pset_deflate(p, 1);
        hid_t f = H5Fcreate("x.h5", H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
        return (int)(H5Fclose(f) + H5Pclose(p) + H5close());
      }]] RS_HDF5_ARCHIVE_LINKS)
    cmake_pop_check_state()
  endif()
  if(RS_HDF5_ARCHIVE AND RS_HDF5_ARCHIVE_LINKS)
    add_library(rs_hdf5_static INTERFACE)
    target_include_directories(rs_hdf5_static INTERFACE
                               $<TARGET_PROPERTY:hdf5::hdf5,INTERFACE_INCLUDE_DIRECTORIES>)
    target_compile_definitions(rs_hdf5_static INTERFACE
                               $<TARGET_PROPERTY:hdf5::hdf5,INTERFACE_COMPILE_DEFINITIONS>)
    target_link_libraries(rs_hdf5_static INTERFACE ${rs_hdf5_libs})
    set(RS_APP_HDF5 rs_hdf5_static)
    set(RS_STATIC_APPS ON)
  elseif(REELSIM_STATIC_DEPS STREQUAL "ON")
    message(FATAL_ERROR "REELSIM_STATIC_DEPS=ON: no static HDF5 that links (libhdf5.a beside "
                        "${HDF5_C_LIBRARY_hdf5}; Debian: libhdf5-dev). Use AUTO or OFF.")
  endif()

  # LAPACKE and the LAPACK/BLAS the system runs today: the OpenBLAS archive in the directory
  # liblapack.so.3 resolves to (Debian's alternatives: openblas-serial/, package
  # libopenblas-serial-dev), never the reference BLAS, which the nip's dense LU would feel.
  find_library(RS_LAPACKE_ARCHIVE NAMES liblapacke.a)
  find_library(RS_LAPACK_RUNTIME NAMES liblapack.so.3)
  if(RS_LAPACK_RUNTIME)
    get_filename_component(rs_lapack_real "${RS_LAPACK_RUNTIME}" REALPATH)
    get_filename_component(rs_lapack_dir "${rs_lapack_real}" DIRECTORY)
    find_library(RS_OPENBLAS_ARCHIVE NAMES libopenblas.a PATHS "${rs_lapack_dir}" NO_DEFAULT_PATH)
  endif()
  if(RS_LAPACKE_ARCHIVE AND RS_OPENBLAS_ARCHIVE)
    set(rs_lapack_libs ${RS_LAPACKE_ARCHIVE} ${RS_OPENBLAS_ARCHIVE} Threads::Threads m)
    cmake_push_check_state(RESET)
    set(CMAKE_REQUIRED_INCLUDES ${RS_LAPACKE_INCLUDE_DIRS})
    set(CMAKE_REQUIRED_LIBRARIES ${rs_lapack_libs})
    set(CMAKE_REQUIRED_QUIET ON)
    check_c_source_compiles([[
      #include <lapacke.h>
      int main(void) {
        double a[4] = {4, 1, 1, 3}, b[2] = {1, 2}, rc = 0;
        lapack_int ip[2];
        return (int)(LAPACKE_dgesv(LAPACK_COL_MAJOR, 2, 1, a, 2, ip, b, 2) +
                     LAPACKE_dpotrf(LAPACK_COL_MAJOR, 'U', 2, a, 2) +
                     LAPACKE_dpotri(LAPACK_COL_MAJOR, 'U', 2, a, 2) +
                     LAPACKE_dpocon(LAPACK_COL_MAJOR, 'U', 2, a, 2, 1.0, &rc));
      }]] RS_LAPACK_ARCHIVES_LINK)
    cmake_pop_check_state()
    if(RS_LAPACK_ARCHIVES_LINK)
      add_library(rs_lapacke_static INTERFACE)
      target_include_directories(rs_lapacke_static INTERFACE ${RS_LAPACKE_INCLUDE_DIRS})
      target_link_libraries(rs_lapacke_static INTERFACE ${rs_lapack_libs})
      set(RS_APP_LAPACKE rs_lapacke_static)
      set(RS_STATIC_APPS ON)
    endif()
  endif()

  # libyaml and UDUNITS-2 (with expat): small, but each shared library costs its loading
  rs_archives(rs_small yaml udunits2 expat)
  if(rs_small)
    cmake_push_check_state(RESET)
    set(CMAKE_REQUIRED_INCLUDES ${RS_YAML_0_1_INCLUDE_DIRS} ${RS_UDUNITS_INCLUDE_DIRS})
    set(CMAKE_REQUIRED_LIBRARIES ${rs_small} m)
    set(CMAKE_REQUIRED_QUIET ON)
    check_c_source_compiles([[
      #include <udunits2.h>
      #include <yaml.h>
      int main(void) {
        yaml_parser_t p;
        ut_system *u = ut_read_xml(0);
        ut_free_system(u);
        return yaml_parser_initialize(&p) ? 0 : 1;
      }]] RS_SMALL_ARCHIVES_LINK)
    cmake_pop_check_state()
    if(RS_SMALL_ARCHIVES_LINK)
      list(GET rs_small 0 rs_yaml_a)
      list(SUBLIST rs_small 1 2 rs_udunits_a)
      add_library(rs_yaml_static INTERFACE)
      target_include_directories(rs_yaml_static INTERFACE ${RS_YAML_0_1_INCLUDE_DIRS})
      target_link_libraries(rs_yaml_static INTERFACE ${rs_yaml_a})
      add_library(rs_udunits_static INTERFACE)
      target_include_directories(rs_udunits_static INTERFACE ${RS_UDUNITS_INCLUDE_DIRS})
      target_link_libraries(rs_udunits_static INTERFACE ${rs_udunits_a} m)
      set(RS_APP_YAML rs_yaml_static)
      set(RS_APP_UDUNITS rs_udunits_static)
    endif()
  endif()
endif()
message(STATUS "reelsim program with static HDF5: ${RS_APP_HDF5}; LAPACKE/OpenBLAS: ${RS_APP_LAPACKE}; libyaml, UDUNITS-2: ${RS_APP_YAML} ${RS_APP_UDUNITS}")
