# The Python module `iga_run` (python/): Debian's pybind11 and Debian's Python 3 with NumPy
# (scripts/install-deps.sh). Python3_EXECUTABLE defaults to /usr/bin/python3, so that a Python on
# PATH without NumPy (a pyenv, a virtualenv) is not picked up by accident.
# The package is built into <build>/python/iga_run and installed into IGA_PYTHON_INSTALL_DIR.
if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "The Python the module is built for")
endif()
set(iga_python_default OFF)
if(NOT IGA_SANITIZE AND NOT IGA_FUZZ)
  # Python first: pybind11 then uses this Python (CMake's FindPython) instead of its own search.
  find_package(Python3 QUIET COMPONENTS Interpreter Development.Module)
  if(Python3_FOUND)
    find_package(pybind11 CONFIG QUIET)
  endif()
  if(Python3_FOUND AND pybind11_FOUND)
    set(iga_python_default ON)
  endif()
endif()
option(IGA_PYTHON "Build the Python module iga_run (needs pybind11-dev, python3-dev, python3-numpy)" ${iga_python_default})
set(IGA_PYTHON_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/python3/dist-packages CACHE PATH
    "Where `cmake --install` puts the Python package (relative: under the prefix)")

if(IGA_PYTHON)
  find_package(Python3 REQUIRED COMPONENTS Interpreter Development.Module)
  find_package(pybind11 CONFIG REQUIRED)
  set(IGA_PYTHON_PACKAGE_DIR ${CMAKE_BINARY_DIR}/python/iga_run)
  pybind11_add_module(_iga_run ${CMAKE_CURRENT_SOURCE_DIR}/python/src/iga_run_module.cpp)
  target_link_libraries(_iga_run PRIVATE igarun)
  set_target_properties(_iga_run PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${IGA_PYTHON_PACKAGE_DIR})
  configure_file(${CMAKE_CURRENT_SOURCE_DIR}/python/iga_run/__init__.py ${IGA_PYTHON_PACKAGE_DIR}/__init__.py COPYONLY)
  install(TARGETS _iga_run LIBRARY DESTINATION ${IGA_PYTHON_INSTALL_DIR}/iga_run)
  install(FILES ${CMAKE_CURRENT_SOURCE_DIR}/python/iga_run/__init__.py DESTINATION ${IGA_PYTHON_INSTALL_DIR}/iga_run)

  if(BUILD_TESTING)
    # Python's own test runner on python/tests (numbers against the command line's summary.json,
    # matrices read back with SciPy).
    add_test(NAME python_module
             COMMAND ${Python3_EXECUTABLE} -m unittest discover -v -s ${CMAKE_CURRENT_SOURCE_DIR}/python/tests)
    set_tests_properties(python_module PROPERTIES TIMEOUT ${IGA_TEST_TIMEOUT}
      ENVIRONMENT "PYTHONPATH=${CMAKE_BINARY_DIR}/python;IGA_RUN_BINARY=$<TARGET_FILE:iga-run>;IGA_SOURCE_DIR=${CMAKE_CURRENT_SOURCE_DIR}")
    add_dependencies(_iga_run iga-run)
  endif()
endif()
