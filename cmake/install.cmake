# `cmake --install build [--prefix P]` installs:
#   bin/iga-run, bin/iga-gmsh-worker
#   lib/libiga_<layer>.a                      the layer libraries (static)
#   include/iga_run/<layer>/...               every header of the layers, paths as in the source tree
#   lib/cmake/iga_run/iga_runConfig.cmake     find_package(iga_run) -> target iga_run::iga_run
# A project links iga_run::iga_run and includes e.g. "solver/study.hpp" (docs/library.md).
include(CMakePackageConfigHelpers)

set(IGA_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/iga_run)
set(iga_layer_targets "")
foreach(layer IN LISTS IGA_LAYERS)
  list(APPEND iga_layer_targets iga_${layer})
  file(GLOB_RECURSE layer_headers RELATIVE ${CMAKE_CURRENT_SOURCE_DIR} CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${layer}/*.hpp)
  # Internal to the solver's PETSc files (it includes PETSc's headers): not part of the library's interface.
  list(FILTER layer_headers EXCLUDE REGEX "solver/petsc_distribution\\.hpp$")
  foreach(header IN LISTS layer_headers)
    get_filename_component(folder ${header} DIRECTORY)
    install(FILES ${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/iga_run/${folder})
  endforeach()
endforeach()

if(IGA_WITH_PETSC)
  list(APPEND iga_layer_targets iga_petsc)  # the PETSc implementation, linked by iga_run::iga_run
  # The plugin iga-run opens (solver/petsc_plugin.cpp looks in ../lib/iga-run/ from the executable).
  install(TARGETS iga-run-petsc LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/iga-run)
endif()
install(TARGETS ${iga_layer_targets} igarun EXPORT iga_runTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS iga-run iga-gmsh-worker RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(EXPORT iga_runTargets NAMESPACE iga_run:: DESTINATION ${IGA_INSTALL_CMAKEDIR})

configure_package_config_file(${CMAKE_CURRENT_SOURCE_DIR}/cmake/iga_runConfig.cmake.in
                              ${CMAKE_CURRENT_BINARY_DIR}/iga_runConfig.cmake
                              INSTALL_DESTINATION ${IGA_INSTALL_CMAKEDIR})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/iga_runConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/iga_runConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/iga_runConfigVersion.cmake
        DESTINATION ${IGA_INSTALL_CMAKEDIR})
