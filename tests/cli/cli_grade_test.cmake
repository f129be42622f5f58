# `functionlab grade check` as tools outside this repository call it: the
# JSON fields and exit codes of docs/grading.md.
# Invoked by CTest: cmake -DFUNCTIONLAB=path -DCOURSEWARE=dir -DOUT_DIR=dir -P cli_grade_test.cmake

include(${CMAKE_CURRENT_LIST_DIR}/cli_test_helpers.cmake)

set(lab ${COURSEWARE}/assignments/implicit-fantasies)
file(MAKE_DIRECTORY ${OUT_DIR})

# The reference solution: graded, full marks, every requirement in order.
run(0 grade check --assignment implicit-fantasies ${lab}/solution/fantasy.x3d --json)
expect_json_equal("${OUT}" "implicit-fantasies" assignment)
expect_json_equal("${OUT}" "ON" gradable)
expect_json_equal("${OUT}" "100" score)
expect_json_equal("${OUT}" "100" max_score)
expect_json_equal("${OUT}" "20" manual_max)
set(ids implicit explicit parametric set-operations morphing animation level-of-detail colour)
set(i 0)
foreach(id IN LISTS ids)
  expect_json_equal("${OUT}" "${id}" requirements ${i} id)
  expect_json_equal("${OUT}" "ON" requirements ${i} met)
  string(JSON line GET "${OUT}" requirements ${i} locations 0 line)
  if(line LESS 1)
    message(FATAL_ERROR "requirement ${id}: no located evidence")
  endif()
  math(EXPR i "${i} + 1")
endforeach()

# By folder too; a folder holding the submission; the gzip form.
run(0 grade check --assignment ${lab} ${lab}/starter.x3d --json)
expect_json_equal("${OUT}" "OFF" requirements 0 met)
expect_json_equal("${OUT}" "ON" requirements 1 met)
file(MAKE_DIRECTORY ${OUT_DIR}/student)
file(COPY ${lab}/solution/fantasy.x3d DESTINATION ${OUT_DIR}/student)
run(0 grade check --assignment implicit-fantasies ${OUT_DIR}/student --json)
expect_json_equal("${OUT}" "100" score)
file(READ ${lab}/solution/fantasy.x3d text)
file(WRITE ${OUT_DIR}/plain.x3d "${text}")
execute_process(COMMAND gzip -kf ${OUT_DIR}/plain.x3d)
if(EXISTS ${OUT_DIR}/plain.x3d.gz)
  run(0 grade check --assignment implicit-fantasies ${OUT_DIR}/plain.x3d.gz --json)
  expect_json_equal("${OUT}" "100" score)
endif()

# Text for people: a checklist.
run(0 grade check --assignment implicit-fantasies ${lab}/starter.x3d)
expect_match("${OUT}" "\\[ \\] implicit")
expect_match("${OUT}" "\\[x\\] explicit")

# Not gradable: exit 1, gradable false, located diagnostics.
file(WRITE ${OUT_DIR}/broken.x3d "<X3D><Scene><FShape>")
run(1 grade check --assignment implicit-fantasies ${OUT_DIR}/broken.x3d --json)
expect_json_equal("${OUT}" "OFF" gradable)
string(JSON line GET "${OUT}" diagnostics 0 line)
run(1 grade check --assignment no-such-lab ${lab}/starter.x3d --json)
expect_json_equal("${OUT}" "OFF" gradable)
run(1 grade check --assignment no-such-lab ${lab}/starter.x3d)
expect_match("${ERR}" "implicit-fantasies")

# Usage errors: exit 2.
run(2 grade check ${lab}/starter.x3d)
run(2 grade check --assignment implicit-fantasies)
run(2 grade check --assignment implicit-fantasies a b)
run(2 grade check --assignment implicit-fantasies ${lab}/starter.x3d --bogus)
run(0 grade check --help)
expect_match("${OUT}" "--assignment ID\\|DIR")

# A class: graded into a gradebook in isolated children, resumable, exported.
set(class ${OUT_DIR}/class)
file(REMOVE_RECURSE ${class} ${OUT_DIR}/gradebook.sqlite ${OUT_DIR}/gradescope)
file(MAKE_DIRECTORY ${class}/dana)
file(COPY_FILE ${lab}/solution/fantasy.x3d ${class}/alice.x3d)
file(COPY_FILE ${lab}/starter.x3d ${class}/bob.x3d)
file(WRITE ${class}/carol.x3d "<X3D><Scene><FShape>")
file(COPY_FILE ${lab}/solution/fantasy.x3d ${class}/dana/world.x3d)
file(WRITE ${OUT_DIR}/roster.csv "id,name,email\nalice,\"Smith, Alice\",alice@example.org\nbob,=HYPERLINK(1),b@example.org\n")
run(0 grade batch --assignment implicit-fantasies ${class} --db ${OUT_DIR}/gradebook.sqlite
    --roster ${OUT_DIR}/roster.csv --jobs 2 --json)
expect_json_equal("${OUT}" "3" graded)
expect_json_equal("${OUT}" "1" not_gradable)
# Each check ran isolated (bubblewrap where it runs, else the syscall filter).
string(JSON isolation GET "${OUT}" isolation)
if(NOT isolation MATCHES "^(bubblewrap|syscall filter)$")
  message(FATAL_ERROR "the batch ran under '${isolation}'")
