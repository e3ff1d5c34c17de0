# SPDX-License-Identifier: Apache-2.0
# Installation: `cmake --install build --prefix P` puts the ncpost executable in P/bin, the public
# headers in P/include/ncpost/, the static libraries in P/lib, and the CMake package in
# P/lib/cmake/ncpost/ (ncpostConfig.cmake, ncpostConfigVersion.cmake, ncpostTargets.cmake), so that
# another project writes find_package(ncpost CONFIG REQUIRED) and links ncpost::ncpost.
include(CMakePackageConfigHelpers)

# ncpost::ncpost: every library plus the umbrella header <ncpost/ncpost.hpp> and <ncpost/version.hpp>.
add_library(ncpost_all INTERFACE)
add_library(ncpost::ncpost ALIAS ncpost_all)
set_target_properties(ncpost_all PROPERTIES EXPORT_NAME ncpost)
target_include_directories(ncpost_all INTERFACE
  "$<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>"
  "$<BUILD_INTERFACE:${NCPOST_GENERATED_INCLUDE_DIR}>"
  "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>")
target_link_libraries(ncpost_all INTERFACE ncpost::postproc ncpost::compensation ncpost::machines ncpost::kinematics ncpost::report)
target_compile_features(ncpost_all INTERFACE cxx_std_20)

install(TARGETS ncpost_all EXPORT ncpostTargets)
install(TARGETS ncpost RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
install(DIRECTORY "${PROJECT_SOURCE_DIR}/include/" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}")
install(FILES "${NCPOST_GENERATED_INCLUDE_DIR}/ncpost/version.hpp" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/ncpost")

set(NCPOST_CMAKE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/ncpost")
install(EXPORT ncpostTargets NAMESPACE ncpost:: DESTINATION "${NCPOST_CMAKE_DIR}")
configure_package_config_file("${PROJECT_SOURCE_DIR}/cmake/ncpostConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/ncpostConfig.cmake"
  INSTALL_DESTINATION "${NCPOST_CMAKE_DIR}"
  PATH_VARS CMAKE_INSTALL_INCLUDEDIR)
# 0.x: a minor version may change the API, so only the same MAJOR.MINOR is compatible.
write_basic_package_version_file("${PROJECT_BINARY_DIR}/ncpostConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}" COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/ncpostConfig.cmake" "${PROJECT_BINARY_DIR}/ncpostConfigVersion.cmake"
  DESTINATION "${NCPOST_CMAKE_DIR}")
install(FILES "${PROJECT_SOURCE_DIR}/LICENSE" DESTINATION "${CMAKE_INSTALL_DATADIR}/doc/ncpost")
