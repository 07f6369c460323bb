# Fail when a case file in prm/ starts with more than three comment lines:
# its header says what the case shows, how long it takes and where its
# report is; the rest belongs on the report page or next to the setting it
# explains. Called by CTest with -DCASES=<prm/*.prm separated by '|'>.
string(REPLACE "|" ";" cases "${CASES}")
set(too_long "")
foreach(prm ${cases})
  file(STRINGS "${prm}" lines)
  set(count 0)
  foreach(line ${lines})
    if(NOT line MATCHES "^#")
      break()
    endif()
    math(EXPR count "${count} + 1")
  endforeach()
  if(count GREATER 3)
    string(APPEND too_long "\n  ${prm}: ${count} header lines")
  endif()
endforeach()
if(NOT too_long STREQUAL "")
  message(FATAL_ERROR "case headers longer than three lines:${too_long}")
endif()
