# End-to-end CLI tests (bad input, outputs, determinism, interrupt) driven by a shell script.
add_test(NAME cli COMMAND ${CMAKE_SOURCE_DIR}/tests/cli/cli_tests.sh $<TARGET_FILE:rcache>)
set_tests_properties(cli PROPERTIES LABELS cli TIMEOUT 300)
# Integrator selection end to end: --integrator, auto, Mitsuba aliases, nested wrappers, -D routing.
add_test(NAME cli_integrators COMMAND ${CMAKE_SOURCE_DIR}/tests/cli/integrator_tests.sh $<TARGET_FILE:rcache>)
set_tests_properties(cli_integrators PROPERTIES LABELS cli TIMEOUT 120)