endif()
# The fallback, asked for: the same verdicts under the syscall filter.
file(REMOVE ${OUT_DIR}/filtered.sqlite ${OUT_DIR}/filtered.sqlite-wal ${OUT_DIR}/filtered.sqlite-shm)
run(0 grade batch --assignment implicit-fantasies ${class} --db ${OUT_DIR}/filtered.sqlite
    --isolation syscall-filter --json)
expect_json_equal("${OUT}" "3" graded)
expect_json_equal("${OUT}" "syscall filter" isolation)
run(2 grade batch --assignment implicit-fantasies ${class} --db ${OUT_DIR}/x.sqlite
    --isolation bubblewrap --no-isolation)
run(0 grade batch --assignment implicit-fantasies ${class} --db ${OUT_DIR}/gradebook.sqlite --json)
expect_json_equal("${OUT}" "4" skipped)
expect_json_equal("${OUT}" "0" graded)
run(0 grade export --db ${OUT_DIR}/gradebook.sqlite --assignment implicit-fantasies
    --format csv -o ${OUT_DIR}/grades.csv)
file(READ ${OUT_DIR}/grades.csv csv)
expect_match("${csv}" "alice,\"Smith, Alice\",alice@example.org,yes,100,100,1,0,,100,")
# Issue 27 §3: the export carries the log's head; the gradebook is intact
# and still holds it; a head it never had is refused.
file(READ ${OUT_DIR}/grades.csv.head.json headJson)
string(JSON head GET "${headJson}" hash)
run(0 grade verify ${OUT_DIR}/gradebook.sqlite --head ${head})
expect_match("${OUT}" "intact: [0-9]+ entries")
run(1 grade verify ${OUT_DIR}/gradebook.sqlite
    --head 0000000000000000000000000000000000000000000000000000000000000001)
expect_match("${OUT}" "NOT INTACT: the head 0000000000000000… is not in the log")
# The instructor's key: made once, signs each batch; the public key checks.
file(REMOVE ${OUT_DIR}/grading.key ${OUT_DIR}/grading.key.pub)
run(0 grade key new --out ${OUT_DIR}/grading.key)
string(STRIP "${OUT}" publicKey)
run(1 grade key new --out ${OUT_DIR}/grading.key) # never overwritten
run(1 grade verify ${OUT_DIR}/gradebook.sqlite --key ${publicKey}) # not signed with it yet
run(0 grade batch --assignment implicit-fantasies ${class} --db ${OUT_DIR}/gradebook.sqlite
    --signing-key ${OUT_DIR}/grading.key --json)
string(JSON signedWith GET "${OUT}" head publicKey)
if(NOT signedWith STREQUAL publicKey)
  message(FATAL_ERROR "the batch signed with ${signedWith}, not ${publicKey}")
endif()
run(0 grade verify ${OUT_DIR}/gradebook.sqlite --key ${OUT_DIR}/grading.key.pub --json)
expect_json_equal("${OUT}" "ON" intact) # CMake reads JSON true as ON
expect_json_equal("${OUT}" "ON" signed holds)
expect_match("${csv}" "bob,'=HYPERLINK\\(1\\),")
expect_match("${csv}" "carol,,,no,0,")
run(0 grade export --db ${OUT_DIR}/gradebook.sqlite --assignment implicit-fantasies
    --format canvas -o ${OUT_DIR}/canvas.csv)
file(READ ${OUT_DIR}/canvas.csv canvas)
expect_match("${canvas}" "^Student,ID,SIS User ID,SIS Login ID,Section,Implicit Fantasies")
run(0 grade export --db ${OUT_DIR}/gradebook.sqlite --assignment implicit-fantasies
    --format moodle -o ${OUT_DIR}/moodle.csv)
run(0 grade export --db ${OUT_DIR}/gradebook.sqlite --assignment implicit-fantasies
    --format gradescope -o ${OUT_DIR}/gradescope)
file(READ ${OUT_DIR}/gradescope/dana/results.json results)
expect_json_equal("${results}" "100" score)
# alice and dana handed in the same solution; bob the starter, which is subtracted.
run(0 grade similar --db ${OUT_DIR}/gradebook.sqlite --assignment implicit-fantasies --json)
expect_json_equal("${OUT}" "alice" 0 first)
expect_json_equal("${OUT}" "dana" 0 second)
expect_json_equal("${OUT}" "1" 0 similarity)
string(JSON pairs LENGTH "${OUT}")
if(NOT pairs EQUAL 1)
  message(FATAL_ERROR "grade similar found ${pairs} pairs, not 1: ${OUT}")
endif()
run(1 grade export --db ${OUT_DIR}/nothere.sqlite --assignment implicit-fantasies
    --format csv -o ${OUT_DIR}/x.csv)
run(2 grade export --db ${OUT_DIR}/gradebook.sqlite --assignment implicit-fantasies
    --format excel -o ${OUT_DIR}/x.csv)
run(1 grade batch --assignment implicit-fantasies ${OUT_DIR}/nothere --db ${OUT_DIR}/g.sqlite)

# The grading benchmark runs end to end on a tiny class (figures: docs/grading.md).
run(0 bench grading --submissions 3 --jobs 1 --work ${OUT_DIR}/bench --json)
string(JSON n GET "${OUT}" submissions)
if(NOT n EQUAL 3)
  message(FATAL_ERROR "bench grading graded ${n} submissions, not 3")
endif()
string(JSON rows LENGTH "${OUT}" requirements)
if(NOT rows EQUAL 8)
  message(FATAL_ERROR "bench grading timed ${rows} requirements, not 8")
endif()
