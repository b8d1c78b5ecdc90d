# How a test is registered: one call per test binary or script, so every test gets the
# same lavapipe and sanitizer environment, a label naming its kind (its folder under
# tests/: `ctest -L e2e` runs that group) and a time limit.
#
#   raytracer_gtest(NAME KIND SOURCES file... LIBRARIES lib... [TIMEOUT s] [PRE_TEST])
#     A GoogleTest binary, each of its cases a ctest test. LIBRARIES: only what the test
#     uses (a test that opens no window does not link raytracer_window). PRE_TEST lists
#     the cases when ctest runs rather than when the binary is built (for cases read from
#     files). TIMEOUT per case, default 300.
#   raytracer_script_test(NAME KIND COMMAND program arg... [TIMEOUT s])
#     One ctest test running COMMAND (a shell or python script, a tool); default 300 s.
include(GoogleTest)

function(raytracer_gtest name kind)
    cmake_parse_arguments(PARSE_ARGV 2 ARG "PRE_TEST" "TIMEOUT" "SOURCES;LIBRARIES")
    if(NOT ARG_TIMEOUT)
        set(ARG_TIMEOUT 300)
    endif()
    set(discovery_mode POST_BUILD)
    if(ARG_PRE_TEST)
        set(discovery_mode PRE_TEST)
    endif()
    add_executable(${name} ${ARG_SOURCES})
    target_link_libraries(${name} PRIVATE ${ARG_LIBRARIES} GTest::gtest_main project_warnings)
    target_compile_definitions(${name} PRIVATE ${TEST_PATH_DEFINITIONS})
    # The environment through `cmake -E env` as the test's launcher, which gtest_discover_tests
    # uses for the discovery run and every case: given as the ENVIRONMENT property, the list
    # lost all but its first entry on the way (the sanitizer options and VK_DRIVER_FILES).
    set_property(TARGET ${name} PROPERTY CROSSCOMPILING_EMULATOR
                 ${CMAKE_COMMAND} -E env ${TEST_ENVIRONMENT})
    gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 DISCOVERY_MODE ${discovery_mode}
        PROPERTIES TIMEOUT ${ARG_TIMEOUT} LABELS ${kind})
endfunction()

function(raytracer_script_test name kind)
    cmake_parse_arguments(PARSE_ARGV 2 ARG "" "TIMEOUT" "COMMAND")
    if(NOT ARG_TIMEOUT)
        set(ARG_TIMEOUT 300)
    endif()
    add_test(NAME ${name} COMMAND ${ARG_COMMAND})
    set_tests_properties(${name} PROPERTIES TIMEOUT ${ARG_TIMEOUT} LABELS ${kind}
                         ENVIRONMENT "${TEST_ENVIRONMENT}")
endfunction()
