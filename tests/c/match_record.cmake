# A game of `breakshot match` played again through the C API gives the
# command's record byte for byte (tests/c/capi_match.c).
#   cmake -DCLI=... -DTOOL=... -DOUT=dir -DGAME=nine_ball -DPLAYERS=a,b -DSEED=s -P match_record.cmake
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${CLI} match --game ${GAME} --players ${PLAYERS} --games 1 --seed ${SEED}
  --noise tournament --jobs 1 --records ${OUT} OUTPUT_QUIET RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "breakshot match exited ${rc}")
endif()
execute_process(COMMAND ${TOOL} ${GAME} ${OUT}/game-0001.json RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "capi_match exited ${rc}")
endif()
