# Fail when doc/user/parameters.md differs from what the code generates.
# Called by CTest with -DEXE=<particulate> -DDOC=<doc/user/parameters.md>.
execute_process(COMMAND "${EXE}" --print-parameters=markdown
  RESULT_VARIABLE result OUTPUT_VARIABLE generated)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "particulate --print-parameters=markdown failed")
endif()
file(READ "${DOC}" committed)
if(NOT generated STREQUAL committed)
  message(FATAL_ERROR "doc/user/parameters.md is stale: run "
    "scripts/generate-parameter-doc.sh and commit the result.")
endif()
