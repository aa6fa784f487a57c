# The layers of iga-run, bottom to top, and what each may include. A file's folder says what it may
# include: `#include "X/..."` in a file of layer L is allowed only when X is L itself or listed
# below for L. Checked at configure time (check_layers) and again by the ctest `layering`.
#
#   config      YAML access, errors with locations, symbolic expressions
#   quadrature  rules on reference cells and sub-cells
#   mesh        mesh files, Gmsh, validation of planar meshes
#   geometry    smooth geometry built from meshes (G1 surfaces from triangle meshes in 3D)
#   spaces      the Space interface and shared evaluation helpers; one folder per space
#   assembly    sparsity, integrators, assembler, boundary conditions, norms, estimators
#   solver      problem description, linear solvers, problem solve, study loop, adaptivity
#   output      VTK, plot, tables and summary, staged output directory
#   app         the command line
cmake_policy(SET CMP0057 NEW)  # if(... IN_LIST ...) also in script mode
set(IGA_LAYERS config quadrature mesh geometry spaces assembly solver output app)
set(IGA_LAYER_USES_config "")
set(IGA_LAYER_USES_quadrature "")
set(IGA_LAYER_USES_mesh config)
set(IGA_LAYER_USES_geometry config quadrature mesh)
set(IGA_LAYER_USES_spaces config quadrature mesh geometry)
set(IGA_LAYER_USES_assembly config quadrature spaces)
set(IGA_LAYER_USES_solver config quadrature spaces assembly)
set(IGA_LAYER_USES_output config quadrature geometry spaces assembly solver)
set(IGA_LAYER_USES_app config quadrature mesh geometry spaces assembly solver output)
# Layers that must not name a space: they may include the interface (spaces/*.hpp) but no file of
# a space's own folder (spaces/NAME/...).
set(IGA_SPACE_BLIND_LAYERS assembly solver output app)

# Every violation in the tree under `root`, one line each ("file: includes X").
function(iga_layer_violations root out_var)
  set(violations "")
  foreach(layer IN LISTS IGA_LAYERS)
    file(GLOB_RECURSE files "${root}/${layer}/*.hpp" "${root}/${layer}/*.cpp")
    set(allowed ${layer} ${IGA_LAYER_USES_${layer}})
    foreach(f IN LISTS files)
      file(STRINGS "${f}" includes REGEX "^[ \t]*#[ \t]*include[ \t]+\"[^\"]+\"")
      file(RELATIVE_PATH rel "${root}" "${f}")
      foreach(line IN LISTS includes)
        string(REGEX REPLACE "^[^\"]*\"([^\"]+)\".*$" "\\1" target "${line}")
        string(REGEX MATCH "^[a-z_0-9]+/" top "${target}")
        if(top STREQUAL "")
          list(APPEND violations "${rel}: includes \"${target}\" (write the path from the project root)")
          continue()
        endif()
        string(REGEX REPLACE "/$" "" top "${top}")
        if(NOT top IN_LIST IGA_LAYERS)
          continue()  # not a layer (e.g. tests/ support never appears in the library)
        endif()
        if(NOT top IN_LIST allowed)
          list(JOIN allowed ", " allowed_text)
          list(APPEND violations "${rel}: includes \"${target}\" (${layer}/ may use: ${allowed_text})")
        elseif(top STREQUAL "spaces" AND layer IN_LIST IGA_SPACE_BLIND_LAYERS
               AND target MATCHES "^spaces/[^/]+/")
          list(APPEND violations "${rel}: includes \"${target}\" (${layer}/ may use the Space interface only)")
        endif()
      endforeach()
    endforeach()
  endforeach()
  set(${out_var} "${violations}" PARENT_SCOPE)
endfunction()

# Fail (configure or test) with every violation listed.
function(iga_check_layers root)
  iga_layer_violations("${root}" violations)
  if(violations)
    list(JOIN violations "\n  " text)
    message(FATAL_ERROR "layer rule broken (see cmake/layers.cmake):\n  ${text}")
  endif()
endfunction()

# `cmake -DIGA_ROOT=... -P cmake/layers.cmake` runs the check as a script (the ctest `layering`).
if(CMAKE_SCRIPT_MODE_FILE AND IGA_ROOT)
  cmake_policy(VERSION 3.25)
  iga_check_layers("${IGA_ROOT}")
  message(STATUS "layer rule holds")
endif()
