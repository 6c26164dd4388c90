# The Bullet adapters' own tests (docs/peers.md, "Bullet"): hand-derived cases, included by
# tests/plugins/CMakeLists.txt.
if(TARGET gjk2d_bullet_float_plugin AND TARGET gjk2d_bullet_double_plugin)
  add_executable(bullet_peer_tests ${CMAKE_CURRENT_LIST_DIR}/test_bullet.cpp)
  target_compile_definitions(bullet_peer_tests PRIVATE
    GJK2D_BULLET_FLOAT_PLUGIN="$<TARGET_FILE:gjk2d_bullet_float_plugin>"
    GJK2D_BULLET_DOUBLE_PLUGIN="$<TARGET_FILE:gjk2d_bullet_double_plugin>"
    GJK2D_BULLET_VERSION="$<TARGET_PROPERTY:gjk2d_bullet_float_plugin,GJK2D_LIBRARY_VERSION>")
  target_include_directories(bullet_peer_tests PRIVATE ${PROJECT_SOURCE_DIR}/tests ${PROJECT_SOURCE_DIR}/tests/plugins/peers)
  target_link_libraries(bullet_peer_tests PRIVATE gjk2d_plugin Catch2::Catch2WithMain
                        ${CMAKE_DL_LIBS})
  add_dependencies(bullet_peer_tests gjk2d_bullet_float_plugin gjk2d_bullet_double_plugin)
  gjk2d_catch_tests(bullet_peer_tests "plugins: bullet: ")
endif()
