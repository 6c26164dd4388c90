# The Box2D v3 adapter's own tests, included by tests/plugins/CMakeLists.txt (the adapter is built
# when GJK2D_BOX2D3_SOURCE names a Box2D v3 tree): hand-derived cases (hand.py), and its answers
# against b2ShapeDistance called directly by direct.c, linked with the adapter's own Box2D objects, on every case of the
# default campaign's families (docs/cli.md, `run`: random:200000, hard, engine).
if(TARGET gjk2d_box2d3_plugin)
  enable_language(C)
  add_executable(box2d3_direct ${CMAKE_CURRENT_LIST_DIR}/direct.c)
  set_target_properties(box2d3_direct PROPERTIES C_STANDARD 17 C_STANDARD_REQUIRED ON C_EXTENSIONS OFF)
  target_link_libraries(box2d3_direct PRIVATE gjk2d_box2d3_sources m)
  set(_box2d3_variant $<TARGET_PROPERTY:gjk2d_box2d3_plugin,GJK2D_VARIANT>)
  add_test(NAME "plugins: box2d-v3: hand-derived cases"
           COMMAND Python3::Interpreter ${CMAKE_CURRENT_LIST_DIR}/hand.py
                   --exe $<TARGET_FILE:gjk-validate> --plugin $<TARGET_FILE:gjk2d_box2d3_plugin>
                   --variant ${_box2d3_variant} --work ${_ci}/box2d3-hand
                   --bridge $<TARGET_FILE:gjk2d_adapter_bridge>)
  add_test(NAME "plugins: box2d-v3: the adapter's answers equal b2ShapeDistance called directly"
           COMMAND Python3::Interpreter ${CMAKE_CURRENT_LIST_DIR}/equal.py
                   --exe $<TARGET_FILE:gjk-validate> --plugin $<TARGET_FILE:gjk2d_box2d3_plugin>
                   --variant ${_box2d3_variant} --direct $<TARGET_FILE:box2d3_direct>
                   --work ${_ci}/box2d3-equal
                   --family random:200000 --family hard --family engine)
  set_tests_properties("plugins: box2d-v3: the adapter's answers equal b2ShapeDistance called directly"
                       PROPERTIES TIMEOUT 900 LABELS release-only)
  # release-only: scripts/test.sh leaves it out of the sanitize run, where it would repeat the
  # release comparison at several times the cost (214,000 cases) with Box2D's C files, which the
  # sanitize preset's CMAKE_CXX_FLAGS do not instrument, compiled alike.
  # `bench --against box2d-v3`: the adapter's own timing loop runs, cold and warm, and
  # the table has its two rows and the ratio column, the JSON their numbers (null when the loop
  # failed); no timing is asserted.
  add_test(NAME "plugins: box2d-v3: bench --against box2d-v3 prints its cold and warm rows"
           COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:gjk-validate> -DEXPECT=0
                   "-DARGS=bench|--family|random:300|--variants|double,double-warm|--against|box2d-v3|--json|${CMAKE_CURRENT_BINARY_DIR}/bench-against.json"
                   "-DEXPECT_STDOUT=box2d-v3               float  warm      300"
                   -DEXPECT_FILE=${CMAKE_CURRENT_BINARY_DIR}/bench-against.json
                   "-DEXPECT_JSON=against/cold/ns_per_query:NUMBER|against/warm/ns_per_query:NUMBER|variants/double/ratio_to_against:NUMBER|variants/double-warm/ratio_to_against:NUMBER"
                   -P ${PROJECT_SOURCE_DIR}/tests/validation/expect_exit.cmake)
  # Its prepared shapes (gjk2d_plugin_prepared) answer as distance_f, bit for bit
  # (tests/plugins/peers/prepared_equal.cpp).
  add_test(NAME "plugins: box2d-v3: prepared shapes answer as distance_f, bit for bit"
           COMMAND prepared_equal --plugin $<TARGET_FILE:gjk2d_box2d3_plugin>
                   --family random:500 --family hard --family engine)
else()
  # A user's clone has no Box2D v3 sources (no Debian package has them): an optional peer. Its
  # tests are one skipped entry that says why (scripts/test.sh prints it); in CI, where
  # ../shared/anchors/box2d-v3 is beside the clone, its absence stops the configure.
  gjk2d_tests_lack("no Box2D v3 sources: the Box2D v3 adapter and its 4 tests are not built"
                   "name a Box2D v3 source tree in GJK2D_BOX2D3_SOURCE, the environment or a CMake option: README.md, \"Box2D v3\"")
  add_test(NAME "plugins: box2d-v3: not built (no Box2D v3 sources)"
           COMMAND Python3::Interpreter -c "print('skipped: the Box2D v3 adapter and its 4 tests: no Box2D v3 sources given (name a tree in GJK2D_BOX2D3_SOURCE, the environment or a CMake option: README.md, \"Box2D v3\")'); raise SystemExit(77)")
  set_tests_properties("plugins: box2d-v3: not built (no Box2D v3 sources)" PROPERTIES SKIP_RETURN_CODE 77)
endif()
