# Each CTest label selects the tests it should, with their timeouts: a list
# written unquoted into gtest_discover_tests' PROPERTIES keeps only its first
# item (LABELS core;grading became LABELS core, and the TIMEOUT after it was
# lost), so `ctest -L grading` ran no grading unit test. One test per test
# program is looked up by name; it must carry every label and the timeout.
# Invoked by CTest: cmake -DCTEST=path -DBUILD_DIR=dir -DCORE_ONLY=ON|OFF -P ...

# name | labels, comma-separated | timeout (seconds; - when none is set)
set(expected
  "CorpusManifest.EveryListedFileExists|core,scene|30"
  "Lexer.ExactLineAndColumnRanges|core,formula|-"
  "BatchGrading.AHangCostsItsOwnTimeNeverTheBatch|core,grading|120"
  "Assignments.ImplicitFantasiesHasTheRequiredIds|core,courseware|300"
  "MeshCache.TimeCountsOnlyWhenTheGeometryReadsIt|core,mesh|120"
  "Affine.InverseUndoesRandomMaps|core,field|60"
  "Animator.TimeSensorDrivesAnInterpolatorDrivesATransform|core,animation|30"
  "ChatCommands.Parse|core,classroom|120"
  "EffectColours.BlueGreenRedFromNothingToOneAndGreyForNaN|core,haptics|120"
  "haptics.UsbProducts.EachProductOnceAndTheFalconKnown|core,haptics|120")
if(NOT CORE_ONLY)
  list(APPEND expected
    "Highlighter.XmlNodesFieldsStringsAndTheFormulaInside|gui,editor|120"
    "CameraPose.AViewpointKeepsItsPlaceDirectionAndFieldOfView|gui,viewer|300"
    "RenderCommand.TheWatermelonIsRedInsideAndGreenOutside|cli,gui|300")
endif()

set(failures "")
foreach(entry IN LISTS expected)
  string(REPLACE "|" ";" parts "${entry}")
  list(GET parts 0 name)
  list(GET parts 1 labels)
  list(GET parts 2 timeout)
  string(REPLACE "," ";" labels "${labels}")
  string(REGEX REPLACE "\\." "\\\\." pattern "${name}")
  foreach(label IN LISTS labels)
    execute_process(COMMAND ${CTEST} -N -L "^${label}$" -R "^${pattern}$"
                    WORKING_DIRECTORY ${BUILD_DIR} OUTPUT_VARIABLE out RESULT_VARIABLE code)
    if(NOT out MATCHES "Total Tests: 1")
      list(APPEND failures "ctest -L ${label} does not select ${name}")
    endif()
  endforeach()
  execute_process(COMMAND ${CTEST} --show-only=json-v1 -R "^${pattern}$"
                  WORKING_DIRECTORY ${BUILD_DIR} OUTPUT_VARIABLE json)
  set(found "-")
  string(JSON count ERROR_VARIABLE err LENGTH "${json}" tests 0 properties)
  if(err OR NOT count)
    list(APPEND failures "${name}: not found, or without properties")
    continue()
  endif()
  math(EXPR lastProperty "${count} - 1")
  foreach(p RANGE 0 ${lastProperty})
    string(JSON pname GET "${json}" tests 0 properties ${p} name)
    if(pname STREQUAL "TIMEOUT")
      string(JSON found GET "${json}" tests 0 properties ${p} value)
    endif()
  endforeach()
  if(NOT (found STREQUAL timeout OR (NOT timeout STREQUAL "-" AND found EQUAL timeout)))
    list(APPEND failures "${name}: TIMEOUT ${found}, expected ${timeout}")
  endif()
endforeach()
if(failures)
  list(JOIN failures "\n  " text)
  message(FATAL_ERROR "labels or timeouts lost:\n  ${text}")
endif()
