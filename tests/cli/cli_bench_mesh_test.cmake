# `functionlab bench remesh` (its output's shape), and `functionlab bench mesh
# --peer vtk`: the meshers and VTK's Flying Edges on
# one shape, every row measured by the same code (this checks the output and
# the peer's agreement with dense marching cubes, it times nothing). The peer
# is Debian's python3-vtk9 (scripts/test installs it); without it the test
# says so, and fails where FUNCTIONLAB_REQUIRE_TOOLS is set.
# Invoked by CTest: cmake -DFUNCTIONLAB=path -P cli_bench_mesh_test.cmake
include(${CMAKE_CURRENT_LIST_DIR}/cli_test_helpers.cmake)

run(2 bench mesh --formula "1 - x*x - y*y - z*z" --box -1.2,-1.2,-1.2,1.2,1.2,1.2 --peer curv)
expect_match("${ERR}" "--peer needs one of vtk, libfive")

# The libfive peer: built only from a libfive source tree given to CMake
# (FUNCTIONLAB_LIBFIVE_SOURCE); without it, the command says how to build it.
get_filename_component(bin_dir "${FUNCTIONLAB}" DIRECTORY)
if(NOT EXISTS "${bin_dir}/functionlab-libfive-peer")
  run(1 bench mesh --formula "0.8^2 - x*x - y*y - z*z" --box -1,-1,-1,1,1,1 --resolutions 16
      --peer libfive)
  expect_match("${ERR}" "FUNCTIONLAB_LIBFIVE_SOURCE")
else()
  # libfive at the same resolutions (powers of two: its octree halves the box);
  # both meshers are dual contouring, so their errors are of a size.
  run(0 bench mesh --formula "0.8^2 - x*x - y*y - z*z" --box -1,-1,-1,1,1,1
      --resolutions 16,32 --threads 1 --peer libfive --json)
  string(JSON n LENGTH "${OUT}")
  if(NOT n EQUAL 6)
    message(FATAL_ERROR "expected 6 rows (adaptive, dense, libfive at 16 and 32): ${OUT}")
  endif()
  foreach(i 4 5)
    string(JSON method GET "${OUT}" ${i} method)
    string(JSON triangles GET "${OUT}" ${i} triangles)
    string(JSON error GET "${OUT}" ${i} max_error)
    if(NOT method STREQUAL "libfive" OR triangles LESS 500 OR error GREATER 0.01)
      message(FATAL_ERROR "libfive row ${i}: ${method}, ${triangles} triangles, error ${error}")
    endif()
  endforeach()
  run(0 bench mesh --formula "(1 - x^2 - y^2 - z^2) & (-((z - x) & y & z))"
      --box -1.1,-1.1,-1.1,1.1,1.1,1.1 --resolutions 24 --threads 2 --peer libfive)
  expect_match("${OUT}" "libfive +32 ")
  expect_match("${OUT}" "libfive at 32 .*as fast")
  # A box twice as long as it is wide: libfive's octree halves every side, so
  # its 16 cells along x (the resolution, as FunctionLab counts it) are half
  # as long along y and z; the row says the resolution it meshed at.
  run(0 bench mesh --formula "0.5 - (x/2)^2 - y^2 - z^2" --box -2,-1,-1,2,1,1
      --resolutions 12 --threads 1 --peer libfive --json)
  string(JSON method GET "${OUT}" 2 method)
  string(JSON resolution GET "${OUT}" 2 resolution)
  string(JSON error GET "${OUT}" 2 max_error)
  if(NOT method STREQUAL "libfive" OR NOT resolution EQUAL 16 OR error GREATER 0.02)
    message(FATAL_ERROR "libfive on a long box: ${OUT}")
  endif()
  # The same shape with R-function set operations, as a scene's
  # setOperations="rfunction" makes them, reaches the peer as such.
  run(0 bench mesh ${EXAMPLES_DIR}/implicit_gallery.x3d --resolutions 16 --threads 1
      --peer libfive)
  expect_match("${OUT}" "libfive +16 ")
  # What libfive cannot express is refused by name.
  run(1 bench mesh --formula "0.5 - abs(x) - floor(y)" --box -1,-1,-1,1,1,1 --resolutions 8
      --peer libfive)
  expect_match("${ERR}" "libfive has no floor")
  run(1 bench mesh --formula "0.5 - abs(x) - mod(y, -1)" --box -1,-1,-1,1,1,1 --resolutions 8
      --peer libfive)
  expect_match("${ERR}" "positive constant divisor")
endif()
run(2 bench mesh --resolutions 16)
expect_match("${ERR}" "give a scene FILE or --formula")

