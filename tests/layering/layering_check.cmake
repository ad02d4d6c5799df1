# ctest layering_check: lower layers never include upper ones (the brief; issue 28's "no upward
# include in src/"). Run as `cmake -DSOURCE=<repo> -P layering_check.cmake`
# (-DMIN_FILES=N: the fewest files a whole tree has; the upward fixture sets 1). Each folder of src/ has a
# layer below; a file may #include "M/..." only from its own folder or a folder of a lower layer, so
# folders of one layer do not include each other either. An include belongs to the folder of the file
# it names ("pipeline/NAME.hpp" to the src/pipeline sub-folder that holds it, likewise src/proofs');
# one that names no file of the tree (hwy/, generated headers) is skipped; a folder missing from the
# table fails the check.
set(layers
  "fixed" 0
  "gs_regs" 5
  "normal_encoding" 10 "powervr" 10 "valve" 10
  "gs_arith" 20
  "gs_memory" 30 "gs_methods" 30 "gs_simd" 30 "vectors" 30
  "gs_packets" 40 "proofs/base" 40
  "proofs/two_pass_triangle" 44
  "proofs/proofs" 48
  "gs_cost" 50 "probe" 50
  "pipeline/core" 60
  "pipeline/reference" 70 "pipeline/assets" 70 "pipeline/gs" 70
  "pipeline/schemes" 80
  "pipeline/report" 90
  "cli" 100)
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
  elseif(path MATCHES "^src/(pipeline|proofs)/([a-z_0-9]+)/")
    set(${out} "${CMAKE_MATCH_1}/${CMAKE_MATCH_2}" PARENT_SCOPE)
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
    set(prefix "${CMAKE_MATCH_1}")
    set(header "${CMAKE_MATCH_2}")
    # The file the include names: NAME/... lives in src/NAME/NAME/, src/schemes/NAME/NAME/,
    # src/pipeline/*/NAME/ or src/proofs/*/NAME/, or include/NAME/.
    file(GLOB holder RELATIVE ${SOURCE} ${SOURCE}/include/${prefix}/${header} ${SOURCE}/src/${prefix}/${prefix}/${header}
         ${SOURCE}/src/schemes/${prefix}/${prefix}/${header} ${SOURCE}/src/pipeline/*/${prefix}/${header}
         ${SOURCE}/src/proofs/*/${prefix}/${header})
    if(NOT holder)
      continue()  # not the project's (e.g. hwy/), or generated into the build tree
    endif()
    list(GET holder 0 holder)
    module_of("${holder}" to)
    layer_of("${to}" to_rank)
    if(to_rank STREQUAL "")
      list(APPEND problems "${holder}: folder ${to} has no layer in tests/layering/layering_check.cmake")
      continue()
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
