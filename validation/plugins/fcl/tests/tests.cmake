# The FCL adapter's own tests (docs/peers.md, "FCL"): hand-derived cases, included by
# tests/plugins/CMakeLists.txt.
if(TARGET gjk2d_fcl_plugin)
  add_executable(fcl_peer_tests ${CMAKE_CURRENT_LIST_DIR}/test_fcl.cpp)
  target_compile_definitions(fcl_peer_tests PRIVATE
    GJK2D_FCL_PLUGIN="$<TARGET_FILE:gjk2d_fcl_plugin>" GJK2D_FCL_VERSION="$<TARGET_PROPERTY:gjk2d_fcl_plugin,GJK2D_LIBRARY_VERSION>")
  target_include_directories(fcl_peer_tests PRIVATE ${PROJECT_SOURCE_DIR}/tests ${PROJECT_SOURCE_DIR}/tests/plugins/peers)
  target_link_libraries(fcl_peer_tests PRIVATE gjk2d_plugin Catch2::Catch2WithMain ${CMAKE_DL_LIBS})
  add_dependencies(fcl_peer_tests gjk2d_fcl_plugin)
  gjk2d_catch_tests(fcl_peer_tests "plugins: fcl: ")
endif()

# Its prepared shapes (gjk2d_plugin_prepared) answer as distance_d, bit for bit, both solvers
# (tests/plugins/peers/prepared_equal.cpp; GST_LIBCCD's aborts on some hard cases are counted).
if(TARGET gjk2d_fcl_plugin AND TARGET prepared_equal)
  add_test(NAME "plugins: fcl: prepared shapes answer as distance_d, bit for bit"
           COMMAND prepared_equal --plugin $<TARGET_FILE:gjk2d_fcl_plugin>
                   --family random:500 --family hard --family engine)
endif()
