# Run earlier_run.prm of this folder, then `particulate FILE` into the same
# output folder, and require what check_bad_input.cmake requires of a run (a
# non-zero exit code, the message on FILE's first line after "# expect: ",
# no crash) and every file the earlier run wrote unchanged (SHA-256).
# Called by CTest with -DEXE=... -DFILE=...
set(earlier ${CMAKE_CURRENT_LIST_DIR}/earlier_run.prm)
file(STRINGS "${earlier}" directory_line REGEX "^ *set Directory *=")
string(REGEX REPLACE "^ *set Directory *= *" "" directory "${directory_line}")
file(REMOVE_RECURSE "${directory}")
execute_process(COMMAND "${EXE}" "${earlier}" RESULT_VARIABLE result
  OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the earlier run failed:\n${err}")
endif()
file(GLOB_RECURSE written RELATIVE "${CMAKE_CURRENT_BINARY_DIR}"
  "${directory}/*")
list(LENGTH written n_written)
if(n_written LESS 5)
  message(FATAL_ERROR "the earlier run wrote only: ${written}")
endif()
foreach(file ${written})
  file(SHA256 "${file}" hash)
  list(APPEND before "${file}=${hash}")
endforeach()

set(RUN 1)
include(${CMAKE_CURRENT_LIST_DIR}/../bad_input/check_bad_input.cmake)

foreach(entry ${before})
  string(REGEX REPLACE "=[0-9a-f]+$" "" file "${entry}")
  if(NOT EXISTS "${file}")
    message(FATAL_ERROR "the refused run removed ${file}")
  endif()
  file(SHA256 "${file}" hash)
  if(NOT entry STREQUAL "${file}=${hash}")
    message(FATAL_ERROR "the refused run changed ${file}")
  endif()
endforeach()
message(STATUS "${n_written} files of the earlier run unchanged")
