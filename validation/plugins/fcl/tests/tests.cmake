# The FCL adapter's own tests (docs/peers/fcl.md): hand-derived cases, included by
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

# Its prepared shapes (gjk2d_plugin_prepared) answer as distance_d, bit for bit, every variant
# (tests/plugins/peers/prepared_equal.cpp; GST_LIBCCD's aborts on some hard cases are counted), but
# the signed one's distance and points within 1e-13 relative: FCL's EPA pair moves in its last bits
# with the heap addresses of its polytope (the largest difference measured on these families:
# 4.3e-15; docs/peers/fcl.md).
if(TARGET gjk2d_fcl_plugin AND TARGET prepared_equal)
  add_test(NAME "plugins: fcl: prepared shapes answer as distance_d, bit for bit"
           COMMAND prepared_equal --plugin $<TARGET_FILE:gjk2d_fcl_plugin>
                   --family random:500 --family hard --family engine
                   --within fcl-0.7-libccd-signed 1e-13)
endif()

# The direct loop (direct_loop.cpp): FCL called on shapes built once, timed beside the adapter's
# prepared queries by hand (its command is in its header comment; docs/peers/fcl.md). Its CTest
# only checks that it runs and that its distances on 50 cases are the adapter's, both solvers.
if(TARGET gjk2d_fcl_plugin)
  find_package(nlohmann_json 3 REQUIRED) # the case file (its imported target is validation/'s)
  find_package(PkgConfig QUIET)
  pkg_check_modules(GJK2D_FCL_DIRECT QUIET fcl)
endif()
if(TARGET gjk2d_fcl_plugin AND GJK2D_FCL_DIRECT_FOUND)
  set(_fcl_direct_flags ${GJK2D_FCL_DIRECT_CFLAGS_OTHER})
  list(FILTER _fcl_direct_flags EXCLUDE REGEX "^-std=")
  add_executable(fcl_direct_loop ${CMAKE_CURRENT_LIST_DIR}/direct_loop.cpp)
  target_include_directories(fcl_direct_loop PRIVATE ${PROJECT_SOURCE_DIR}/tests/plugins/peers)
  target_include_directories(fcl_direct_loop SYSTEM PRIVATE ${GJK2D_FCL_DIRECT_INCLUDE_DIRS})
  target_compile_options(fcl_direct_loop PRIVATE ${_fcl_direct_flags})
  target_link_libraries(fcl_direct_loop PRIVATE gjk2d_plugin nlohmann_json::nlohmann_json
                        ${GJK2D_FCL_DIRECT_LINK_LIBRARIES} ${CMAKE_DL_LIBS})
  foreach(_variant fcl-0.7-libccd fcl-0.7-indep fcl-0.7-libccd-signed)
    add_test(NAME "plugins: fcl: the direct loop runs, its distances are the adapter's (${_variant})"
             COMMAND fcl_direct_loop ${GJK2D_DIRECT_LOOP_CASES} --variant ${_variant} --check 50
                     --plugin $<TARGET_FILE:gjk2d_fcl_plugin>)
    set_tests_properties("plugins: fcl: the direct loop runs, its distances are the adapter's (${_variant})"
                         PROPERTIES FIXTURES_REQUIRED gjk2d_direct_loop_cases)
  endforeach()
endif()

# FCL's signed distance aborts on an assertion in libccd's EPA (ComputeVisiblePatch) on a kept hard
# case (signed-assert-cases.json, with its provenance): the runner counts one crash and goes on
# (signed_crash_check.py).
find_package(Python3 COMPONENTS Interpreter)
if(TARGET gjk2d_fcl_plugin AND Python3_Interpreter_FOUND)
  add_test(NAME "plugins: fcl: an assert in signed distance is one case's crash, the campaign goes on"
           COMMAND Python3::Interpreter ${CMAKE_CURRENT_LIST_DIR}/signed_crash_check.py
                   --exe $<TARGET_FILE:gjk-validate> --plugin $<TARGET_FILE:gjk2d_fcl_plugin>
                   --cases ${CMAKE_CURRENT_LIST_DIR}/signed-assert-cases.json
                   --work ${CMAKE_CURRENT_BINARY_DIR}/fcl-signed-crash)
endif()
