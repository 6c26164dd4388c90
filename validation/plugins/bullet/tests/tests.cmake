# The Bullet adapters' own tests (docs/peers/bullet.md): hand-derived cases, included by
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

# Their prepared shapes (gjk2d_plugin_prepared) answer as distance_f / distance_d, bit for bit
# (tests/plugins/peers/prepared_equal.cpp).
foreach(_precision float double)
  if(TARGET gjk2d_bullet_${_precision}_plugin AND TARGET prepared_equal)
    add_test(NAME "plugins: bullet: ${_precision}: prepared shapes answer as the plain call, bit for bit"
             COMMAND prepared_equal --plugin $<TARGET_FILE:gjk2d_bullet_${_precision}_plugin>
                     --family random:500 --family hard --family engine)
  endif()
endforeach()

# The prisms' half height on penetrating cases (test_prism_height.cpp): Bullet in double called
# directly (its own pkg-config flags, BT_USE_DOUBLE_PRECISION), beside the adapter.
if(TARGET gjk2d_bullet_double_plugin)
  find_package(PkgConfig QUIET)
  pkg_check_modules(GJK2D_BULLET_TEST_DOUBLE QUIET bullet-float64)
endif()
if(TARGET gjk2d_bullet_double_plugin AND GJK2D_BULLET_TEST_DOUBLE_FOUND)
  add_executable(bullet_prism_height_tests ${CMAKE_CURRENT_LIST_DIR}/test_prism_height.cpp)
  target_compile_definitions(bullet_prism_height_tests PRIVATE
    GJK2D_BULLET_DOUBLE_PLUGIN="$<TARGET_FILE:gjk2d_bullet_double_plugin>")
  target_include_directories(bullet_prism_height_tests PRIVATE ${PROJECT_SOURCE_DIR}/tests
                             ${PROJECT_SOURCE_DIR}/tests/plugins/peers)
  target_include_directories(bullet_prism_height_tests SYSTEM PRIVATE
                             ${GJK2D_BULLET_TEST_DOUBLE_INCLUDE_DIRS})
  target_compile_options(bullet_prism_height_tests PRIVATE ${GJK2D_BULLET_TEST_DOUBLE_CFLAGS_OTHER})
  target_link_libraries(bullet_prism_height_tests PRIVATE gjk2d_plugin Catch2::Catch2WithMain
                        ${GJK2D_BULLET_TEST_DOUBLE_LINK_LIBRARIES} ${CMAKE_DL_LIBS})
  add_dependencies(bullet_prism_height_tests gjk2d_bullet_double_plugin)
  gjk2d_catch_tests(bullet_prism_height_tests "plugins: bullet prism height: ")
endif()

# The direct loops (direct_loop.cpp, built once per precision as the adapter): Bullet called on
# shapes built once, timed beside the adapter's prepared queries by hand (the command is in the
# source's header comment; docs/peers/bullet.md). Their CTests only check that they run and that
# their distances on 50 cases are the adapter's.
find_package(nlohmann_json 3 REQUIRED) # the case file (its imported target is validation/'s)
find_package(PkgConfig QUIET)
foreach(_precision float double)
  if(_precision STREQUAL "float")
    set(_package bullet)
  else()
    set(_package bullet-float64)
  endif()
  if(NOT TARGET gjk2d_bullet_${_precision}_plugin)
    continue()
  endif()
  pkg_check_modules(GJK2D_BULLET_DIRECT_${_precision} QUIET ${_package})
  if(NOT GJK2D_BULLET_DIRECT_${_precision}_FOUND)
    continue()
  endif()
  set(_target bullet_direct_loop_${_precision})
  add_executable(${_target} ${CMAKE_CURRENT_LIST_DIR}/direct_loop.cpp)
  target_include_directories(${_target} PRIVATE ${PROJECT_SOURCE_DIR}/tests/plugins/peers)
  target_include_directories(${_target} SYSTEM PRIVATE
                             ${GJK2D_BULLET_DIRECT_${_precision}_INCLUDE_DIRS})
  target_compile_options(${_target} PRIVATE ${GJK2D_BULLET_DIRECT_${_precision}_CFLAGS_OTHER})
  target_link_libraries(${_target} PRIVATE gjk2d_plugin nlohmann_json::nlohmann_json
                        ${GJK2D_BULLET_DIRECT_${_precision}_LINK_LIBRARIES} ${CMAKE_DL_LIBS})
  # Bullet's depth against the prisms' half height (depth_height.cpp; docs/peers/prisms.md): a measuring program; its CTest checks the adapter's rule on a few cases.
  set(_depth bullet_depth_height_${_precision})
  add_executable(${_depth} ${CMAKE_CURRENT_LIST_DIR}/depth_height.cpp)
  target_include_directories(${_depth} PRIVATE ${PROJECT_SOURCE_DIR}/tests/plugins/peers)
  target_include_directories(${_depth} SYSTEM PRIVATE
                             ${GJK2D_BULLET_DIRECT_${_precision}_INCLUDE_DIRS})
  target_compile_options(${_depth} PRIVATE ${GJK2D_BULLET_DIRECT_${_precision}_CFLAGS_OTHER})
  target_link_libraries(${_depth} PRIVATE gjk2d_plugin nlohmann_json::nlohmann_json
                        ${GJK2D_BULLET_DIRECT_${_precision}_LINK_LIBRARIES} ${CMAKE_DL_LIBS})
  add_test(NAME "plugins: bullet: ${_precision}: the depth-height program answers as the adapter at its half height"
           COMMAND ${_depth} ${GJK2D_DIRECT_LOOP_CASES} --check 50
                   --plugin $<TARGET_FILE:gjk2d_bullet_${_precision}_plugin>)
  set_tests_properties("plugins: bullet: ${_precision}: the depth-height program answers as the adapter at its half height"
                       PROPERTIES FIXTURES_REQUIRED gjk2d_direct_loop_cases)
  add_test(NAME "plugins: bullet: ${_precision}: the direct loop runs, its distances are the adapter's"
           COMMAND ${_target} ${GJK2D_DIRECT_LOOP_CASES} --check 50
                   --plugin $<TARGET_FILE:gjk2d_bullet_${_precision}_plugin>)
  set_tests_properties("plugins: bullet: ${_precision}: the direct loop runs, its distances are the adapter's"
                       PROPERTIES FIXTURES_REQUIRED gjk2d_direct_loop_cases)
endforeach()
