# SPDX-License-Identifier: Apache-2.0
# ncpost_library(NAME DEPS...): one library per top-level folder, sources = src/*.cpp,
# public headers under include/ncpost/NAME/, alias ncpost::NAME (also the exported name).
# Installed with its headers into the export set ncpostTargets (cmake/ncpost_install.cmake).
function(ncpost_library name)
  file(GLOB_RECURSE _srcs CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/src/*.cpp")
  add_library(ncpost_${name} STATIC ${_srcs})
  add_library(ncpost::${name} ALIAS ncpost_${name})
  set_target_properties(ncpost_${name} PROPERTIES EXPORT_NAME ${name} POSITION_INDEPENDENT_CODE ON)
  target_include_directories(ncpost_${name} PUBLIC
    "$<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>"
    "$<BUILD_INTERFACE:${NCPOST_GENERATED_INCLUDE_DIR}>"
    "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>")
  target_compile_options(ncpost_${name} PRIVATE -Wall -Wextra -Wpedantic -Wno-restrict)
  target_link_libraries(ncpost_${name} PUBLIC ${ARGN})
  install(TARGETS ncpost_${name} EXPORT ncpostTargets
    ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}"
    LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}"
    INCLUDES DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}")
  install(DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}/include/" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}"
    FILES_MATCHING PATTERN "*.hpp")
endfunction()

# ncpost_add_test(FILE DEPS...): one Catch2 executable per *_test.cpp, registered with CTest.
# Each test runs in its own folder, build/test-tmp/<folder>_<name> (also NCPOST_TEST_TMPDIR):
# files a test writes by a relative name land there, so tests run by `ctest -j` cannot collide on
# a file name (two tests once both wrote build/trr_identified.json).
function(ncpost_add_test file)
  get_filename_component(_name "${file}" NAME_WE)
  file(RELATIVE_PATH _rel "${CMAKE_SOURCE_DIR}/tests" "${file}")
  get_filename_component(_dir "${_rel}" DIRECTORY)
  string(REPLACE "/" "_" _prefix "${_dir}")
  set(_target "test_${_prefix}_${_name}")
  set(_tmp "${CMAKE_BINARY_DIR}/test-tmp/${_prefix}_${_name}")
  file(MAKE_DIRECTORY "${_tmp}")
  add_executable(${_target} "${file}")
  target_link_libraries(${_target} PRIVATE ncpost_catch_main ${ARGN})
  target_compile_definitions(${_target} PRIVATE
    NCPOST_SOURCE_DIR="${CMAKE_SOURCE_DIR}"
    NCPOST_BINARY="$<TARGET_FILE:ncpost>"
    NCPOST_TEST_TMPDIR="${_tmp}")
  add_test(NAME "${_prefix}/${_name}" COMMAND ${_target})
  set_tests_properties("${_prefix}/${_name}" PROPERTIES WORKING_DIRECTORY "${_tmp}")
endfunction()
