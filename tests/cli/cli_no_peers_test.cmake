# The product executable links no benchmark peer: neither muParser nor OpenMP
# (libgomp). Those live in functionlab-bench, which `functionlab bench eval` runs.
#
# What functionlab itself links is its ELF NEEDED list (readelf -d): neither
# may be there. `ldd` lists the whole closure: muParser must not be in it
# either, but libgomp is, through Qt: libQt6Core needs libb2 (BLAKE2), which
# Debian builds with OpenMP. That one is Qt's, not ours, and is allowed only
# when it comes that way.
# Invoked by CTest: cmake -DFUNCTIONLAB=path -DBENCH=path -DHAVE_MUPARSER=ON|OFF -P ...

find_program(READELF readelf)
find_program(LDD ldd)
if(NOT READELF OR NOT LDD)
  message(STATUS "no readelf/ldd here: nothing to check")
  return()
endif()

function(needed file out)
  execute_process(COMMAND ${READELF} -d ${file} RESULT_VARIABLE code OUTPUT_VARIABLE dyn
                  ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "readelf -d ${file} exited ${code}: ${err}")
  endif()
  string(REGEX MATCHALL "Shared library: \\[[^]]+\\]" libs "${dyn}")
  string(TOLOWER "${libs}" libs)
  set(${out} "${libs}" PARENT_SCOPE)
endfunction()

needed(${FUNCTIONLAB} direct)
if(direct MATCHES "muparser|gomp")
  message(FATAL_ERROR "functionlab links a benchmark peer itself: ${direct}")
endif()

execute_process(COMMAND ${LDD} ${FUNCTIONLAB} RESULT_VARIABLE code OUTPUT_VARIABLE closure
                ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "ldd ${FUNCTIONLAB} exited ${code}: ${err}")
endif()
string(TOLOWER "${closure}" closure_lower)
if(closure_lower MATCHES "muparser")
  message(FATAL_ERROR "functionlab loads muParser:\n${closure}")
endif()
if(closure_lower MATCHES "gomp")
  # Only through a system library that is not ours (Qt's libb2).
  string(REGEX MATCHALL "=> (/[^ ]+)" paths "${closure}")
  set(via "")
  foreach(p IN LISTS paths)
    string(REGEX REPLACE "^=> " "" lib "${p}")
    if(lib MATCHES "gomp")
      continue()
    endif()
    needed(${lib} lib_needed)
    if(lib_needed MATCHES "gomp")
      list(APPEND via ${lib})
    endif()
  endforeach()
  foreach(lib IN LISTS via)
    if(lib MATCHES "^${CMAKE_BINARY_DIR}|functionlab|muparser")
      message(FATAL_ERROR "libgomp comes in through ${lib}")
    endif()
  endforeach()
  message(STATUS "libgomp is loaded only through system libraries: ${via}")
endif()

# It is a real check: the benchmark executable does link muParser (when the
# build found it).
if(BENCH AND HAVE_MUPARSER)
  needed(${BENCH} bench_direct)
  if(NOT bench_direct MATCHES "muparser")
    message(FATAL_ERROR "functionlab-bench should link muParser: ${bench_direct}")
  endif()
endif()
