# Runs `functionlab convert` like a user: encodings, the preview for other
# browsers, usage errors.
# Invoked by CTest: cmake -DFUNCTIONLAB=path -DEXAMPLES=dir -DOUT_DIR=dir -P cli_convert_test.cmake

include(${CMAKE_CURRENT_LIST_DIR}/cli_test_helpers.cmake)

file(MAKE_DIRECTORY ${OUT_DIR})

run(0 convert --help)
expect_match("${OUT}" "--no-preview")
run(2 convert ${EXAMPLES}/watermelon.x3d)                          # no OUT
run(2 convert ${EXAMPLES}/watermelon.x3d ${OUT_DIR}/w.dae)         # unknown encoding
run(2 convert ${EXAMPLES}/watermelon.x3d ${OUT_DIR}/w.x3dv --preview-resolution)
run(2 convert ${EXAMPLES}/watermelon.x3d ${OUT_DIR}/w.x3dv --preview-resolution 1)
run(2 convert ${EXAMPLES}/watermelon.x3d ${OUT_DIR}/w.x3dv --preview-resolution nan)
run(2 convert ${EXAMPLES}/watermelon.x3d ${OUT_DIR}/w.x3dv --preview)
run(1 convert ${OUT_DIR}/missing.x3d ${OUT_DIR}/w.x3dv)

# By default the function shapes come with a plain-X3D preview ...
run(0 convert ${EXAMPLES}/watermelon.x3d ${OUT_DIR}/w.x3dv)
file(READ ${OUT_DIR}/w.x3dv with)
expect_match("${with}" "DEF FunctionLab_Preview Group")
expect_match("${with}" "IndexedFaceSet")
# ... which FunctionLab itself does not read as part of the scene: converting
# again gives the same text, and the checker sees one shape.
run(0 convert ${OUT_DIR}/w.x3dv ${OUT_DIR}/w2.x3dv)
file(READ ${OUT_DIR}/w2.x3dv again)
if(NOT with STREQUAL again)
  message(FATAL_ERROR "converting a converted scene changed it")
endif()
run(0 mesh ${OUT_DIR}/w.x3dv --resolution 16 -o ${OUT_DIR}/w.stl)
expect_match("${ERR}" "^FShape [^\n]*triangles[^\n]*\nwrote")

run(0 convert ${EXAMPLES}/watermelon.x3d ${OUT_DIR}/w.x3d --no-preview)
file(READ ${OUT_DIR}/w.x3d without)
if(without MATCHES "FunctionLab_Preview|IndexedFaceSet")
  message(FATAL_ERROR "--no-preview wrote a preview")
endif()
expect_match("${without}" "<FShape")

# A coarser preview is smaller.
run(0 convert ${EXAMPLES}/watermelon.x3d ${OUT_DIR}/coarse.x3dv --preview-resolution 8)
file(SIZE ${OUT_DIR}/coarse.x3dv coarse_size)
file(SIZE ${OUT_DIR}/w.x3dv default_size)
if(NOT coarse_size LESS default_size)
  message(FATAL_ERROR "resolution 8 wrote ${coarse_size} bytes, 32 wrote ${default_size}")
endif()
