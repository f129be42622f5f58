# `functionlab grade report` end to end: a class graded, its report written,
# everything a submission wrote escaped, and — where chromium is installed
# (scripts/test installs it) — the pages opened in a real browser, their
# screenshots kept in OUT_DIR to look at.
# Invoked by CTest: cmake -DFUNCTIONLAB=path -DCOURSEWARE=dir -DOUT_DIR=dir -P cli_report_test.cmake

include(${CMAKE_CURRENT_LIST_DIR}/cli_test_helpers.cmake)

set(lab ${COURSEWARE}/assignments/implicit-fantasies)
file(REMOVE_RECURSE ${OUT_DIR})
file(MAKE_DIRECTORY ${OUT_DIR}/class)
file(COPY_FILE ${lab}/solution/fantasy.x3d ${OUT_DIR}/class/alice.x3d)
file(COPY_FILE ${lab}/starter.x3d ${OUT_DIR}/class/bob.x3d)
# A student whose name and formula carry markup: the report must show it as text.
file(WRITE "${OUT_DIR}/class/eve<b>.x3dv" "#X3D V3.3 utf8
PROFILE Immersive
COMPONENT FunctionLab:1
FShape { geometry FGeometry { type \"explicit\" definition \"x < 0.2 ? 0.3 - x*x - y*y - z*z : -1\" } }
")
run(0 grade batch --assignment implicit-fantasies ${OUT_DIR}/class --db ${OUT_DIR}/gb.sqlite)
run(0 grade report --db ${OUT_DIR}/gb.sqlite --assignment implicit-fantasies -o ${OUT_DIR}/report)
expect_match("${OUT}" "4 pages")
file(READ ${OUT_DIR}/report/index.html index)
expect_match("${index}" "eve&lt;b&gt;")
if(index MATCHES "eve<b>")
  message(FATAL_ERROR "the report wrote a student's markup into the page")
endif()
expect_match("${index}" "Pass rate per requirement")
file(GLOB pages ${OUT_DIR}/report/*.html)
list(LENGTH pages n)
if(NOT n EQUAL 4)
  message(FATAL_ERROR "expected 4 pages, found ${n}")
endif()
file(GLOB evePage ${OUT_DIR}/report/eve*.html)
file(READ ${evePage} eve)
expect_match("${eve}" "x &lt; 0.2")
# Pictures: the solution moves, so two; they are real PNGs.
if(EXISTS ${OUT_DIR}/report/pictures/alice-1.png)
  file(READ ${OUT_DIR}/report/pictures/alice-1.png head LIMIT 4 HEX)
  if(NOT head STREQUAL "89504e47")
    message(FATAL_ERROR "alice-1.png is not a PNG")
  endif()
else()
  # In CI (FUNCTIONLAB_REQUIRE_TOOLS) a report without pictures is a failure.
  missing_tool("no pictures were drawn (no display and no xvfb-run?)")
endif()

find_program(CHROMIUM NAMES chromium chromium-browser)
if(NOT CHROMIUM)
  missing_tool("chromium is not installed: the pages are not opened in a browser (apt-get install chromium)")
  return()
endif()
foreach(page index alice)
  execute_process(COMMAND ${CHROMIUM} --headless --no-sandbox --disable-gpu
                          --screenshot=${OUT_DIR}/browser-${page}.png --window-size=1000,1200
                          file://${OUT_DIR}/report/${page}.html
                  RESULT_VARIABLE code OUTPUT_QUIET ERROR_QUIET TIMEOUT 120)
  if(NOT code EQUAL 0 OR NOT EXISTS ${OUT_DIR}/browser-${page}.png)
    message(FATAL_ERROR "chromium could not show ${page}.html (exit ${code})")
  endif()
  file(SIZE ${OUT_DIR}/browser-${page}.png size)
  if(size LESS 20000)
    message(FATAL_ERROR "the screenshot of ${page}.html is nearly empty (${size} bytes)")
  endif()
endforeach()
