# Grading a course on a cluster (issue 32 §4), as docs/grading.md shows it:
# a class graded in 4 disjoint parts at once by GNU parallel (grade batch
# --shard K/N, one gradebook each), merged (grade merge), holds the same
# results as one batch; the merged log verifies and holds every part's
# entries; parts that overlap, a part that was tampered with, or an output
# that exists are refused and nothing is written.
# Invoked by CTest: cmake -DFUNCTIONLAB=path -DCOURSEWARE=dir -DOUT_DIR=dir -P cli_grade_shard_test.cmake

include(${CMAKE_CURRENT_LIST_DIR}/cli_test_helpers.cmake)

set(lab ${COURSEWARE}/assignments/implicit-fantasies)
file(REMOVE_RECURSE ${OUT_DIR})
set(class ${OUT_DIR}/class)
file(MAKE_DIRECTORY ${class})
# Ten students: solutions, a starter, a broken file, a folder.
foreach(s alice cem dana erin femi gus hana ivo)
  file(COPY_FILE ${lab}/solution/fantasy.x3d ${class}/${s}.x3d)
endforeach()
file(COPY_FILE ${lab}/starter.x3d ${class}/bob.x3d)
file(WRITE ${class}/carol.x3d "<X3D><Scene><FShape>")
file(WRITE ${OUT_DIR}/roster.csv "id,name,email\nalice,\"Smith, Alice\",alice@example.org\nbob,Bob,b@example.org\n")

# One batch: the reference.
run(0 grade batch --assignment implicit-fantasies ${class} --db ${OUT_DIR}/one.sqlite
    --roster ${OUT_DIR}/roster.csv --json)
expect_json_equal("${OUT}" "9" graded)
expect_json_equal("${OUT}" "1" not_gradable)

# --shard: K counts from 0 and stays below N.
run(2 grade batch --assignment implicit-fantasies ${class} --db ${OUT_DIR}/x.sqlite --shard 4/4)
expect_match("${ERR}" "K counts from 0")
run(2 grade batch --assignment implicit-fantasies ${class} --db ${OUT_DIR}/x.sqlite --shard 1)
run(2 grade batch --assignment implicit-fantasies ${class} --db ${OUT_DIR}/x.sqlite --shard 0/0)

# Four parts at once, as GNU parallel runs them across machines.
find_program(PARALLEL parallel)
set(parts)
if(PARALLEL)
  execute_process(
    COMMAND ${PARALLEL} --halt now,fail=1 ${FUNCTIONLAB} grade batch --assignment implicit-fantasies
            ${class} --db ${OUT_DIR}/part-{}.sqlite --roster ${OUT_DIR}/roster.csv
            --shard {}/4 --json ::: 0 1 2 3
    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "parallel grade batch --shard: exit ${code}\n${out}\n${err}")
  endif()
else()
  missing_tool("GNU parallel is not installed: the parts are graded one after another (apt-get install parallel)")
  foreach(k 0 1 2 3)
    run(0 grade batch --assignment implicit-fantasies ${class} --db ${OUT_DIR}/part-${k}.sqlite
        --roster ${OUT_DIR}/roster.csv --shard ${k}/4 --json)
  endforeach()
endif()
# Every student in exactly one part.
set(total 0)
foreach(k 0 1 2 3)
  list(APPEND parts ${OUT_DIR}/part-${k}.sqlite)
  run(0 grade export --db ${OUT_DIR}/part-${k}.sqlite --assignment implicit-fantasies --format csv
      -o ${OUT_DIR}/part-${k}.csv)
  file(STRINGS ${OUT_DIR}/part-${k}.csv rows)
  list(LENGTH rows n)
  math(EXPR total "${total} + ${n} - 1")
endforeach()
if(NOT total EQUAL 10)
  message(FATAL_ERROR "the parts hold ${total} students, not the class's 10")
endif()

# Merged: the same results as one batch, a log that verifies.
run(0 grade merge ${parts} -o ${OUT_DIR}/course.sqlite --json)
expect_json_equal("${OUT}" "4" sources)
expect_json_equal("${OUT}" "10" grades)
run(0 grade verify ${OUT_DIR}/course.sqlite --json)
expect_json_equal("${OUT}" "ON" intact)
foreach(book one course)
  run(0 grade export --db ${OUT_DIR}/${book}.sqlite --assignment implicit-fantasies --format csv
      -o ${OUT_DIR}/${book}.csv)
endforeach()
file(READ ${OUT_DIR}/one.csv one)
file(READ ${OUT_DIR}/course.csv course)
if(NOT one STREQUAL course)
  message(FATAL_ERROR "the merged gradebook differs from one batch:\n${one}\n---\n${course}")
endif()
expect_match("${course}" "alice,\"Smith, Alice\",alice@example.org,yes,100,")

# Refused, nothing written: overlapping parts, an existing output, a part
# named twice, a part whose log was changed.
run(1 grade merge ${OUT_DIR}/one.sqlite ${OUT_DIR}/part-1.sqlite -o ${OUT_DIR}/bad.sqlite)
expect_match("${ERR}" "is in both .*one.sqlite and .*part-1.sqlite: the parts of a class must be disjoint")
if(EXISTS ${OUT_DIR}/bad.sqlite OR EXISTS ${OUT_DIR}/bad.sqlite.partial)
  message(FATAL_ERROR "a refused merge left a file")
endif()
run(1 grade merge ${parts} -o ${OUT_DIR}/course.sqlite)
expect_match("${ERR}" "exists")
run(1 grade merge ${OUT_DIR}/part-0.sqlite ${OUT_DIR}/part-0.sqlite -o ${OUT_DIR}/bad.sqlite)
expect_match("${ERR}" "named twice")
run(1 grade merge ${OUT_DIR}/no-such.sqlite -o ${OUT_DIR}/bad.sqlite)
run(2 grade merge -o ${OUT_DIR}/bad.sqlite)
run(2 grade merge ${parts})
