# Runs one example program and compares its standard output with a file of expected output.
#
#   cmake -DPROGRAM=exe [-DARGS=a;b] -DEXPECTED=file.txt -DACTUAL=out.txt [-DFILTER=regex]
#         -P check_output.cmake
#
# Lines of the expected file that start with '#' are comments (the hand computations that
# justify the values) and are left out of the comparison. With FILTER, only the output lines
# that start with a match of FILTER are compared (they must contain no ';'). The comparison is
# exact; the program's whole output is kept in ACTUAL for a diff.

foreach(variable PROGRAM EXPECTED ACTUAL)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "check_output.cmake: ${variable} is not set")
  endif()
endforeach()

execute_process(COMMAND "${PROGRAM}" ${ARGS} OUTPUT_VARIABLE output ERROR_VARIABLE errors
                RESULT_VARIABLE status)
file(WRITE "${ACTUAL}" "${output}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} exited with ${status}\n${errors}\nits output:\n${output}")
endif()

if(DEFINED FILTER AND NOT FILTER STREQUAL "")
  string(REGEX MATCHALL "\n${FILTER}[^\n]*" kept "\n${output}")
  string(REPLACE ";" "" kept "${kept}")
  string(REGEX REPLACE "^\n" "" compared "${kept}\n")
else()
  set(compared "${output}")
endif()

file(READ "${EXPECTED}" expected)
string(REGEX REPLACE "\n#[^\n]*" "" expected "\n${expected}")
string(REGEX REPLACE "^\n" "" expected "${expected}")

if(NOT compared STREQUAL expected)
  message(FATAL_ERROR "the output of ${PROGRAM} differs from ${EXPECTED}\n"
                      "--- expected (comments left out) ---\n${expected}"
                      "--- compared output ---\n${compared}"
                      "(whole output in ${ACTUAL})")
endif()
message(STATUS "output matches ${EXPECTED}")
