## The test library/downstream (cmake -P): installs the PolyFrac build
## POLYFRAC_BINARY_DIR into POLYFRAC_BINARY_DIR/install-check, checks the
## installed tree, then configures, builds and runs DOWNSTREAM_SOURCE_DIR
## against the installed package only (with the build's compiler, flags and
## build type). Fails on the first step that fails.
set(prefix ${POLYFRAC_BINARY_DIR}/install-check)
set(build ${POLYFRAC_BINARY_DIR}/downstream-build)

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "Failed (exit status ${status}): ${ARGN}")
  endif()
endfunction()

run(${CMAKE_COMMAND} --install ${POLYFRAC_BINARY_DIR} --prefix ${prefix})

file(GLOB_RECURSE config ${prefix}/*/PolyFracConfig.cmake)
list(LENGTH config n_config)
if(NOT n_config EQUAL 1)
  message(FATAL_ERROR "Expected one PolyFracConfig.cmake in ${prefix}, found: ${config}")
endif()
get_filename_component(config_dir ${config} DIRECTORY)
foreach(file
    ${config_dir}/PolyFracConfigVersion.cmake
    ${config_dir}/PolyFracTargets.cmake
    ${prefix}/bin/polyfrac
    ${prefix}/include/polyfrac/mesh/polytopal_mesh.h
    ${prefix}/include/polyfrac/app/simulator.h)
  if(NOT EXISTS ${file})
    message(FATAL_ERROR "Not installed: ${file}")
  endif()
endforeach()
file(GLOB library ${prefix}/lib*/libpolyfrac.so ${prefix}/lib/*/libpolyfrac.so)
if(NOT library)
  message(FATAL_ERROR "Not installed: libpolyfrac.so under ${prefix}")
endif()

# The installed program runs from the install tree (RPATH $ORIGIN/../lib).
run(${prefix}/bin/polyfrac --print-parameters 2 OUTPUT_QUIET)

run(${CMAKE_COMMAND} -S ${DOWNSTREAM_SOURCE_DIR} -B ${build}
  -DCMAKE_PREFIX_PATH=${prefix}
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
  -DCMAKE_BUILD_TYPE=${BUILD_TYPE}
  -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
  "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}"
  "-DCMAKE_EXE_LINKER_FLAGS=${EXE_LINKER_FLAGS}"
  -DEXPECT_GMSH_API=${EXPECT_GMSH_API})

# The package found must be the installed one, not the build tree.
file(STRINGS ${build}/CMakeCache.txt found REGEX "^PolyFrac_DIR:")
string(REGEX REPLACE "^PolyFrac_DIR:[A-Z]+=" "" found "${found}")
if(NOT found STREQUAL config_dir)
  message(FATAL_ERROR "The downstream project found PolyFrac in <${found}>, "
    "not in the install tree <${config_dir}>.")
endif()

run(${CMAKE_COMMAND} --build ${build})
run(${build}/downstream)
