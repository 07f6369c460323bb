# Run `particulate --validate FILE` (with -DRUN=1: `particulate FILE`, for
# what only the run's set-up can see) and require a non-zero exit code and
# the message given on the file's first line after "# expect: " (a regular
# expression), or given as -DEXPECT=... Called by CTest with -DEXE=...
# -DFILE=...
if(DEFINED EXPECT)
  set(expected "${EXPECT}")
else()
  file(STRINGS "${FILE}" first_line LIMIT_COUNT 1)
  string(REGEX REPLACE "^# expect: " "" expected "${first_line}")
endif()
if(DEFINED RUN)
  set(mode "")
else()
  set(mode --validate)
endif()
execute_process(COMMAND "${EXE}" ${mode} "${FILE}"
  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
string(REPLACE "\n" " " flat "${all}")
if(result EQUAL 0)
  message(FATAL_ERROR "accepted a broken file:\n${all}")
endif()
if(NOT flat MATCHES "${expected}")
  message(FATAL_ERROR "message does not match '${expected}':\n${all}")
endif()
if(all MATCHES "Stacktrace|Segmentation|Aborted")
  message(FATAL_ERROR "crashed instead of a clean message:\n${all}")
endif()
message(STATUS "rejected with: ${all}")