# bench remesh: the time from an edit to its mesh, as p50/p95 (the shape of
# its JSON; it times nothing here).
run(0 bench remesh --formula "0.8^2 - x*x - y*y - z*z" --box -1,-1,-1,1,1,1 --resolution 16
    --edits 4 --threads 1 --json)
foreach(part compile_ms mesh_ms total_ms)
  foreach(q p50 p95)
    string(JSON v GET "${OUT}" ${part} ${q})
  endforeach()
endforeach()
string(JSON peak GET "${OUT}" peak_mib)
if(NOT peak GREATER 1)
  message(FATAL_ERROR "bench remesh: no peak memory: ${OUT}")
endif()
string(JSON edits GET "${OUT}" edits)
if(NOT edits EQUAL 4)
  message(FATAL_ERROR "bench remesh: ${OUT}")
endif()
run(2 bench remesh --formula "x" --resolution 16)
expect_match("${ERR}" "--formula needs --box")
run(1 bench remesh --formula "sine(x)" --box -1,-1,-1,1,1,1 --edits 2)
expect_match("${ERR}" "did you mean")

# Dense marching cubes' and VTK's max errors on one grid agree within 5 %
# (CMake compares no real numbers itself).
# Within 10 %: the two marching cubes split ambiguous faces differently
# (4 332 and 4 368 triangles on the bitten sphere at 24), which shows at its
# creases, where the error measured at vertices and edge middles is largest;
# a grid read the wrong way round makes a different shape altogether.
function(expect_same_error dense vtk what)
  execute_process(COMMAND /usr/bin/python3 -c
                  "import sys; d,v=float(sys.argv[1]),float(sys.argv[2]); sys.exit(0 if abs(d-v) <= 0.1*d else 1)"
                  ${dense} ${vtk} RESULT_VARIABLE same)
  if(NOT same EQUAL 0)
    message(FATAL_ERROR "${what}: dense max error ${dense}, vtk ${vtk}: not the same grid")
  endif()
endfunction()

execute_process(COMMAND /usr/bin/python3 -c "import vtkmodules.vtkFiltersCore"
                RESULT_VARIABLE have_vtk OUTPUT_QUIET ERROR_QUIET)
if(NOT have_vtk EQUAL 0)
  missing_tool("python3-vtk9 is not installed: bench mesh's VTK peer is not run (apt-get install python3-vtk9)")
  return()
endif()
run(0 bench mesh --formula "0.8^2 - x*x - y*y - z*z" --box -1,-1,-1,1,1,1
    --resolutions 16,24 --threads 1 --json)
string(JSON n LENGTH "${OUT}")
# adaptive and dense at 16 and 24, vtk at 16, 24 and 48
if(NOT n EQUAL 7)
  message(FATAL_ERROR "expected 7 rows, got ${n}: ${OUT}")
endif()
set(dense_error "")
set(vtk_error "")
math(EXPR last "${n} - 1")
foreach(i RANGE ${last})
  string(JSON method GET "${OUT}" ${i} method)
  string(JSON resolution GET "${OUT}" ${i} resolution)
  string(JSON triangles GET "${OUT}" ${i} triangles)
  string(JSON error GET "${OUT}" ${i} max_error)
  if(triangles LESS 100)
    message(FATAL_ERROR "${method} at ${resolution}: only ${triangles} triangles")
  endif()
  if(method STREQUAL "dense" AND resolution EQUAL 24)
    set(dense_error ${error})
  elseif(method STREQUAL "vtk" AND resolution EQUAL 24)
    set(vtk_error ${error})
  endif()
endforeach()
# The same grid contoured by two marching-cubes meshers: the same error
# (within float32 samples), which also shows the grid reached VTK the right
# way round.
if(dense_error STREQUAL "" OR vtk_error STREQUAL "")
  message(FATAL_ERROR "no dense or vtk row at 24: ${OUT}")
endif()
expect_same_error(${dense_error} ${vtk_error} "sphere")
# An asymmetric shape (a bitten sphere): a grid read the wrong way round by
# VTK would show here, where a sphere hides it.
run(0 bench mesh --formula "(1 - x^2 - y^2 - z^2) & (-((z - x) & y & z))"
    --box -1.1,-1.1,-1.1,1.1,1.1,1.1 --resolutions 24 --threads 1)
expect_match("${OUT}" "vtk +24 ")
string(REGEX MATCH "dense +24 +[0-9]+ +[0-9]+ +[0-9.]+ +([0-9.e+-]+)" _ "${OUT}")
set(d ${CMAKE_MATCH_1})
string(REGEX MATCH "vtk +24 +[0-9]+ +[0-9]+ +[0-9.]+ +([0-9.e+-]+)" _ "${OUT}")
set(v ${CMAKE_MATCH_1})
expect_same_error(${d} ${v} "bitten sphere\n${OUT}")
expect_match("${OUT}" "as fast|reaches no such error")
