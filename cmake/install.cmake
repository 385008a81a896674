# What `cmake --install` puts under the prefix (included from the top CMakeLists.txt):
#   lib/libreelsim.so.<v> (or .a)            the library, target reelsim::reelsim
#   lib/cmake/reelsim/reelsim{Config,ConfigVersion,Targets}.cmake   find_package(reelsim CONFIG)
#   lib/pkgconfig/reelsim.pc                 pkg-config --cflags --libs reelsim
#   include/reelsim/*.h                      the public headers (reelsim/reelsim.h: all of them)
#   bin/reelsim                              the command-line program
#   lib/reelsim/reelsim-mpi.so               its MPI module (a build with MPI)
#   share/reelsim/models/*.yaml              the shipped material models
include(CMakePackageConfigHelpers)

set(RS_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/reelsim)

install(TARGETS reelsim EXPORT reelsimTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS reelsim_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(RS_HAVE_MPI) # the program's MPI module (src/sweep/mpi_module.h), where it looks for it
  install(TARGETS reelsim_mpi LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/reelsim)
endif()
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/reelsim.bash
        DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME reelsim)
install(DIRECTORY include/reelsim DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.h")
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/include/reelsim/version.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/reelsim)
install(DIRECTORY models/ DESTINATION ${RS_MODELS_INSTALL_DIR} FILES_MATCHING PATTERN "*.yaml")

install(EXPORT reelsimTargets NAMESPACE reelsim:: DESTINATION ${RS_CMAKE_DIR})
# A static libreelsim leaves its dependencies to the program: the package finds them.
if(BUILD_SHARED_LIBS)
  set(RS_STATIC_CONFIG 0)
else()
  set(RS_STATIC_CONFIG 1)
endif()
configure_package_config_file(cmake/reelsimConfig.cmake.in
                              ${CMAKE_CURRENT_BINARY_DIR}/reelsimConfig.cmake
                              INSTALL_DESTINATION ${RS_CMAKE_DIR})
# 0.y: a minor version may break the API, so only the same minor is compatible
if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(RS_COMPATIBILITY SameMinorVersion)
else()
  set(RS_COMPATIBILITY SameMajorVersion)
endif()
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/reelsimConfigVersion.cmake
                                 COMPATIBILITY ${RS_COMPATIBILITY})
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/reelsimConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/reelsimConfigVersion.cmake
        DESTINATION ${RS_CMAKE_DIR})

# pkg-config: the private requirements only for a static library (a program linking the
# shared one needs none of them, nor their -dev packages)
if(BUILD_SHARED_LIBS)
  set(RS_PC_REQUIRES_PRIVATE "")
  set(RS_PC_LIBS_PRIVATE "")
else()
  list(JOIN RS_PKG_MODULES " " RS_PC_REQUIRES_PRIVATE)
  # Debian's name for the serial HDF5's module
  set(RS_PC_REQUIRES_PRIVATE "hdf5-serial ${RS_PC_REQUIRES_PRIVATE}")
  set(RS_PC_LIBS_PRIVATE "-lsundials_cvode -lsundials_nvecserial -lsundials_sunmatrixdense -lsundials_sunlinsoldense")
  if(NOT SUNDIALS_VERSION VERSION_LESS 7) # SUNDIALS 7 moved the shared parts to sundials_core
    string(APPEND RS_PC_LIBS_PRIVATE " -lsundials_core")
  endif()
  string(APPEND RS_PC_LIBS_PRIVATE " -lm -pthread")
  foreach(l IN LISTS CMAKE_DL_LIBS)
    string(APPEND RS_PC_LIBS_PRIVATE " -l${l}")
  endforeach()
endif()
file(RELATIVE_PATH RS_PC_PREFIX_FROM_PCDIR ${CMAKE_INSTALL_FULL_LIBDIR}/pkgconfig
     ${CMAKE_INSTALL_PREFIX})
configure_file(cmake/reelsim.pc.in ${CMAKE_CURRENT_BINARY_DIR}/reelsim.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/reelsim.pc
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
