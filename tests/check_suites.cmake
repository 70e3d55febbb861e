# ctest's suites_registered: the test suites raster_tests holds (--list-test-suites) must
# be exactly those tests/suites.cmake registered, so none compiles and never runs.
execute_process(COMMAND ${BINARY} --list-test-suites --no-intro --no-version
                OUTPUT_VARIABLE listed RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${BINARY} --list-test-suites failed (${status})")
endif()
string(REGEX MATCHALL "\n[a-z0-9_]+" names "\n${listed}")
set(held "")
foreach(name ${names})
  string(STRIP "${name}" name)
  list(APPEND held ${name})
endforeach()
list(REMOVE_DUPLICATES held)
list(SORT held)
if(NOT "${held}" STREQUAL "${EXPECTED}")
  message(FATAL_ERROR "test suites in the binary: ${held}\nregistered with ctest: ${EXPECTED}")
endif()
message(STATUS "${held}")
