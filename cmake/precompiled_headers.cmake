## The deal.II, Trilinos and standard headers that PolyFrac's sources and
## test programs include (directly or through PolyFrac's headers), compiled
## once into the library's precompiled header. Parsing them took about 8 of
## the 10 s that each source file or test program took to compile. The
## headers are the same in every build type; what they expand to (DEBUG,
## sanitizers) follows the build's flags. POLYFRAC_PRECOMPILED_HEADERS=OFF
## turns them off (to check that every file includes what it uses).
option(POLYFRAC_PRECOMPILED_HEADERS
  "Compile the deal.II headers once (cmake/precompiled_headers.cmake)" ON)
set(POLYFRAC_PRECOMPILED_HEADER_LIST
    <deal.II/base/exceptions.h>
    <deal.II/base/function.h>
    <deal.II/base/function_parser.h>
    <deal.II/base/index_set.h>
    <deal.II/base/mpi.h>
    <deal.II/base/parameter_handler.h>
    <deal.II/base/point.h>
    <deal.II/base/tensor.h>
    <deal.II/base/timer.h>
    <deal.II/base/utilities.h>
    <deal.II/grid/tria.h>
    <deal.II/grid/tria_accessor.h>
    <deal.II/grid/tria_iterator.h>
    <deal.II/lac/dynamic_sparsity_pattern.h>
    <deal.II/lac/full_matrix.h>
    <deal.II/lac/sparse_direct.h>
    <deal.II/lac/sparse_matrix.h>
    <deal.II/lac/sparsity_pattern.h>
    <deal.II/lac/trilinos_precondition.h>
    <deal.II/lac/trilinos_sparse_matrix.h>
    <deal.II/lac/trilinos_sparsity_pattern.h>
    <deal.II/lac/trilinos_vector.h>
    <deal.II/lac/vector.h>
    <functional>
    <map>
    <memory>
    <string>
    <vector>)
if(POLYFRAC_PRECOMPILED_HEADERS)
  target_precompile_headers(polyfrac PRIVATE ${POLYFRAC_PRECOMPILED_HEADER_LIST})
  # The programs' copy: compiled with the flags of a program that links the
  # library (the library's own has polyfrac_EXPORTS defined, and GCC refuses
  # a precompiled header whose macros differ).
  file(WRITE ${CMAKE_BINARY_DIR}/polyfrac_pch.cc "")
  add_library(polyfrac_pch OBJECT ${CMAKE_BINARY_DIR}/polyfrac_pch.cc)
  deal_ii_setup_target(polyfrac_pch)
  target_link_libraries(polyfrac_pch polyfrac)
  target_precompile_headers(polyfrac_pch PRIVATE
    ${POLYFRAC_PRECOMPILED_HEADER_LIST})
endif()

# Lets the executable targets of the directories given (below the current
# one) reuse the programs' precompiled header; their flags are those of
# polyfrac_pch (deal_ii_setup_target with the same build type).
function(polyfrac_reuse_precompiled_headers)
  if(NOT POLYFRAC_PRECOMPILED_HEADERS)
    return()
  endif()
  foreach(_dir ${ARGN})
    get_property(_targets DIRECTORY ${_dir} PROPERTY BUILDSYSTEM_TARGETS)
    foreach(_target ${_targets})
      get_target_property(_type ${_target} TYPE)
      if(_type STREQUAL "EXECUTABLE")
        target_precompile_headers(${_target} REUSE_FROM polyfrac_pch)
      endif()
    endforeach()
  endforeach()
endfunction()
