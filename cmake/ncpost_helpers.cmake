# SPDX-License-Identifier: Apache-2.0
# The standard and third-party headers of the libraries' precompiled headers (ncpost_library, and
# ncpost_compensation's own, compensation/CMakeLists.txt).
set(NCPOST_LIBRARY_PCH_HEADERS <fmt/format.h> <algorithm> <array> <cmath> <map> <memory> <optional> <sstream> <string>
    <vector>)

# ncpost_library(NAME [PCH_FROM TARGET] DEPS...): one library per top-level folder, sources = src/*.cpp,
# public headers under include/ncpost/NAME/, alias ncpost::NAME (also the exported name).
# Installed with its headers into the export set ncpostTargets (cmake/ncpost_install.cmake).
# PCH_FROM: the units start from TARGET's precompiled header instead of building one of their own
# (issue 26: each took 10 to 16 s of compiler time). GCC takes a precompiled header only if every
# macro defined when it was built is defined the same way (-Winvalid-pch says so when not): the
# libraries that link ncpost::machines all have its definitions (FMT_SHARED, TOML_*); extra
# ones (BOOST_ALL_NO_LIB) do not matter.
function(ncpost_library name)
  cmake_parse_arguments(PARSE_ARGV 1 _arg "" "PCH_FROM" "")
  set(ARGN ${_arg_UNPARSED_ARGUMENTS})
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
  # the heavy headers nearly every unit includes, parsed once per library (issue 26); Eigen where
  # the library sees it (its own dependency, or through another ncpost library)
  if(_arg_PCH_FROM)
    ncpost_precompile(ncpost_${name} REUSE_FROM ${_arg_PCH_FROM})
  else()
    set(_eigen "")
    if(ARGN MATCHES "Eigen3::Eigen|ncpost::")
      set(_eigen <Eigen/Dense>)
    endif()
    ncpost_precompile(ncpost_${name} ${_eigen} ${NCPOST_LIBRARY_PCH_HEADERS})
  endif()
  ncpost_unity(ncpost_${name})
  install(TARGETS ncpost_${name} EXPORT ncpostTargets
    ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}"
    LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}"
    INCLUDES DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}")
  install(DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}/include/" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}"
    FILES_MATCHING PATTERN "*.hpp")
endfunction()

# The flags every test unit is compiled with (a precompiled header is only used with the same).
macro(ncpost_test_flags target)
  target_link_libraries(${target} PRIVATE ncpost_catch_main ${ARGN})
  # Test code is built at -O1: it calls the product's libraries (built -O3) and holds little hot
  # code of its own, while -O3 on Catch2's expanded assertions cost a third of the test build.
  target_compile_options(${target} PRIVATE -O1)
  target_compile_definitions(${target} PRIVATE NCPOST_SOURCE_DIR="${CMAKE_SOURCE_DIR}" NCPOST_BINARY="$<TARGET_FILE:ncpost>")
endmacro()

