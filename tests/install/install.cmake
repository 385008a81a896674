# Installing reelsim and using it as a library (tests/install/*.sh): each case installs
# the build into its own temporary prefix outside the trees.
#   install.exports       the shared library exports only rs_ symbols (skipped if static)
#   install.headers       the installed headers: boilerplate, umbrella, self-contained, C++
#   install.models        the installed program finds the installed material models
#   install.find_package  examples/ built with find_package(reelsim CONFIG) and run
#   install.pkg_config    examples/wind_scene.c built with pkg-config's flags and run
if(REELSIM_SANITIZE)
  # a program linking this build's library must bring the sanitizers' run-time first
  set(RS_CONSUMER_CFLAGS "-fsanitize=address,undefined -fno-omit-frame-pointer")
else()
  set(RS_CONSUMER_CFLAGS "")
endif()
if(BUILD_SHARED_LIBS)
  set(RS_STATIC 0)
else()
  set(RS_STATIC 1)
endif()
set(RS_INSTALL_TEST_ENV
    "RS_BUILD=${PROJECT_BINARY_DIR}" "RS_SOURCE=${PROJECT_SOURCE_DIR}"
    "RS_CMAKE=${CMAKE_COMMAND}" "RS_CC=${CMAKE_C_COMPILER}"
    "RS_LIBDIR=${CMAKE_INSTALL_LIBDIR}" "RS_BINDIR=${CMAKE_INSTALL_BINDIR}"
    "RS_DATADIR=${CMAKE_INSTALL_DATADIR}" "RS_STATIC=${RS_STATIC}"
    "RS_CONSUMER_CFLAGS=${RS_CONSUMER_CFLAGS}")

function(rs_install_test name label script)
  add_test(NAME install.${name}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/install/${script} ${ARGN})
  set_tests_properties(install.${name} PROPERTIES LABELS ${label} TIMEOUT 300
                       SKIP_RETURN_CODE 77 ENVIRONMENT "${RS_INSTALL_TEST_ENV}")
endfunction()

rs_install_test(exports unit exports.sh $<TARGET_FILE:reelsim>)
rs_install_test(headers unit headers.sh)
rs_install_test(models cli models.sh)
rs_install_test(find_package cli consumer.sh find_package)
rs_install_test(pkg_config cli consumer.sh pkg_config)
rs_install_test(completion cli completion.sh)
