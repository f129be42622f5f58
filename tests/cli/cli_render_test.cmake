# Runs `functionlab render` like a user: an image of the size asked for, and
# clear messages for what cannot be drawn. Needs a display (CTest runs under
# xvfb-run from scripts/test; render also starts xvfb-run itself without one).
# Invoked by CTest: cmake -DFUNCTIONLAB=path -DEXAMPLES=dir -DOUT_DIR=dir -P cli_render_test.cmake

include(${CMAKE_CURRENT_LIST_DIR}/cli_test_helpers.cmake)

file(MAKE_DIRECTORY ${OUT_DIR})
run(0 render --help)
expect_match("${OUT}" "--viewpoint")
run(2 render ${EXAMPLES}/watermelon.x3d)                                      # no -o
run(2 render ${EXAMPLES}/watermelon.x3d -o ${OUT_DIR}/a.png --size 0x10)
run(2 render ${EXAMPLES}/watermelon.x3d -o ${OUT_DIR}/a.xyz)
run(1 render ${OUT_DIR}/missing.x3d -o ${OUT_DIR}/a.png)

run(0 render ${EXAMPLES}/watermelon.x3d -o ${OUT_DIR}/melon.png --size 200x150)
expect_match("${ERR}" "wrote .*melon.png \\(200x150, 1 shapes, [0-9]+ triangles\\)")
if(NOT EXISTS ${OUT_DIR}/melon.png)
  message(FATAL_ERROR "melon.png was not written")
endif()
# PNG: the width and height are big-endian words at bytes 16 and 20.
file(READ ${OUT_DIR}/melon.png header LIMIT 24 HEX)
string(SUBSTRING "${header}" 32 16 size)
if(NOT size STREQUAL "000000c800000096")
  message(FATAL_ERROR "melon.png is not 200x150: ${size}")
endif()

run(0 render ${EXAMPLES}/clock.x3d --time 36000 --viewpoint Front -o ${OUT_DIR}/clock.png --size 64x64)
run(1 render ${EXAMPLES}/clock.x3d --viewpoint Back -o ${OUT_DIR}/clock.png)
expect_match("${ERR}" "no viewpoint named 'Back'; the scene has: Front")
