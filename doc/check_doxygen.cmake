## Runs doxygen on DOXYFILE and fails if it reports a warning (written to
## WARNINGS by the Doxyfile) or if doxygen is missing.
if(NOT DOXYGEN_EXECUTABLE)
  message(FATAL_ERROR "doxygen not found: apt-get install doxygen "
    "(scripts/setup.sh installs it), then configure again.")
endif()
file(REMOVE ${WARNINGS})
execute_process(COMMAND ${DOXYGEN_EXECUTABLE} ${DOXYFILE}
  RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "doxygen failed (exit status ${status}).")
endif()
file(READ ${WARNINGS} log)
if(NOT log STREQUAL "")
  message(FATAL_ERROR "doxygen warnings (document every public member of "
    "include/):\n${log}")
endif()
message(STATUS "doxygen: no warnings")
