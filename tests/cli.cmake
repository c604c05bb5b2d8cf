# End-to-end CLI tests (bad input, outputs, determinism, interrupt) driven by a shell script.
add_test(NAME cli COMMAND ${CMAKE_SOURCE_DIR}/tests/cli/cli_tests.sh $<TARGET_FILE:rcache>)
set_tests_properties(cli PROPERTIES LABELS cli TIMEOUT 300)
# Hostile inputs (issue 19): crashes, hangs, unbounded memory and lost output, each under limits.
add_test(NAME cli_hostile COMMAND ${CMAKE_SOURCE_DIR}/tests/cli/hostile_tests.sh $<TARGET_FILE:rcache>)
set_tests_properties(cli_hostile PROPERTIES LABELS cli TIMEOUT 600)
