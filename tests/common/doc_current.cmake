# Fails when a generated document differs from what its command prints now (regenerate it with that
# command). -DGSDOT3=the binary -DARGS="prove;--markdown" -DEXPECTED=docs/X.md -DACTUAL=build copy.
execute_process(COMMAND ${GSDOT3} ${ARGS} OUTPUT_FILE ${ACTUAL} RESULT_VARIABLE rc)
list(JOIN ARGS " " command)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "gsdot3 ${command} failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${ACTUAL} ${EXPECTED} RESULT_VARIABLE diff)
if(NOT diff EQUAL 0)
  message(FATAL_ERROR "${EXPECTED} is stale: regenerate it with `gsdot3 ${command} > ${EXPECTED}` "
                      "(new output in ${ACTUAL})")
endif()
