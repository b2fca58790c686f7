# A bad input leaves the results of an earlier run as they were: runs GOOD
# (procsim arguments writing into OUT, emptied first), keeps the checksum of
# OUT/FILE, runs BAD (writing into the same OUT) and passes only if BAD exits
# non-zero with one line on stderr, OUT/FILE is byte for byte what GOOD wrote
# and no temporary is left in OUT.
#   cmake -DPROCSIM=... -DOUT=DIR -DFILE=NAME "-DGOOD=a;b" "-DBAD=c;d" -P keepsEarlierOutput.cmake
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${PROCSIM} ${GOOD} RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT status EQUAL 0 OR NOT EXISTS ${OUT}/${FILE})
  message(FATAL_ERROR "the earlier run (procsim ${GOOD}) did not write ${FILE}: status ${status}, ${err}")
endif()
file(SHA256 ${OUT}/${FILE} before)
execute_process(COMMAND ${PROCSIM} ${BAD} RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE err)
if(status EQUAL 0)
  message(FATAL_ERROR "procsim ${BAD}: the bad input was accepted")
endif()
if(NOT err MATCHES "^procsim: [^\n]*\n$")
  message(FATAL_ERROR "procsim ${BAD}: expected one line on stderr, got: ${err}")
endif()
if(NOT EXISTS ${OUT}/${FILE})
  message(FATAL_ERROR "procsim ${BAD} removed the earlier ${FILE}")
endif()
file(SHA256 ${OUT}/${FILE} after)
if(NOT before STREQUAL after)
  message(FATAL_ERROR "procsim ${BAD} changed the earlier ${FILE}")
endif()
file(GLOB_RECURSE temporaries ${OUT}/*.tmp)
if(temporaries)
  message(FATAL_ERROR "procsim ${BAD} left temporaries: ${temporaries}")
endif()
message(STATUS "${FILE} kept; ${err}")
