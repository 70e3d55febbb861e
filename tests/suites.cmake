# Each doctest test suite is one ctest test, so `ctest` output names the area that failed.
# The suites are read from the test sources (every TEST_SUITE("NAME")): a suite that
# exists, runs. Editing a test source configures again, so a new suite is found at once;
# the suites_registered test checks the list against the binary's own.
# With RASTER_TEST_SUITES_ONLY, TEST_SOURCES keeps only the sources declaring one of those
# suites and those declaring none (main, shared helpers), and only those suites register.
# Each suite also gets a ctest label the configurations select by (ctest -L / -LE):
# command_line when every source declaring it is in tests/apps/ (the suites that check the
# program's options, files and messages, not the pipeline's bytes), pipeline otherwise. The
# tests below are labelled harness (Python and Chromium) and micro (the microbenchmarks).
set(RASTER_TEST_SUITES "")
set(pipeline_suites "")
set(kept_sources "")
foreach(source ${TEST_SOURCES})
  file(STRINGS ${source} declared REGEX "TEST_SUITE(_BEGIN)?\\(\"[^\"]+\"\\)")
  set(keep TRUE)
  if(RASTER_TEST_SUITES_ONLY AND declared)
    set(keep FALSE)
  endif()
  set(source_suites "")
  foreach(line ${declared})
    string(REGEX REPLACE ".*TEST_SUITE(_BEGIN)?\\(\"([^\"]+)\"\\).*" "\\2" suite "${line}")
    list(APPEND source_suites ${suite})
    if(NOT source MATCHES "/tests/apps/")
      list(APPEND pipeline_suites ${suite})
    endif()
    if(suite IN_LIST RASTER_TEST_SUITES_ONLY)
      set(keep TRUE)
    endif()
  endforeach()
  if(keep)
    list(APPEND kept_sources ${source})
    list(APPEND RASTER_TEST_SUITES ${source_suites})
  endif()
endforeach()
set(TEST_SOURCES ${kept_sources})
list(REMOVE_DUPLICATES RASTER_TEST_SUITES)
list(SORT RASTER_TEST_SUITES)
foreach(wanted ${RASTER_TEST_SUITES_ONLY})
  if(NOT wanted IN_LIST RASTER_TEST_SUITES)
    message(FATAL_ERROR "RASTER_TEST_SUITES_ONLY names ${wanted}, which no test source declares")
  endif()
endforeach()
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${TEST_SOURCES})
foreach(suite ${RASTER_TEST_SUITES})
  add_test(NAME ${suite} COMMAND raster_tests --test-suite=${suite} --no-intro)
  if(suite IN_LIST pipeline_suites)
    set(label pipeline)
  else()
    set(label command_line)
  endif()
  set_tests_properties(${suite} PROPERTIES ENVIRONMENT "RASTER_SOURCE_DIR=${CMAKE_SOURCE_DIR}" LABELS ${label})
endforeach()
# The longest suites start first, so that `ctest -j` runs the short ones beside them and no
# long one is left running alone at the end (a fresh clone has no Testing/ cost data, and
# ctest would start them in name order: under ASan + UBSan, views, 79 s, started last).
# Their costs are the seconds each took under ASan + UBSan, the longest configuration
# (a fresh clone's CI run of ad60a01: docs/notes/2026-12-02-ci-minutes-2.md); scene_deferred,
# among the longest with SIMD off, by its seconds there, and the harness tests, which only
# the release run has, ahead of its 10-second suites. A suite a configuration does not build
# is skipped. The costs only order the suites: each still runs whole.
set(suite_costs determinism_paths 100 views 80 determinism 60 trace 40 scene_deferred 36 hostile 35
    report 31 gl_math 28 cli 26 stability 25 sweep 21 memory 20 methods 19 scene_pbr 18)
while(suite_costs)
  list(POP_FRONT suite_costs suite cost)
  if(suite IN_LIST RASTER_TEST_SUITES)
    set_tests_properties(${suite} PROPERTIES COST ${cost})
  endif()
endwhile()
# Every suite the binary holds is one of the list above (a suite declared in a way the
# scan above does not read would otherwise never run).
add_test(NAME suites_registered COMMAND ${CMAKE_COMMAND} -DBINARY=$<TARGET_FILE:raster_tests>
         "-DEXPECTED=${RASTER_TEST_SUITES}" -P ${CMAKE_CURRENT_LIST_DIR}/check_suites.cmake)
