# ctest layering_check: lower layers never include upper ones (the brief; issue 28's "no upward
# include in src/"). Run as `cmake -DSOURCE=<repo> -P layering_check.cmake`
# (-DMIN_FILES=N: the fewest files a whole tree has; the upward fixture sets 1). Each folder of src/ has a
# layer below; a file may #include "M/..." only from its own folder or a folder of a lower layer, so
# folders of one layer do not include each other either. A header "pipeline/NAME.hpp" belongs to the
# src/pipeline sub-folder that holds it. Quoted includes of folders not in the table (e.g. hwy/) are
# not the project's and are skipped; a src folder missing from the table fails the check.
set(layers
  "fixed" 0
  "gs_regs" 1 "normal_encoding" 1 "powervr" 1 "valve" 1
  "gs_arith" 2
  "gs_memory" 3 "gs_methods" 3 "gs_simd" 3 "vectors" 3
  "gs_packets" 4 "proofs" 4
  "gs_cost" 5 "probe" 5
  "pipeline/core" 6
  "pipeline/reference" 7 "pipeline/assets" 7 "pipeline/gs" 7
  "pipeline/schemes" 8
  "pipeline/report" 9
  "cli" 10)
function(layer_of module out)
  list(FIND layers "${module}" at)
  if(at EQUAL -1)
    set(${out} "" PARENT_SCOPE)
  else()
    math(EXPR at "${at} + 1")
    list(GET layers ${at} rank)
    set(${out} ${rank} PARENT_SCOPE)
  endif()
endfunction()
# The folder (module) a file of src/ or include/ belongs to.
function(module_of path out)
  if(path MATCHES "^include/fixed/")
    set(${out} "fixed" PARENT_SCOPE)
  elseif(path MATCHES "^src/schemes/([a-z_0-9]+)/")
    set(${out} "${CMAKE_MATCH_1}" PARENT_SCOPE)
  elseif(path MATCHES "^src/pipeline/([a-z_0-9]+)/")
    set(${out} "pipeline/${CMAKE_MATCH_1}" PARENT_SCOPE)
  elseif(path MATCHES "^src/([a-z_0-9]+)/")
    set(${out} "${CMAKE_MATCH_1}" PARENT_SCOPE)
  else()
    set(${out} "" PARENT_SCOPE)
  endif()
endfunction()

file(GLOB_RECURSE files RELATIVE ${SOURCE} ${SOURCE}/src/*.hpp ${SOURCE}/src/*.cpp ${SOURCE}/include/*.hpp)
list(LENGTH files count)
if(NOT DEFINED MIN_FILES)
  set(MIN_FILES 100)
endif()
if(count LESS MIN_FILES)
  message(FATAL_ERROR "layering_check: found ${count} files under ${SOURCE}/src; expected the whole tree")
endif()
set(problems "")
set(checked 0)
foreach(f IN LISTS files)
  module_of("${f}" from)
  layer_of("${from}" from_rank)
  if(from_rank STREQUAL "")
    list(APPEND problems "${f}: folder ${from} has no layer in tests/layering/layering_check.cmake")
    continue()
  endif()
  file(STRINGS ${SOURCE}/${f} includes REGEX "^[ \t]*#[ \t]*include[ \t]+\"")
  foreach(line IN LISTS includes)
    if(NOT line MATCHES "\"([a-z_0-9]+)/([^\"]+)\"")
      continue()
    endif()
    set(to "${CMAKE_MATCH_1}")
    set(header "${CMAKE_MATCH_2}")
    if(to STREQUAL "pipeline")
      file(GLOB holder RELATIVE ${SOURCE} ${SOURCE}/src/pipeline/*/pipeline/${header})
      if(NOT holder)
        list(APPEND problems "${f}: includes pipeline/${header}, which no src/pipeline folder holds")
        continue()
      endif()
      module_of("${holder}" to)
    endif()
    layer_of("${to}" to_rank)
    if(to_rank STREQUAL "")
      continue()  # not a project folder (e.g. hwy/)
    endif()
    math(EXPR checked "${checked} + 1")
    if(NOT to STREQUAL from AND NOT to_rank LESS from_rank)
      list(APPEND problems "${f} (${from}, layer ${from_rank}) includes ${to} (layer ${to_rank}): ${line}")
    endif()
  endforeach()
endforeach()
if(problems)
  list(JOIN problems "\n  " shown)
  message(FATAL_ERROR "layering_check: includes against the layers:\n  ${shown}")
endif()
message(STATUS "layering_check: ${checked} project includes in ${count} files, none upward or sideways")
