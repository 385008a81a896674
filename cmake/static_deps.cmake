# The applications' dependencies (included from the top CMakeLists.txt; docs/performance.md,
# "Start-up"). The reelsim program links the library's objects (reelsim_app) with HDF5 and
# LAPACKE/OpenBLAS as static archives where Debian ships them: the shared libhdf5_serial brings 25 more libraries (its ROS3 driver's curl, OpenSSL,
# GnuTLS, Kerberos, LDAP; no object of that driver is linked from the archive) and the
# shared LAPACKE/OpenBLAS huge symbol tables to relocate: 15 ms and 6 ms of a start-up that
# was 37 ms. libreelsim.so (the Python package's, a C user's) links the shared ones as before.
#   REELSIM_STATIC_DEPS  AUTO: each archive when found and a test program links with it
#                        (not in the fuzzing build: its LeakSanitizer suppressions name
#                        libhdf5.so); ON: the HDF5 archive is required; OFF: the shared
#                        libraries, the program linking libreelsim.
# Sets RS_APP_HDF5 and RS_APP_LAPACKE (what the applications link for each) and
# RS_STATIC_APPS (ON when either is an archive: the program then links reelsim_app).
set(REELSIM_STATIC_DEPS AUTO CACHE STRING
    "Link the reelsim program with static HDF5 and LAPACKE/OpenBLAS: AUTO (when found), ON, OFF")
set_property(CACHE REELSIM_STATIC_DEPS PROPERTY STRINGS AUTO ON OFF)

set(RS_APP_HDF5 hdf5::hdf5)
set(RS_APP_LAPACKE PkgConfig::RS_LAPACKE)
set(RS_STATIC_APPS OFF)

if(REELSIM_STATIC_DEPS STREQUAL "ON" OR (REELSIM_STATIC_DEPS STREQUAL "AUTO" AND NOT REELSIM_FUZZ))
  include(CheckCSourceCompiles)
  include(CMakePushCheckState)

  # HDF5: the archive beside the shared library CMake found (Debian: hdf5/serial/libhdf5.a),
  # with the compression libraries its filters call.
  get_filename_component(rs_hdf5_dir "${HDF5_C_LIBRARY_hdf5}" DIRECTORY)
  find_library(RS_HDF5_ARCHIVE NAMES libhdf5.a PATHS "${rs_hdf5_dir}" NO_DEFAULT_PATH)
  set(rs_hdf5_libs ${RS_HDF5_ARCHIVE})
  foreach(l sz z)
    find_library(RS_HDF5_DEP_${l} NAMES ${l})
    if(RS_HDF5_DEP_${l})
      list(APPEND rs_hdf5_libs ${RS_HDF5_DEP_${l}})
    endif()
  endforeach()
  list(APPEND rs_hdf5_libs Threads::Threads m ${CMAKE_DL_LIBS})
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
endif()
message(STATUS "reelsim program with static HDF5: ${RS_APP_HDF5}; LAPACKE/OpenBLAS: ${RS_APP_LAPACKE}")
