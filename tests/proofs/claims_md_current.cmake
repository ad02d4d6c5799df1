# Fails when docs/claims.md differs from `gsdot3 prove --markdown` (regenerate it with that command).
execute_process(COMMAND ${GSDOT3} prove --markdown OUTPUT_FILE ${ACTUAL} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "gsdot3 prove --markdown failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${ACTUAL} ${EXPECTED} RESULT_VARIABLE diff)
if(NOT diff EQUAL 0)
  message(FATAL_ERROR "docs/claims.md is stale: regenerate it with `gsdot3 prove --markdown > docs/claims.md` "
                      "(new output in ${ACTUAL})")
endif()
