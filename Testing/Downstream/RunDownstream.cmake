# Installs the build tree into a scratch prefix, then configures, builds and runs a tiny
# project against it with find_package(VTKGlobe), and imports the installed Python package.
# Arguments: -DBUILD_DIR=... -DWORK_DIR=... -DSOURCE_DIR=... -DPYTHON=... -DPYTHON_DEST=...
file(REMOVE_RECURSE "${WORK_DIR}")
set(prefix "${WORK_DIR}/install")

function (run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}${err}")
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}")
  endif ()
endfunction ()

run("${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}")
run("${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${WORK_DIR}/build"
  "-DCMAKE_PREFIX_PATH=${prefix}" -DCMAKE_BUILD_TYPE=Release)
run("${CMAKE_COMMAND}" --build "${WORK_DIR}/build")
run("${WORK_DIR}/build/downstream")
if (PYTHON)
  run("${CMAKE_COMMAND}" -E env "PYTHONPATH=${prefix}/${PYTHON_DEST}" "${PYTHON}"
    "${CMAKE_CURRENT_LIST_DIR}/check_install.py")
endif ()
message("downstream project built and ran against ${prefix}")