# ncpost_add_test_folder(FOLDER FILES... DEPS deps...): the *_test.cpp FILES of tests/FOLDER/ as
# one Catch2 program, test_FOLDER (a few programs to link instead of one per file). CTest lists each
# TEST_CASE on its own, named "<folder>/<file>: <case>" (cmake/ncpost_discover_tests.cmake, after
# each build), and runs it in its file's own folder, build/test-tmp/<folder>_<file> (also
# NCPOST_TEST_TMP_ROOT/<folder>_<file>): files a test writes by a relative name cannot collide with another file's
# under `ctest -j`, and the cases of one file never run at the same time (a RESOURCE_LOCK on that
# folder), as when each file was a program of its own. Hidden cases ([.]) are not registered.
# One file's cases by hand: `build/tests/test_FOLDER -# "[#<file>]"`.
function(ncpost_add_test_folder folder)
  cmake_parse_arguments(PARSE_ARGV 1 _arg "" "" "DEPS")
  if(NOT TARGET ncpost_test_pch)  # the test programs' precompiled header, built once for all
    file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/ncpost_test_pch.cpp" "// the tests' precompiled header\n")
    add_library(ncpost_test_pch OBJECT "${CMAKE_CURRENT_BINARY_DIR}/ncpost_test_pch.cpp")
    ncpost_test_flags(ncpost_test_pch ${_arg_DEPS})
    ncpost_precompile(ncpost_test_pch <catch2/catch.hpp> <Eigen/Dense> <fmt/format.h> <algorithm> <cmath>
                      <filesystem> <fstream> <functional> <map> <optional> <regex> <sstream> <string> <vector>)
  endif()
  set(_target "test_${folder}")
  add_executable(${_target} ${_arg_UNPARSED_ARGUMENTS})
  ncpost_test_flags(${_target} ${_arg_DEPS})
  ncpost_precompile(${_target} REUSE_FROM ncpost_test_pch)
  ncpost_test_units(${_target} "${CMAKE_CURRENT_SOURCE_DIR}/${folder}" ${_arg_UNPARSED_ARGUMENTS})
  set(_seen "")
  set(_files_list "")
  foreach(_file ${_arg_UNPARSED_ARGUMENTS})
    get_filename_component(_name "${_file}" NAME_WE)
    file(RELATIVE_PATH _rel "${CMAKE_SOURCE_DIR}/tests" "${_file}")
    get_filename_component(_dir "${_rel}" DIRECTORY)
    string(REPLACE "/" "_" _prefix "${_dir}")
    if(_name IN_LIST _seen)  # Catch2's file tag [#<file>] names the file without its folder
      message(FATAL_ERROR "tests/${folder}/: two test files named ${_name}.cpp; rename one")
    endif()
    list(APPEND _seen "${_name}")
    set(_tmp "${CMAKE_BINARY_DIR}/test-tmp/${_prefix}_${_name}")
    file(MAKE_DIRECTORY "${_tmp}")
    string(APPEND _files_list "${_name}|${_dir}/${_name}|${_tmp}\n")
  endforeach()
  set(_files "${CMAKE_CURRENT_BINARY_DIR}/${_target}_files.txt")
  set(_ctest "${CMAKE_CURRENT_BINARY_DIR}/${_target}_tests.cmake")
  file(WRITE "${_files}" "${_files_list}")
  add_custom_command(TARGET ${_target} POST_BUILD BYPRODUCTS "${_ctest}"
    COMMAND "${CMAKE_COMMAND}" -D "EXE=$<TARGET_FILE:${_target}>" -D "FILES=${_files}" -D "OUT=${_ctest}"
            -D "COSTS=${PROJECT_SOURCE_DIR}/tests/test_costs.txt"
            -P "${PROJECT_SOURCE_DIR}/cmake/ncpost_discover_tests.cmake"
    VERBATIM)
  set(_include "${CMAKE_CURRENT_BINARY_DIR}/${_target}_include.cmake")
  file(WRITE "${_include}" "if(EXISTS \"${_ctest}\")\n  include(\"${_ctest}\")\nelse()\n"
                           "  add_test(${_target}_NOT_BUILT ${_target}_NOT_BUILT)\nendif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${_include}")
endfunction()

# ncpost_precompile(TARGET HEADERS... | TARGET REUSE_FROM OTHER): TARGET's units start from a
# precompiled header of cmake/eigen_checks.hpp and HEADERS (heavy third-party and standard headers
# most of its units include: parsed once instead of once per unit), or from OTHER's (same flags).
# GCC uses a precompiled header only if nothing comes before it, so the -include of
# eigen_checks.hpp that every unit gets (CMakeLists.txt) moves into the header, first as before.
function(ncpost_precompile target)
  cmake_parse_arguments(PARSE_ARGV 1 _arg "" "REUSE_FROM" "")
  get_target_property(_opts ${target} COMPILE_OPTIONS)
  if(_opts)
    list(FILTER _opts EXCLUDE REGEX "eigen_checks\\.hpp")
    set_target_properties(${target} PROPERTIES COMPILE_OPTIONS "${_opts}")
  endif()
  if(_arg_REUSE_FROM)
    target_precompile_headers(${target} REUSE_FROM ${_arg_REUSE_FROM})
  else()
    target_precompile_headers(${target} PRIVATE "${PROJECT_SOURCE_DIR}/cmake/eigen_checks.hpp" ${_arg_UNPARSED_ARGUMENTS})
  endif()
  # ccache caches units built on a precompiled header only with this sloppiness (ccache manual,
  # "Precompiled headers"): given here to these targets when ccache is the launcher.
  if(CMAKE_CXX_COMPILER_LAUNCHER MATCHES "ccache")
    set_target_properties(${target} PROPERTIES CXX_COMPILER_LAUNCHER
      "${CMAKE_COMMAND};-E;env;CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime;${CMAKE_CXX_COMPILER_LAUNCHER}")
  endif()
