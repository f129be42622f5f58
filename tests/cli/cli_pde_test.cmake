# pde fit, mesh MODEL.pde and bench pde as a user runs them: exit codes, the
# JSON figures, a located refusal, and the benchmark's rows with its peers.
# -DFUNCTIONLAB -DMESH (a small OBJ) -DOUT_DIR
file(REMOVE_RECURSE "${OUT_DIR}")
file(MAKE_DIRECTORY "${OUT_DIR}")

function(run expected)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL expected)
    message(FATAL_ERROR "${ARGN}: exit ${rc}, wanted ${expected}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()

run(0 ${FUNCTIONLAB} pde fit ${MESH} -o ${OUT_DIR}/m.pde --patches 4 --radii 4 --json
    --scene ${OUT_DIR}/m.x3d)
string(JSON patches GET "${out}" patches)
string(JSON bytes GET "${out}" bytes)
string(JSON rms GET "${out}" rms)
if(patches LESS 4 OR bytes LESS 20 OR NOT EXISTS ${OUT_DIR}/m.pde OR NOT EXISTS ${OUT_DIR}/m.x3d)
  message(FATAL_ERROR "pde fit: ${out}")
endif()
run(0 ${FUNCTIONLAB} mesh ${OUT_DIR}/m.pde --resolution 16 -o ${OUT_DIR}/m.obj)
run(0 ${FUNCTIONLAB} check ${OUT_DIR}/m.x3d)
run(0 ${FUNCTIONLAB} pde fit ${MESH} --patches 2 --formula 1 -o ${OUT_DIR}/patch.x3dv)
run(0 ${FUNCTIONLAB} check ${OUT_DIR}/patch.x3dv)

# Not an OBJ: located, exit 1.
file(WRITE ${OUT_DIR}/page.obj "<html>\n<body>a page</body>\n")
run(1 ${FUNCTIONLAB} pde fit ${OUT_DIR}/page.obj -o ${OUT_DIR}/x.pde)
if(NOT err MATCHES "page.obj:1:1: '<html>' is not an OBJ mesh statement")
  message(FATAL_ERROR "not located: ${err}")
endif()
# A model that is not one: located, exit 1.
file(WRITE ${OUT_DIR}/bad.pde "FLPDE text 1\nbox 0 0 0 1 1 1\npatch radii 1 a x\n")
run(1 ${FUNCTIONLAB} mesh ${OUT_DIR}/bad.pde -o ${OUT_DIR}/bad.obj)
if(NOT err MATCHES "bad.pde:3:17: expected a, not 'x'")
  message(FATAL_ERROR "not located: ${err}")
endif()

# The benchmark: every method's rows, each with an error measured.
execute_process(COMMAND ${FUNCTIONLAB} bench pde ${MESH} --patches 2 --draco 8 --simplify 0.01
                        --samples 2000 --json
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 1 AND err MATCHES "built without Draco")
  message(STATUS "bench pde: no peers in this build (${err})")
elseif(NOT rc EQUAL 0)
  message(FATAL_ERROR "bench pde: exit ${rc}\n${out}\n${err}")
else()
  foreach(method pde draco simplify\\+draco)
    if(NOT out MATCHES "\"method\": \"${method}\"")
      message(FATAL_ERROR "bench pde: no ${method} row\n${out}")
    endif()
  endforeach()
  if(NOT out MATCHES "\"method\": \"draco\", \"setting\": \"qp 8\", \"bytes\": [0-9]+, \"rms\": [0-9]")
    message(FATAL_ERROR "bench pde: the draco row has no error\n${out}")
  endif()
endif()
