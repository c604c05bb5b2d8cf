# End-to-end CLI tests (bad input, outputs, determinism, interrupt) driven by a shell script.
add_test(NAME cli COMMAND ${CMAKE_SOURCE_DIR}/tests/cli/cli_tests.sh $<TARGET_FILE:rcache>)
set_tests_properties(cli PROPERTIES LABELS cli TIMEOUT 300)
