# End-to-end CLI tests (bad input, outputs, determinism, interrupt) driven by a shell script.
add_test(NAME cli COMMAND ${CMAKE_SOURCE_DIR}/tests/cli/cli_tests.sh $<TARGET_FILE:rcache>)
set_tests_properties(cli PROPERTIES LABELS cli TIMEOUT 300)
# The merl BSDF end to end: generator, relative file name, render, bad file.
add_test(NAME cli_merl COMMAND ${CMAKE_SOURCE_DIR}/tests/cli/merl_tests.sh $<TARGET_FILE:rcache> $<TARGET_FILE:merl_generate>)
set_tests_properties(cli_merl PROPERTIES LABELS cli TIMEOUT 120)
# Integrator selection end to end: --integrator, auto, Mitsuba aliases, nested wrappers, -D routing.
add_test(NAME cli_integrators COMMAND ${CMAKE_SOURCE_DIR}/tests/cli/integrator_tests.sh $<TARGET_FILE:rcache>)
set_tests_properties(cli_integrators PROPERTIES LABELS cli TIMEOUT 120)
# Hostile inputs (issue 19): crashes, hangs, unbounded memory and lost output, each under limits.
add_test(NAME cli_hostile COMMAND ${CMAKE_SOURCE_DIR}/tests/cli/hostile_tests.sh $<TARGET_FILE:rcache>)
set_tests_properties(cli_hostile PROPERTIES LABELS cli TIMEOUT 600)
# Crop windows, walk-throughs with a shared cache and cache merging (issue 20).
add_test(NAME cli_walk COMMAND ${CMAKE_SOURCE_DIR}/tests/cli/walk_tests.sh $<TARGET_FILE:rcache>)
set_tests_properties(cli_walk PROPERTIES LABELS cli TIMEOUT 120)
# The Dask driver on a local two-worker cluster: tiled stills, a killed worker, an animation (issue 20).
add_test(NAME dask_driver COMMAND /usr/bin/python3 ${CMAKE_SOURCE_DIR}/tests/dask/dask_driver_test.py $<TARGET_FILE:rcache>)
set_tests_properties(dask_driver PROPERTIES LABELS dask TIMEOUT 300)
# --cluster slurm|pbs through dask-jobqueue with fake batch commands; skipped (77) without dask-jobqueue.
add_test(NAME dask_jobqueue COMMAND /usr/bin/python3 ${CMAKE_SOURCE_DIR}/tests/dask/jobqueue_test.py $<TARGET_FILE:rcache>)
set_tests_properties(dask_jobqueue PROPERTIES LABELS dask TIMEOUT 300 SKIP_RETURN_CODE 77)
# --time SECONDS (render/progressive.h): the budget honoured, whole passes, passes = a render of their spp.
add_test(NAME cli_progressive COMMAND ${CMAKE_SOURCE_DIR}/tests/cli/progressive_tests.sh $<TARGET_FILE:rcache>)
set_tests_properties(cli_progressive PROPERTIES LABELS cli TIMEOUT 180)
# rcache images and cache files identical for 1, 2 and 3 threads (issue 16: the cache's parallel steps).
add_test(NAME cli_thread_determinism COMMAND ${CMAKE_SOURCE_DIR}/tests/cli/thread_determinism_tests.sh $<TARGET_FILE:rcache>)
set_tests_properties(cli_thread_determinism PROPERTIES LABELS cli TIMEOUT 300)
# bench/agreement_stats.py (the corpus comparison's noise estimate): t tails, calibration, power.
add_test(NAME bench_agreement_stats COMMAND /usr/bin/python3 ${CMAKE_SOURCE_DIR}/tests/bench/agreement_stats_test.py)
set_tests_properties(bench_agreement_stats PROPERTIES LABELS bench TIMEOUT 60)
