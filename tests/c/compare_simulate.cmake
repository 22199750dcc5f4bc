# bs_simulation_result_json gives `breakshot simulate`'s bytes: runs the
# command and tests/c/capi_simulate on every scenario of FILES and compares
# the outputs.
#   cmake -DCLI=... -DTOOL=... -DOUT=dir -DFILES="a;b" -P compare_simulate.cmake
file(MAKE_DIRECTORY ${OUT})
set(n 0)
foreach(f ${FILES})
  get_filename_component(name ${f} NAME_WE)
  execute_process(COMMAND ${CLI} simulate ${f} OUTPUT_FILE ${OUT}/${name}-cli.json
    RESULT_VARIABLE rc_cli)
  execute_process(COMMAND ${TOOL} ${f} OUTPUT_FILE ${OUT}/${name}-capi.json
    RESULT_VARIABLE rc_capi)
  if(NOT rc_cli EQUAL 0 OR NOT rc_capi EQUAL 0)
    message(FATAL_ERROR "${f}: breakshot simulate exited ${rc_cli}, capi_simulate ${rc_capi}")
  endif()
  file(SHA256 ${OUT}/${name}-cli.json a)
  file(SHA256 ${OUT}/${name}-capi.json b)
  if(NOT a STREQUAL b)
    message(FATAL_ERROR "${f}: the C API's result differs from breakshot simulate's "
      "(${OUT}/${name}-capi.json, ${OUT}/${name}-cli.json)")
  endif()
  math(EXPR n "${n} + 1")
endforeach()
if(n EQUAL 0)
  message(FATAL_ERROR "no scenario compared")
endif()
message(STATUS "${n} scenarios: the C API's results are breakshot simulate's bytes")
