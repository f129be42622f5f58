# cmake -DBUILD_DIR=... -DOUT=... -DSOURCE=... -P install_components_test.cmake
# Installs the components "student" and "instructor" into OUT and checks:
# the student's part has the executable, every example, manifest, starter
# and instructions, and not one reference solution; the instructor's part
# has every solution, in share/functionlab/instructor/ID/solution/; and the
# installed functionlab finds the installed courseware.
file(REMOVE_RECURSE "${OUT}")
foreach(component student instructor)
  execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD_DIR}" --component ${component}
                          --prefix "${OUT}/${component}"
                  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cmake --install --component ${component} failed: ${err}")
  endif()
endforeach()

set(student "${OUT}/student")
file(GLOB_RECURSE student_files RELATIVE "${student}" "${student}/*")
foreach(f ${student_files})
  if(f MATCHES "/solution/" OR f MATCHES "/solution$")
    message(FATAL_ERROR "the student's installation holds a solution: ${f}")
  endif()
endforeach()
foreach(wanted bin/functionlab share/functionlab/courseware/examples/watermelon.x3d)
  if(NOT EXISTS "${student}/${wanted}")
    message(FATAL_ERROR "the student's installation lacks ${wanted}")
  endif()
endforeach()

file(GLOB manifests RELATIVE "${SOURCE}/courseware/assignments"
     "${SOURCE}/courseware/assignments/*/manifest.json")
list(LENGTH manifests count)
if(count LESS 5)
  message(FATAL_ERROR "expected the course's assignments, found ${count}")
endif()
foreach(manifest ${manifests})
  get_filename_component(id "${manifest}" DIRECTORY)
  foreach(part manifest.json instructions.md starter.x3d)
    if(NOT EXISTS "${student}/share/functionlab/courseware/assignments/${id}/${part}")
      message(FATAL_ERROR "the student's installation lacks assignments/${id}/${part}")
    endif()
  endforeach()
  file(GLOB solutions RELATIVE "${SOURCE}/courseware/assignments/${id}"
       "${SOURCE}/courseware/assignments/${id}/solution/*")
  foreach(s ${solutions})
    if(NOT EXISTS "${OUT}/instructor/share/functionlab/instructor/${id}/${s}")
      message(FATAL_ERROR "the instructor's part lacks ${id}/${s}")
    endif()
  endforeach()
endforeach()

file(GLOB_RECURSE instructor_files RELATIVE "${OUT}/instructor" "${OUT}/instructor/*")
foreach(f ${instructor_files})
  if(NOT f MATCHES "^share/functionlab/instructor/[^/]+/solution/[^/]+$")
    message(FATAL_ERROR "the instructor's part holds more than solutions: ${f}")
  endif()
endforeach()

# The installed executable reads the installed courseware (examples listed
# from share/functionlab/courseware, not from the source tree).
execute_process(COMMAND "${student}/bin/functionlab" check
                        "${student}/share/functionlab/courseware/assignments/time/starter.x3d"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the installed functionlab cannot check an installed starter: ${out}${err}")
endif()
message(STATUS "student: ${student_files}")
