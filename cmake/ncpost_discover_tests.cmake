# SPDX-License-Identifier: Apache-2.0
# Run after each build of a test program (cmake -P, from ncpost_add_test_folder in
# ncpost_helpers.cmake): asks the program for the Catch2 test cases of each of its files and writes
# the CTest file that registers every case as a test of its own:
#   name      <folder>/<file>: <case>
#   command   the program, the case's name as a Catch2 test spec (\ , [ ] and a leading - or ~
#             escaped with a backslash), -w NoTests (a name that no longer
#             matches exactly one case fails instead of passing with nothing run)
#   folder    the file's working folder; RESOURCE_LOCK on it, so one file's cases never overlap.
# Written here rather than with Catch2 2.13's catch_discover_tests, which splits a case name at a
# ';' into tests that match nothing (43 of the 408 case names here have one).
#   cost      the case's seconds in tests/test_costs.txt (COSTS) where it is listed: CTest starts the
#             costliest first when the build has no timing of its own (a clean clone)
# Inputs (-D): EXE, the program; FILES, a file of lines "<tag>|<test name prefix>|<folder>";
# OUT, the CTest file to write; COSTS (optional), lines "<seconds>\t<test name>" ('#' comments).
set(_costs "")
if(DEFINED COSTS AND EXISTS "${COSTS}")
  file(STRINGS "${COSTS}" _costs REGEX "^[0-9]")
endif()
file(STRINGS "${FILES}" _lines)
set(_script "")
set(_count 0)
foreach(_line IN LISTS _lines)
  string(REPLACE "|" ";" _fields "${_line}")
  list(GET _fields 0 _tag)
  list(GET _fields 1 _prefix)
  list(GET _fields 2 _dir)
  execute_process(COMMAND "${EXE}" "-#" "[#${_tag}]~[.]" --list-test-names-only
                  OUTPUT_VARIABLE _out RESULT_VARIABLE _rc WORKING_DIRECTORY "${_dir}")
  if(_rc LESS 0 OR NOT _rc MATCHES "^[0-9]+$")
    message(FATAL_ERROR "${EXE} -# [#${_tag}] --list-test-names-only: ${_rc}\n${_out}")
  endif()
  # One case per line. A ';' in a name must not split it: held as a marker while the lines are a list.
  string(REPLACE ";" "<ncpost-semicolon>" _out "${_out}")
  string(REPLACE "\n" ";" _names "${_out}")
  foreach(_name IN LISTS _names)
    if(_name STREQUAL "")
      continue()
    endif()
    string(REPLACE "<ncpost-semicolon>" ";" _name "${_name}")
    string(REPLACE "\\" "\\\\" _spec "${_name}")
    foreach(_c , [ ])
      string(REPLACE "${_c}" "\\${_c}" _spec "${_spec}")
    endforeach()
    if(_spec MATCHES "^[-~]")  # else an option, or an exclusion
      string(PREPEND _spec "\\")
    endif()
    set(_cost "")
    foreach(_entry IN LISTS _costs)
      string(FIND "${_entry}" "\t" _tab)
      math(EXPR _after "${_tab} + 1")
      string(SUBSTRING "${_entry}" ${_after} -1 _listed)
      if(_listed STREQUAL "${_prefix}: ${_name}")
        string(SUBSTRING "${_entry}" 0 ${_tab} _seconds)
        set(_cost " COST ${_seconds}")
        break()
      endif()
    endforeach()
    string(APPEND _script
      "add_test([==[${_prefix}: ${_name}]==] [==[${EXE}]==] [==[${_spec}]==] -w NoTests)\n"
      "set_tests_properties([==[${_prefix}: ${_name}]==] PROPERTIES WORKING_DIRECTORY [==[${_dir}]==] RESOURCE_LOCK [==[${_dir}]==]${_cost})\n")
    math(EXPR _count "${_count} + 1")
  endforeach()
endforeach()
file(WRITE "${OUT}" "${_script}")
message(STATUS "${EXE}: ${_count} test cases")