endfunction()

# ncpost_test_units(TARGET FOLDER FILES...): TARGET's test files are compiled NCPOST_TEST_UNITY_BATCH to a unit (CMake's
# unity build): Catch2's, Eigen's and the library headers' inline code is then compiled once for all the
# files instead of once for each (issue 26). Each file stays a namespace of its own
# (NCPOST_UNITY_ID, one per file), so helpers of the same name in two files, or a `using
# namespace` in one, do not meet; every header any file of the folder includes is included first,
# outside those namespaces (a generated header, remade when a test file changes).
function(ncpost_test_units target folder)
  set(_incs "")
  foreach(_file ${ARGN})
    file(STRINGS "${_file}" _lines REGEX "^#include")
    list(APPEND _incs ${_lines})
  endforeach()
  list(REMOVE_DUPLICATES _incs)
  string(REPLACE ";" "\n" _text "${_incs}")
  set(_header "${CMAKE_CURRENT_BINARY_DIR}/${target}_includes.hpp")
  file(CONFIGURE OUTPUT "${_header}" CONTENT "// generated (ncpost_test_units): every header the files of ${target} include\n#pragma once\n${_text}\n" @ONLY)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${ARGN})
  target_include_directories(${target} PRIVATE "${folder}")
  target_compile_definitions(${target} PRIVATE NCPOST_TEST_TMP_ROOT="${CMAKE_BINARY_DIR}/test-tmp")
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${NCPOST_TEST_UNITY_BATCH} UNITY_BUILD_UNIQUE_ID NCPOST_UNITY_ID
    UNITY_BUILD_CODE_BEFORE_INCLUDE "#include \"${_header}\"\nnamespace NCPOST_UNITY_ID {"
    UNITY_BUILD_CODE_AFTER_INCLUDE "}  // namespace NCPOST_UNITY_ID")
endfunction()

# ncpost_unity(TARGET): TARGET's files compiled up to NCPOST_UNITY_BATCH to a unit when NCPOST_UNITY is
# ON (CMake's unity build, in groups): the files of one folder only, in their order, so that a unit
# never mixes two folders (the fuzz build, tests/fuzz/CMakeLists.txt, replaces every unit of
# postproc/src/read/ by its own instrumented objects). Files of one folder may then meet in one
# unit: names local to a file (an anonymous namespace, `static`) must differ between the files of a
# folder, as the build checks. Files marked SKIP_UNITY_BUILD_INCLUSION stay units of their own.
function(ncpost_unity target)
  if(NOT NCPOST_UNITY)
    return()
  endif()
  get_target_property(_srcs ${target} SOURCES)
  set(_dirs "")
  foreach(_src ${_srcs})
    if(_src MATCHES "\\.cpp$")
      get_filename_component(_dir "${_src}" DIRECTORY)
      string(MAKE_C_IDENTIFIER "${_dir}" _key)
      list(APPEND _in_${_key} "${_src}")
      list(APPEND _dirs "${_key}")
    endif()
  endforeach()
  list(REMOVE_DUPLICATES _dirs)
  set(_group 0)
  foreach(_key ${_dirs})
    set(_count 0)
    foreach(_src ${_in_${_key}})
      if(_count EQUAL NCPOST_UNITY_BATCH)
        math(EXPR _group "${_group} + 1")
        set(_count 0)
      endif()
      set_source_files_properties("${_src}" TARGET_DIRECTORY ${target} PROPERTIES UNITY_GROUP "${target}_${_group}")
      math(EXPR _count "${_count} + 1")
    endforeach()
    math(EXPR _group "${_group} + 1")
  endforeach()
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_MODE GROUP)
  # a type of one file holding a type of that file's anonymous namespace is fine in a unit of
  # several files too (GCC warns because the file is then an included one)
  target_compile_options(${target} PRIVATE -Wno-subobject-linkage)
endfunction()
