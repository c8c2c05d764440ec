# CTest's short fuzz run (cmake -P): a fresh copy of the seed corpus, then
# libFuzzer for SECONDS seconds on it. Fails on any finding, naming the saved
# input and how to rerun it.
#   -DFUZZER=<executable> -DSEEDS=<seed folder> -DWORK=<scratch folder>
#   -DSECONDS=<n> [-DSEED=<libFuzzer seed, 0 or absent: random>]
#   [-DEXTRA_ARGS="<libFuzzer flags separated by spaces>"]
foreach (required FUZZER SEEDS WORK SECONDS)
  if (NOT DEFINED ${required})
    message(FATAL_ERROR "RunShortFuzz.cmake: -D${required}=... is missing")
  endif ()
endforeach ()

# the seeds stay untouched in the source tree; the run grows its own copy
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/artifacts")
file(COPY "${SEEDS}/" DESTINATION "${WORK}/corpus")

separate_arguments(extra UNIX_COMMAND "${EXTRA_ARGS}")
if (DEFINED SEED AND NOT SEED STREQUAL "" AND NOT SEED EQUAL 0)
  list(APPEND extra -seed=${SEED})
endif ()
set(command "${FUZZER}" "${WORK}/corpus"
  -max_total_time=${SECONDS}
  -rss_limit_mb=2048
  -timeout=10
  -print_final_stats=1
  -print_funcs=0
  "-artifact_prefix=${WORK}/artifacts/"
  ${extra})
string(REPLACE ";" " " shown "${command}")
message(STATUS "${shown}")
execute_process(COMMAND ${command} RESULT_VARIABLE status)
if (NOT status EQUAL 0)
  file(GLOB findings "${WORK}/artifacts/*")
  message(FATAL_ERROR "the fuzzer stopped with status ${status}; saved input(s): ${findings}\n"
    "rerun one with: ${FUZZER} <input>")
endif ()
