# Runs `functionlab mesh` like a user: formats, warnings, exit codes.
# Invoked by CTest: cmake -DFUNCTIONLAB=path -DEXAMPLES=dir -DOUT_DIR=dir -P cli_mesh_test.cmake

include(${CMAKE_CURRENT_LIST_DIR}/cli_test_helpers.cmake)

file(MAKE_DIRECTORY ${OUT_DIR})
set(SPHERE "0.8^2 - x*x - y*y - z*z")

run(0 mesh --help)
expect_match("${OUT}" "--formula")
run(2 mesh --formula "${SPHERE}" -o ${OUT_DIR}/a.stl)                    # no --box
run(2 mesh --formula "${SPHERE}" --box 1,1,1,0,0,0 -o ${OUT_DIR}/a.stl)  # empty box
run(2 mesh --formula "${SPHERE}" --box -1,-1,-1,1,1,1 -o ${OUT_DIR}/a.dae)
run(2 mesh --formula "${SPHERE}" --box -1,-1,-1,1,1,1)                   # no -o
run(2 mesh --formula "${SPHERE}" --box -1,-1,-1,1,1,1 --resolution 8 --error 0.01 -o ${OUT_DIR}/a.stl)
run(1 mesh --formula "sine(x)" --box -1,-1,-1,1,1,1 -o ${OUT_DIR}/a.stl)
expect_match("${ERR}" "formula:1:1: error: .*sin")

foreach(ext stl obj ply glb x3d)
  run(0 mesh --formula "${SPHERE}" --box -1,-1,-1,1,1,1 --resolution 12.5 -o ${OUT_DIR}/sphere.${ext})
  expect_match("${ERR}" "triangles.*closed")
  if(NOT EXISTS ${OUT_DIR}/sphere.${ext})
    message(FATAL_ERROR "sphere.${ext} was not written")
  endif()
endforeach()
# The X3D file is a scene our own checker loads.
run(0 check ${OUT_DIR}/sphere.x3d)

run(0 mesh --formula "${SPHERE}" --box -1,-1,-1,1,1,1 --error 0.001 -o ${OUT_DIR}/e.stl)
expect_match("${ERR}" "measured error 0?\\.000[0-9]")

# No sign change: a warning on stderr, and still exit 0 with a file written.
run(0 mesh --formula "-(x*x + y*y + z*z - 0.25)^2" --box -1,-1,-1,1,1,1 -o ${OUT_DIR}/none.obj)
expect_match("${ERR}" "warning: .*never becomes positive")
# Undefined regions: one warning naming the formula's sqrt.
run(0 mesh --formula "0.5 - x*x - y*y - z*z + 0*sqrt(x)" --box -1,-1,-1,1,1,1 --open -o ${OUT_DIR}/nan.obj)
expect_match("${ERR}" "warning: the function is undefined \\(NaN\\).*sqrt")

# A scene: its function shapes, placed and meshed in their boxes.
run(0 mesh ${EXAMPLES}/watermelon.x3d --resolution 24 -o ${OUT_DIR}/melon.glb)
expect_match("${ERR}" "FShape .*watermelon.x3d:[0-9]+:[0-9]+.*triangles")
run(0 mesh ${EXAMPLES}/clock.x3d --time 15 -o ${OUT_DIR}/clock.glb)     # parametric surfaces
expect_match("${ERR}" "FShape CAP .*triangles")
# Standard geometry is meshed too: a Box is 12 triangles.
file(WRITE ${OUT_DIR}/boxes.x3dv "#X3D V3.3 utf8\nPROFILE Immersive\nShape { geometry Box {} }\n")
run(0 mesh ${OUT_DIR}/boxes.x3dv -o ${OUT_DIR}/boxes.glb)
expect_match("${ERR}" "Shape .*: 12 triangles")
file(WRITE ${OUT_DIR}/empty.x3dv "#X3D V3.3 utf8\nPROFILE Immersive\nGroup {}\n")
run(1 mesh ${OUT_DIR}/empty.x3dv -o ${OUT_DIR}/empty.glb)
expect_match("${ERR}" "no shape to mesh")
run(1 mesh ${OUT_DIR}/missing.x3d -o ${OUT_DIR}/m.stl)

# Point clouds: on the surface, through the solid, from a scene; never to STL.
run(0 mesh --formula "${SPHERE}" --box -1,-1,-1,1,1,1 --points 3000 -o ${OUT_DIR}/cloud.ply)
expect_match("${ERR}" "formula: 3000 points")
expect_match("${ERR}" "wrote .*cloud.ply .*3000 points")
run(0 mesh --formula "${SPHERE}" --box -1,-1,-1,1,1,1 --points 3000 --solid -o ${OUT_DIR}/filled.x3d)
run(0 check ${OUT_DIR}/filled.x3d)
run(0 mesh ${EXAMPLES}/watermelon.x3d --points 5000 -o ${OUT_DIR}/melon-points.glb)
expect_match("${ERR}" "FShape .*watermelon.x3d:[0-9]+:[0-9]+.*points")
run(2 mesh --formula "${SPHERE}" --box -1,-1,-1,1,1,1 --points 3000 -o ${OUT_DIR}/cloud.stl)
expect_match("${ERR}" "STL holds triangles only")
run(2 mesh --formula "${SPHERE}" --box -1,-1,-1,1,1,1 --points 2.5 -o ${OUT_DIR}/cloud.ply)
run(2 mesh --formula "${SPHERE}" --box -1,-1,-1,1,1,1 --solid -o ${OUT_DIR}/cloud.ply)

# What accuracy costs in time: both methods per resolution, as JSON and a plot.
run(0 bench accuracy --formula "${SPHERE}" --box -1,-1,-1,1,1,1 --resolutions 8,16 --json
    --plot ${OUT_DIR}/accuracy.svg)
string(JSON rows LENGTH "${OUT}")
if(NOT rows EQUAL 4)
  message(FATAL_ERROR "expected 4 rows (2 methods x 2 resolutions), got ${rows}: ${OUT}")
endif()
foreach(i RANGE 3)
  foreach(key method resolution triangles evaluations ms max_error mean_error)
    string(JSON v GET "${OUT}" ${i} ${key})
  endforeach()
endforeach()
string(JSON m0 GET "${OUT}" 0 method)
string(JSON m1 GET "${OUT}" 1 method)
if(NOT m0 STREQUAL "adaptive" OR NOT m1 STREQUAL "dense")
  message(FATAL_ERROR "rows should alternate adaptive, dense: ${OUT}")
endif()
file(READ ${OUT_DIR}/accuracy.svg svg)
expect_match("${svg}" "<svg.*polyline.*polyline.*</svg>")
run(0 bench accuracy ${EXAMPLES}/watermelon.x3d --resolutions 8)
expect_match("${OUT}" "at resolution 8: adaptive")
run(2 bench accuracy --formula "${SPHERE}" --box -1,-1,-1,1,1,1 --resolutions 0)
# The adaptive mesher's budget: too small a one leaves its rows out with the
# mesher's message (dense rows remain); a bad value is a usage error.
run(0 bench accuracy --formula "${SPHERE}" --box -1,-1,-1,1,1,1 --resolutions 64 --memory 1
    --threads 1)
expect_match("${OUT}" "dense +64")
expect_match("${ERR}" "no row for adaptive at resolution 64: .*raise the memory budget")
run(2 bench accuracy --formula "${SPHERE}" --box -1,-1,-1,1,1,1 --memory 0.5)
run(2 bench accuracy --formula "${SPHERE}" --box -1,-1,-1,1,1,1 --threads abc)
