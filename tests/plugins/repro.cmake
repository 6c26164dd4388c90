# `gjk-validate repro` (docs/peers.md, "Repro programs"): for each shipped peer's variant, the
# program repro writes, built or run as its comment says, prints the answer gjk-validate reports
# for the case, bit for bit, on an overlapping and a separated case (repro_check.py checks that
# the cases hold both). 77 (skipped, with the reason) when the variant is not built here; the Box2D
# v3 one needs the Box2D v3 sources (README.md, "Box2D v3"). Included by CMakeLists.txt here.
set(_repro ${CMAKE_CURRENT_SOURCE_DIR}/repro_check.py)
set(_box2d3_variant box2d-3-*) # not built: repro_check.py skips it
set(_box2d3_env "")
if(TARGET gjk2d_box2d3_plugin)
  set(_box2d3_variant $<TARGET_PROPERTY:gjk2d_box2d3_plugin,GJK2D_VARIANT>)
  set(_box2d3_env "|--env|BOX2D3=${GJK2D_BOX2D3_SOURCE}")
endif()
# variant|family|cases|what the cases are|more arguments (a variant ending in * is the first
# listed variant of that prefix: GEOS's name carries the installed GEOS version; a later --node-path
# replaces planck's)
set(_repros
    "planck-1.5.0|random:2000|random/1,random/2|random/1 (its overlap points) and random/2, and the bug report on the overlap|--expect-on-overlap|.md"
    "fcl-0.7-libccd|random:2000|random/1,random/2|random/1 and random/2"
    "fcl-0.7-indep|random:2000|random/1,random/2|random/1 and random/2"
    "fcl-0.7-indep|hard/scale-sweep:172|hard/scale-sweep/57-vertex-edge-gap-x1e-05,hard/scale-sweep/71-overlapping-x0.00037|hard/scale-sweep/57 and hard/scale-sweep/71, an overlap"
    "box2d-2.4.1|random:2000|random/1,random/2|random/1 and random/2"
    "bullet-3.24-double|random:2000|random/1,random/2|random/1 and random/2"
    "bullet-3.24-float|random:2000|random/1,random/2|random/1 and random/2"
    "${_box2d3_variant}|random:2000|random/1,random/2|random/1 and random/2${_box2d3_env}"
    "geos-*|random:2000|random/1,random/2|random/1 and random/2"
    "rapier2d-0.21.0|random:2000|random/1,random/2|random/1, a penetration, and random/2, on their world points|--node-path|${PROJECT_SOURCE_DIR}/build/npm/rapier/node_modules"
    "jolt-1.1.0|random:2000|random/1,random/2|random/1 and random/2|--node-path|${PROJECT_SOURCE_DIR}/build/npm/jolt/node_modules")
set(_k 0)
foreach(entry IN LISTS _repros)
  math(EXPR _k "${_k} + 1")
  string(REPLACE "|" ";" entry "${entry}")
  list(GET entry 0 variant)
  list(GET entry 1 family)
  list(GET entry 2 cases)
  list(GET entry 3 what)
  set(more "")
  list(LENGTH entry n)
  if(n GREATER 4)
    list(SUBLIST entry 4 -1 more)
  endif()
  string(REGEX REPLACE "\\$<.*>" "box2d-v3" shown "${variant}")
  string(REGEX REPLACE "-?\\*$" "" shown "${shown}")
  set(name "plugins: repro: ${shown}: the program prints the report's answer bit for bit (${what})")
  add_test(NAME "${name}"
           COMMAND Python3::Interpreter ${_repro} --exe $<TARGET_FILE:gjk-validate>
                   --variant ${variant} --family ${family} --cases ${cases}
                   --node-path ${PROJECT_SOURCE_DIR}/build/npm/planck/node_modules
                   --work ${_ci}/repro-${_k}-${shown} ${more})
  set_tests_properties("${name}" PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 600)
  # A peer's program against the report: the same comparison from either build. The first (planck,
  # with its bug report) also runs under the sanitizers, for repro's own code; the rest once.
  if(_k GREATER 1)
    set_tests_properties("${name}" PROPERTIES LABELS release-only)
  endif()
endforeach()
# What repro refuses, each with exit 2 and one line (docs/cli.md, "Exit codes"): a
# user's plugin, which has no template, and one of gjk2d's own variants.
add_test(NAME "plugins: repro: a plugin without a repro template is refused (exit 2)"
         COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:gjk-validate> -DEXPECT=2
                 "-DARGS=repro|--family|random:5|random/1|--no-default-plugins|--plugin|$<TARGET_FILE:test_plugin_good-but-quirky>|--variants|test-good-but-quirky|--out|${_ci}/repro-refused"
                 "-DEXPECT_STDERR=has no repro template"
                 -P ${PROJECT_SOURCE_DIR}/tests/validation/expect_exit.cmake)
add_test(NAME "plugins: repro: one of gjk2d's own variants is refused (exit 2)"
         COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:gjk-validate> -DEXPECT=2
                 "-DARGS=repro|--family|random:5|random/1|--variants|double|--out|${_ci}/repro-refused"
                 "-DEXPECT_STDERR=is one of gjk2d's own variants"
                 -P ${PROJECT_SOURCE_DIR}/tests/validation/expect_exit.cmake)
