# ctest format_check: every C++ file of the project is laid out as .clang-format says (120 columns,
# issue 28). Run as `cmake -DSOURCE=<repo> -DCLANG_FORMAT=<exe> -P format_check.cmake`; it lists the
# files clang-format would change and fails, so the fix is `clang-format -i` on them.
file(GLOB_RECURSE files RELATIVE ${SOURCE}
  ${SOURCE}/src/*.cpp ${SOURCE}/src/*.hpp ${SOURCE}/include/*.hpp ${SOURCE}/include/*.h
  ${SOURCE}/tests/*.cpp ${SOURCE}/tests/*.hpp ${SOURCE}/fuzz/*.cpp ${SOURCE}/fuzz/*.hpp
  ${SOURCE}/bench/*.cpp ${SOURCE}/tools/*.cpp ${SOURCE}/tools/*.hpp)
list(LENGTH files count)
if(count LESS 100)
  message(FATAL_ERROR "format_check: found ${count} C++ files under ${SOURCE}; expected the whole tree")
endif()
set(unformatted "")
foreach(f IN LISTS files)
  execute_process(COMMAND ${CLANG_FORMAT} --style=file --dry-run --Werror ${f}
                  WORKING_DIRECTORY ${SOURCE} RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
  if(NOT rc EQUAL 0)
    list(APPEND unformatted ${f})
  endif()
endforeach()
if(unformatted)
  list(JOIN unformatted "\n  " shown)
  message(FATAL_ERROR "format_check: not as .clang-format says (fix: clang-format -i FILE):\n  ${shown}")
endif()
message(STATUS "format_check: ${count} files as .clang-format says")
