## cmake --install: the headers, the shared library, the polyfrac program and
## the CMake package PolyFrac (target PolyFrac::polyfrac), so that a deal.II
## project can find_package(PolyFrac) (see examples/downstream).
include(CMakePackageConfigHelpers)

set(POLYFRAC_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/PolyFrac)
set(POLYFRAC_DEAL_II_DIR "${deal.II_DIR}")

install(DIRECTORY ${CMAKE_SOURCE_DIR}/include/polyfrac
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS polyfrac EXPORT PolyFracTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS polyfrac-bin RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(EXPORT PolyFracTargets
  NAMESPACE PolyFrac::
  DESTINATION ${POLYFRAC_INSTALL_CMAKEDIR})

configure_package_config_file(${CMAKE_SOURCE_DIR}/cmake/PolyFracConfig.cmake.in
  ${CMAKE_BINARY_DIR}/PolyFracConfig.cmake
  INSTALL_DESTINATION ${POLYFRAC_INSTALL_CMAKEDIR})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/PolyFracConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES
  ${CMAKE_BINARY_DIR}/PolyFracConfig.cmake
  ${CMAKE_BINARY_DIR}/PolyFracConfigVersion.cmake
  DESTINATION ${POLYFRAC_INSTALL_CMAKEDIR})
