# ncpost_library(NAME DEPS...): one library per top-level folder, sources = src/*.cpp,
# public headers under include/ncpost/NAME/, alias ncpost::NAME.
function(ncpost_library name)
  file(GLOB_RECURSE _srcs CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/src/*.cpp")
  add_library(ncpost_${name} STATIC ${_srcs})
  add_library(ncpost::${name} ALIAS ncpost_${name})
  target_include_directories(ncpost_${name} PUBLIC "${CMAKE_CURRENT_SOURCE_DIR}/include")
  target_compile_options(ncpost_${name} PRIVATE -Wall -Wextra -Wpedantic -Wno-restrict)
  target_link_libraries(ncpost_${name} PUBLIC ${ARGN})
endfunction()

# ncpost_add_test(FILE DEPS...): one Catch2 executable per *_test.cpp, registered with CTest.
function(ncpost_add_test file)
  get_filename_component(_name "${file}" NAME_WE)
  file(RELATIVE_PATH _rel "${CMAKE_SOURCE_DIR}/tests" "${file}")
  get_filename_component(_dir "${_rel}" DIRECTORY)
  string(REPLACE "/" "_" _prefix "${_dir}")
  set(_target "test_${_prefix}_${_name}")
  add_executable(${_target} "${file}")
  target_link_libraries(${_target} PRIVATE ncpost_catch_main ${ARGN})
  target_compile_definitions(${_target} PRIVATE
    NCPOST_SOURCE_DIR="${CMAKE_SOURCE_DIR}"
    NCPOST_BINARY="$<TARGET_FILE:ncpost>")
  add_test(NAME "${_prefix}/${_name}" COMMAND ${_target})
  set_tests_properties("${_prefix}/${_name}" PROPERTIES WORKING_DIRECTORY "${CMAKE_BINARY_DIR}")
endfunction()
