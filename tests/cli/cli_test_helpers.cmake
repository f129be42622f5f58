# Shared by the command-line tests: run functionlab like a user, check output.
# run(EXPECTED_EXIT args...) sets OUT and ERR; expect_match(TEXT REGEX);
# expect_json_equal(JSON EXPECTED path...).

function(run expected_code)
  execute_process(COMMAND ${FUNCTIONLAB} ${ARGN}
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL expected_code)
    message(FATAL_ERROR "functionlab ${ARGN}\n exited ${code}, expected ${expected_code}\nstdout: ${out}\nstderr: ${err}")
  endif()
  set(OUT "${out}" PARENT_SCOPE)
  set(ERR "${err}" PARENT_SCOPE)
endfunction()

function(expect_match text regex)
  if(NOT text MATCHES "${regex}")
    message(FATAL_ERROR "expected output to match '${regex}', got:\n${text}")
  endif()
endfunction()

function(expect_json_equal json expected)
  string(JSON actual GET "${json}" ${ARGN})
  if(NOT actual STREQUAL expected)
    message(FATAL_ERROR "JSON ${ARGN}: expected '${expected}', got '${actual}' in ${json}")
  endif()
endfunction()

# A tool a test needs is missing: a warning on a developer's machine, a
# failure where it must be there (CI sets FUNCTIONLAB_REQUIRE_TOOLS=1).
function(missing_tool message)
  if(DEFINED ENV{FUNCTIONLAB_REQUIRE_TOOLS} AND NOT "$ENV{FUNCTIONLAB_REQUIRE_TOOLS}" STREQUAL ""
     AND NOT "$ENV{FUNCTIONLAB_REQUIRE_TOOLS}" STREQUAL "0")
    message(FATAL_ERROR "${message} (FUNCTIONLAB_REQUIRE_TOOLS is set: the tool must be installed)")
  endif()
  message(WARNING "${message}")
endfunction()
