#--------------------------------------------------------------------------
# setupTests.cmake — one CTest case per setup in the table, read at ctest time
#--------------------------------------------------------------------------
# Included by ctest (TEST_INCLUDE_FILES, set in tests/CMakeLists.txt), so the
# list comes from the program itself (`ample --list`, i.e. setupsTable() in
# setups/setups.cpp): a new line in the table is a new test, setup.<name>,
# with no edit here. Each runs the setup with its defaults, or with the smaller
# parameters of SETUP_SMALL, and passes when every load step converges (exit 0).
# Inputs (from setupTests-generated.cmake): AMPLE (the program), CMAKE_BIN, SETUP_OUT (a
#   folder for the runs), SETUP_SMALL ("name|name=value ..." per entry), SETUP_SKIP (the
#   "needs exercise" pattern of the student copy, docs/exercises.md)
# Outputs: the tests setup.<name> (label setup); setup.table if the list fails
#--------------------------------------------------------------------------
execute_process(COMMAND "${AMPLE}" --list OUTPUT_VARIABLE listing RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  add_test(setup.table "${CMAKE_BIN}" -E echo "cannot run ${AMPLE} --list: build the program first")
  set_tests_properties(setup.table PROPERTIES FAIL_REGULAR_EXPRESSION ".")  # fails, with the reason
  return()
endif()
string(REGEX MATCHALL "(^|\n)  [A-Za-z0-9_]+\t" lines "${listing}")
set(names "")
foreach(line IN LISTS lines)
  string(STRIP "${line}" name)
  list(APPEND names "${name}")
endforeach()

foreach(entry IN LISTS SETUP_SMALL)               # a small run for a setup whose defaults take long
  string(REPLACE "|" ";" parts "${entry}")
  list(GET parts 0 name)
  list(GET parts 1 args)
  set(small_${name} "${args}")
  list(FIND names "${name}" known)
  if(known EQUAL -1)                              # a stale entry: say so instead of passing silently
    add_test(setup.${name} "${CMAKE_BIN}" -E echo "SETUP_SMALL names '${name}', not in `ample --list`")
    set_tests_properties(setup.${name} PROPERTIES FAIL_REGULAR_EXPRESSION "." LABELS setup)
  endif()
endforeach()

foreach(name IN LISTS names)
  separate_arguments(args UNIX_COMMAND "${small_${name}}")
  set(vtk --vtk 0)                                # unless the entry has its own (an option is given once)
  list(FIND args "--vtk" own)
  if(NOT own EQUAL -1)
    set(vtk "")
  endif()
  add_test(setup.${name} "${AMPLE}" ${name} ${vtk} --quiet --out "${SETUP_OUT}/setup_${name}" ${args})
  # the student copy: a run that reaches a blanked exercise prints "needs exercise X" (skipped)
  set_tests_properties(setup.${name} PROPERTIES LABELS setup SKIP_REGULAR_EXPRESSION "${SETUP_SKIP}")
endforeach()
