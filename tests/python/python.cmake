# The Python package's tests (tests/python/test_*.py, pytest): one ctest entry per file,
# python.<file> (python.test_run, ...), label python, in the normal run. Each runs the
# package the build made (PYTHONPATH=<build>/python) with the interpreter that has
# Debian's python3-numpy, -h5py, -pytest and -matplotlib (scripts/setup.sh installs them).
# pytest exits 5 when it collects nothing, so an entry that runs no test fails.
#
# Not registered in a sanitizer build (REELSIM_SANITIZE, REELSIM_FUZZ): a python3
# process loading an ASan-instrumented libreelsim aborts unless libasan is preloaded
# into the interpreter, and the C tests cover the same library there. Nor without the
# package (a static libreelsim, REELSIM_PYTHON=OFF).
if(RS_HAVE_PYTHON_PACKAGE AND NOT REELSIM_SANITIZE AND NOT REELSIM_FUZZ)
  # The Debian interpreter first: another python3 first on PATH (pyenv, a venv) lacks
  # Debian's modules.
  if(NOT REELSIM_PYTHON_EXECUTABLE)
    find_program(RS_PY_CANDIDATE_DEBIAN python3 PATHS /usr/bin NO_DEFAULT_PATH)
    find_program(RS_PY_CANDIDATE_PATH python3)
    foreach(py IN ITEMS ${RS_PY_CANDIDATE_DEBIAN} ${RS_PY_CANDIDATE_PATH})
      execute_process(COMMAND ${py} -c "import numpy, h5py, pytest, matplotlib"
                      RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
      if(rc EQUAL 0)
        set(REELSIM_PYTHON_EXECUTABLE ${py} CACHE FILEPATH
            "python3 with numpy, h5py, pytest and matplotlib, for the python tests")
        break()
      endif()
    endforeach()
  endif()
  if(NOT REELSIM_PYTHON_EXECUTABLE)
    message(WARNING "python tests not registered: no python3 imports numpy, h5py, pytest "
                    "and matplotlib (Debian: python3-numpy python3-h5py python3-pytest "
                    "python3-matplotlib; scripts/setup.sh installs them)")
  else()
    file(GLOB RS_PY_TESTS CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/python/test_*.py)
    foreach(t IN LISTS RS_PY_TESTS)
      get_filename_component(n ${t} NAME_WE)
      add_test(NAME python.${n}
               COMMAND ${REELSIM_PYTHON_EXECUTABLE} -m pytest -q -p no:cacheprovider
                       --rootdir=${CMAKE_CURRENT_SOURCE_DIR}/python ${t})
      set_tests_properties(python.${n} PROPERTIES LABELS python TIMEOUT 300 ENVIRONMENT
        "PYTHONPATH=${RS_PYTHON_BUILD_DIR};PYTHONDONTWRITEBYTECODE=1;MPLBACKEND=Agg;RS_SOURCE=${PROJECT_SOURCE_DIR};RS_BUILD=${PROJECT_BINARY_DIR};RS_CLI=$<TARGET_FILE:reelsim_cli>;RS_CMAKE=${CMAKE_COMMAND}")
    endforeach()
  endif()
endif()
