# Run `particulate FILE`, a case that goes wrong during its time steps, and
# require what check_bad_input.cmake requires of a run (a non-zero exit code,
# the message on the file's first line after "# expect: ", no crash), and
# the time series particle_0.dat of the folder named by 'Directory' intact
# up to the stop: its first row (t = 0) and, as its last line, the note of
# why the run stopped. Called by CTest with -DEXE=... -DFILE=...
file(STRINGS "${FILE}" directory_line REGEX "^ *set Directory *=")
string(REGEX REPLACE "^ *set Directory *= *" "" directory "${directory_line}")
file(REMOVE_RECURSE "${directory}")
set(RUN 1)
include(${CMAKE_CURRENT_LIST_DIR}/../bad_input/check_bad_input.cmake)
file(STRINGS "${directory}/particle_0.dat" rows)
list(GET rows 1 first_row)
list(GET rows -1 last_row)
if(NOT first_row MATCHES "^0 ")
  message(FATAL_ERROR "particle_0.dat lost its first row: ${first_row}")
endif()
if(NOT last_row MATCHES "^# run stopped after t = .*: ${expected}")
  message(FATAL_ERROR "particle_0.dat does not end with why the run "
                      "stopped: ${last_row}")
endif()
