# The Box2D 2.4.1 adapter's contract held to Box2D itself (test_box2d.cpp): hand-derived cases,
# included by tests/plugins/CMakeLists.txt. (Its refusal of more than 256 points is checked in
# tests/plugins, plugin_ci.py box2d.)
if(TARGET gjk2d_box2d_plugin)
  add_executable(box2d_peer_tests ${CMAKE_CURRENT_LIST_DIR}/test_box2d.cpp)
  target_compile_definitions(box2d_peer_tests PRIVATE
    GJK2D_BOX2D_PLUGIN="$<TARGET_FILE:gjk2d_box2d_plugin>")
  target_include_directories(box2d_peer_tests PRIVATE ${PROJECT_SOURCE_DIR}/tests ${PROJECT_SOURCE_DIR}/tests/plugins/peers)
  target_link_libraries(box2d_peer_tests PRIVATE gjk2d_plugin Catch2::Catch2WithMain ${CMAKE_DL_LIBS})
  add_dependencies(box2d_peer_tests gjk2d_box2d_plugin)
  gjk2d_catch_tests(box2d_peer_tests "plugins: box2d-2.4: ")
endif()

# Its prepared shapes (gjk2d_plugin_prepared) answer as distance_f, bit for bit
# (tests/plugins/peers/prepared_equal.cpp).
if(TARGET gjk2d_box2d_plugin AND TARGET prepared_equal)
  add_test(NAME "plugins: box2d-2.4: prepared shapes answer as distance_f, bit for bit"
           COMMAND prepared_equal --plugin $<TARGET_FILE:gjk2d_box2d_plugin>
                   --family random:500 --family hard --family engine)
endif()