if(RASTER_TEST_SUITES_ONLY)
  return()   # the tests below run the command line, the microbenchmarks and Python
endif()


# The microbenchmarks (bench/micro, built when Google Benchmark is found): every family runs
# once, briefly, and the JSON it writes must name them all.
# The three largest gather working sets are left out (their misses take the longest).
if(benchmark_FOUND)
  set(micro_peaks "")
  if(NOT raster_use_avx2)
    set(micro_peaks --no-peaks)   # the peaks are AVX2 intrinsics
  endif()
  add_test(NAME micro_smoke COMMAND python3 ${CMAKE_SOURCE_DIR}/bench/run_micro.py --check ${micro_peaks}
           --binary $<TARGET_FILE:raster_micro> --out ${CMAKE_BINARY_DIR}/micro_smoke.json --min-time 0.001
           "--filter=-:(65536|131072|262144)$")
  set_tests_properties(micro_smoke PROPERTIES TIMEOUT 60 LABELS micro)
endif()

# Debian's Python, which has the Debian packages (matplotlib, distributed); a python3 earlier
# in PATH, such as a pyenv shim, may not.
if(EXISTS /usr/bin/python3)
  set(TEST_PYTHON /usr/bin/python3)
else()
  set(TEST_PYTHON python3)
endif()

# bench/dask_sweep.py on a real 2-worker LocalCluster (python3-distributed), one worker
# killed under a shard: the merged sweep must equal `raster sweep`'s byte for byte.
add_test(NAME dask_sweep COMMAND ${TEST_PYTHON} ${CMAKE_SOURCE_DIR}/tests/apps/dask_sweep_test.py $<TARGET_FILE:raster_cli>
         ${CMAKE_SOURCE_DIR})
set_tests_properties(dask_sweep PROPERTIES TIMEOUT 300 ENVIRONMENT "RASTER_SOURCE_DIR=${CMAKE_SOURCE_DIR}" LABELS harness
                     COST 20)

# bench/goal_runs.py, the issues' speed-goal protocol, on tiny frames: its verdicts follow
# the runs' ratios, its JSON and table agree, bad input exits 2 before any run.
add_test(NAME goal_runs COMMAND ${TEST_PYTHON} ${CMAKE_SOURCE_DIR}/tests/apps/goal_runs_test.py $<TARGET_FILE:raster_cli>
         ${CMAKE_SOURCE_DIR})
set_tests_properties(goal_runs PROPERTIES TIMEOUT 300 LABELS harness COST 30)

# The bench scripts that chart or model files a person hands them (bench/sweep_chart.py,
# tradeoff_chart.py, scaling_model.py, target_hashes.py): the repository's own results drawn
# and modelled, anything else refused with exit 2 and a line naming it, before any work; and
# bench/random_frames.py's random frames against llvmpipe (a difference caught).
add_test(NAME bench_scripts COMMAND ${TEST_PYTHON} ${CMAKE_SOURCE_DIR}/tests/apps/bench_scripts_test.py
         $<TARGET_FILE:raster_cli> ${CMAKE_SOURCE_DIR})
set_tests_properties(bench_scripts PROPERTIES TIMEOUT 180 LABELS harness COST 45)

# bench/paper_bounds.py: a real run's frame beside its bounds at a given clock, the committed
# table (BENCHMARKS.md's) redrawn from its runs, and a bounds file that no longer matches its
# scene's passes refused with exit 2.
add_test(NAME paper_bounds COMMAND ${TEST_PYTHON} ${CMAKE_SOURCE_DIR}/tests/apps/paper_bounds_test.py
         $<TARGET_FILE:raster_cli> ${CMAKE_SOURCE_DIR})
set_tests_properties(paper_bounds PROPERTIES TIMEOUT 180 LABELS harness COST 10)

# `raster report` opened in headless Chromium (chromium, chromium-driver, python3-selenium):
# every image loads at its file's size, no console error, table values equal their JSON.
add_test(NAME report_chromium COMMAND ${TEST_PYTHON} ${CMAKE_SOURCE_DIR}/tests/apps/report_chromium_test.py
         $<TARGET_FILE:raster_cli> ${CMAKE_SOURCE_DIR})
set_tests_properties(report_chromium PROPERTIES TIMEOUT 180 ENVIRONMENT "RASTER_SOURCE_DIR=${CMAKE_SOURCE_DIR}" LABELS harness
                     COST 30)
