# Runs `functionlab formula …` like a user and checks exit codes and output.
# Invoked by CTest: cmake -DFUNCTIONLAB=path -P cli_formula_test.cmake

include(${CMAKE_CURRENT_LIST_DIR}/cli_test_helpers.cmake)

function(expect_json_null json)
  string(JSON type TYPE "${json}" ${ARGN})
  if(NOT type STREQUAL "NULL")
    message(FATAL_ERROR "JSON ${ARGN}: expected null, got ${type} in ${json}")
  endif()
endfunction()

# --help / --version / usage errors
run(0 --help)
expect_match("${OUT}" "formula eval")
run(0 --version)
expect_match("${OUT}" "^functionlab [0-9]+\\.[0-9]+\\.[0-9]+")
run(2 no-such-command)
run(2 formula)
run(2 formula eval "x")
run(2 formula eval "x" --at 1,2)
run(2 formula eval "x" --at 1,2,3 --bogus)
run(2 formula eval "x" --at nan,0,0)
run(2 formula eval "x" --at 1e400,0,0)
run(2 formula eval "x" --at 0,0,0 --t inf)

# a formula may start with '-'; "--" ends the options
run(0 formula eval "-x^2" --at 3,0,0 --json)
expect_json_equal("${OUT}" "-9" value)
run(0 formula eval --at 3,0,0 -- "-x" --json)
expect_json_equal("${OUT}" "-3" value)
run(2 formula eval "x" --at 3,0,0 --jsn)

# check: caret diagnostics and exit status
run(1 formula check "sine(x) + 1")
expect_match("${ERR}" "formula:1:1: error: unknown function 'sine' \\(did you mean 'sin'\\?\\)")
expect_match("${ERR}" "\n  sine\\(x\\) \\+ 1\n  \\^~~~\n")
run(0 formula check "(1-x^2-y^2-z^2) & (-((z-x) & y & z))" --tape)
expect_match("${OUT}" "ok: [0-9]+ operations")
expect_match("${OUT}" "min")

# eval: value and gradient, text and JSON
run(0 formula eval "1 - x^2 - y^2 - z^2" --at 0.5,0,0)
expect_match("${OUT}" "value = 0.75")
run(0 formula eval "1 - x^2 - y^2 - z^2" --at 0.5,0,0 --json)
string(JSON value GET "${OUT}" value)
if(NOT value EQUAL 0.75)
  message(FATAL_ERROR "value ${value}")
endif()
expect_json_equal("${OUT}" "ON" finite)
expect_json_equal("${OUT}" "-1" gradient 0)
expect_json_equal("${OUT}" "0" gradient 1)
string(JSON ndiag LENGTH "${OUT}" diagnostics)
if(NOT ndiag EQUAL 0)
  message(FATAL_ERROR "unexpected diagnostics: ${OUT}")
endif()

# time and parameters
# (semicolons: passed as one bracket argument, which CMake does not split)
execute_process(COMMAND ${FUNCTIONLAB} formula eval [=[param R = 1; return R - x + t;]=]
                        --at 0.25,0,0 --t 2 --param R=3 --json
                RESULT_VARIABLE code OUTPUT_VARIABLE OUT)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "param eval exited ${code}: ${OUT}")
endif()
string(JSON value GET "${OUT}" value)
if(NOT value EQUAL 4.75)
  message(FATAL_ERROR "value ${value}")
endif()
run(1 formula eval "x" --at 0,0,0 --param Q=3 --json)
expect_match("${OUT}" "no parameter 'Q'")

# non-finite values: null, finite false, and a located warning; still exit 0
run(0 formula eval "log(x)" --at -1,0,0 --json)
expect_json_null("${OUT}" value)
expect_json_equal("${OUT}" "OFF" finite)
expect_json_null("${OUT}" gradient 0) # no gradient of an undefined value
expect_json_equal("${OUT}" "warning" diagnostics 0 severity)
expect_json_equal("${OUT}" "1" diagnostics 0 column)

# errors in JSON mode: exactly one object, exit 1
run(1 formula eval "sin(x" --at 0,0,0 --json)
expect_json_null("${OUT}" value)
expect_json_equal("${OUT}" "error" diagnostics 0 severity)
expect_json_equal("${OUT}" "6" diagnostics 0 column)

# parametric: outputs and gradient in u, v, w
execute_process(COMMAND ${FUNCTIONLAB} formula eval [=[x = cos(u) * v; y = sin(u) * v; z = w;]=]
                        --kind parametric --uvw 0,2,3 --json
                RESULT_VARIABLE code OUTPUT_VARIABLE OUT)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "parametric eval exited ${code}: ${OUT}")
endif()
expect_json_equal("${OUT}" "2" outputs x)
expect_json_equal("${OUT}" "3" outputs z)
expect_json_equal("${OUT}" "1" gradient 1)
