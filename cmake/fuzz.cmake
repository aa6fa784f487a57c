# libFuzzer targets (scripts/fuzz.sh): each fuzz/*_fuzz.cpp becomes an executable that links only
# the layers it needs, so a clang build of the fuzz targets stays small. Everything compiled in
# this mode carries the fuzzer's coverage hooks and AddressSanitizer + UndefinedBehaviorSanitizer.
option(IGA_FUZZ "Build the libFuzzer targets of fuzz/ (needs clang; see scripts/fuzz.sh)" OFF)
if(IGA_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "IGA_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined
                      -fno-omit-frame-pointer -g -O1)
  add_link_options(-fsanitize=address,undefined)

  # target -> the layers it links; problem_fuzz and petsc_options_fuzz compile the one solver file
  # they exercise (problem_fuzz also the eigen and shell blocks' readers and the integrator objects a parsed
  # problem holds, which need nothing beyond config) instead of linking the whole solver (and with
  # it spaces, assembly, Gmsh meshing, PETSc).
  set(IGA_FUZZ_LAYERS_config_node_fuzz iga_config)
  set(IGA_FUZZ_LAYERS_expression_fuzz iga_config)
  set(IGA_FUZZ_LAYERS_problem_fuzz iga_config)
  set(IGA_FUZZ_SOURCES_problem_fuzz ${CMAKE_CURRENT_SOURCE_DIR}/solver/problem.cpp
                                    ${CMAKE_CURRENT_SOURCE_DIR}/solver/eigen_spec.cpp
                                    ${CMAKE_CURRENT_SOURCE_DIR}/solver/shell_config.cpp
                                    ${CMAKE_CURRENT_SOURCE_DIR}/assembly/integrators.cpp
                                    ${CMAKE_CURRENT_SOURCE_DIR}/assembly/shell_integrators.cpp)
  set(IGA_FUZZ_LAYERS_obj_mesh_fuzz iga_mesh)
  set(IGA_FUZZ_LAYERS_off_mesh_fuzz iga_mesh)
  set(IGA_FUZZ_LAYERS_gismo_xml_fuzz iga_mesh)
  set(IGA_FUZZ_LAYERS_petsc_options_fuzz iga_config)
  set(IGA_FUZZ_SOURCES_petsc_options_fuzz ${CMAKE_CURRENT_SOURCE_DIR}/solver/petsc_option_policy.cpp)
  set(IGA_FUZZ_LAYERS_surface_mesh_fuzz iga_geometry iga_mesh)

  file(GLOB IGA_FUZZ_SOURCES CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/*_fuzz.cpp)
  set(IGA_FUZZ_TARGETS "")
  foreach(src IN LISTS IGA_FUZZ_SOURCES)
    get_filename_component(name ${src} NAME_WE)
    if(NOT DEFINED IGA_FUZZ_LAYERS_${name})
      message(FATAL_ERROR "cmake/fuzz.cmake: say which layers ${name} links (IGA_FUZZ_LAYERS_${name})")
    endif()
    add_executable(${name} ${src} ${IGA_FUZZ_SOURCES_${name}})
    target_link_libraries(${name} PRIVATE ${IGA_FUZZ_LAYERS_${name}})
    target_link_options(${name} PRIVATE -fsanitize=fuzzer)
    list(APPEND IGA_FUZZ_TARGETS ${name})
  endforeach()
  add_custom_target(fuzz_targets DEPENDS ${IGA_FUZZ_TARGETS})
endif()
