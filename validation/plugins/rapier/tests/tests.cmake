# The Rapier executable adapter gjk2d-rapier (docs/peers/rapier.md), driven by
# rapier_driver.py here (a small host side of the protocol, tests/plugins/adapter_driver.py's):
# its handshake with the `input ... world` line and the contract, hand-derived cases in world
# points, what it refuses and why, bad requests, nan and inf, a time request. 77 (skipped) when
# the adapter was not built (no node or build/npm/rapier: scripts/setup_npm.sh), a failure under
# GJK2D_REQUIRE_ALL=1. Included by tests/plugins/CMakeLists.txt.
set(_rapier_driver ${CMAKE_CURRENT_LIST_DIR}/rapier_driver.py)
set(_rapier_adapter ${PROJECT_BINARY_DIR}/validation/plugins/gjk2d-rapier)
set(_rapier_checks
    "handshake|declares one f32 variant in world points, its contract with parry's tolerances"
    "squares-3-apart|two unit squares 3 apart give 3 and witnesses on the facing edges"
    "overlap|overlapping squares give minus the depth 0.5 and a penetration pair 0.5 apart"
    "point-segment|a point and a slanted segment give sqrt 2 and the foot, in world coordinates"
    "discs|two discs give the gap minus both radii"
    "discs-overlap|discs penetrating by 1 give -1 and a pair on their boundaries"
    "rounded|a disc and a rounded square give 1.75 within parry's GJK tolerance"
    "rounded-overlap|rounded squares penetrating by 0.25 give -0.25 within the EPA tolerance"
    "far-apart|squares 999999 apart are answered (the prediction covers every finite distance)"
    "beyond-sqrt-f32-max|a point 2^64 away reads as touching (f32 overflow, pinned)"
    "dropped-vertex|a vertex turning by 0.57 degrees is dropped by parry (pinned)"
    "refusals|a transform other than the identity, no polygon, a rounded segment are refused"
    "coincident|3 coincident points get the error Rapier's hull throws there"
    "trap|a WebAssembly trap gets error for its id, a fresh instance the next request"
    "bad-requests|a bad request gets error for its id and the stream goes on"
    "nonfinite|nan and inf in a case are refused for its id"
    "time|a time request gives timed with positive totals for the loop and the preparation")
foreach(entry IN LISTS _rapier_checks)
  string(REPLACE "|" ";" entry "${entry}")
  list(GET entry 0 check)
  list(GET entry 1 what)
  add_test(NAME "plugins: rapier: ${what}"
           COMMAND Python3::Interpreter ${_rapier_driver} --adapter ${_rapier_adapter} --check ${check})
  set_tests_properties("plugins: rapier: ${what}" PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 60)
endforeach()
# Done when (docs/peers/rapier.md): on cases generated now with a seed drawn now,
# the report's Rapier answers are those of direct.js, a program of Rapier's own API alone, on the
# world points the protocol's rule gives, bit for bit (direct_check.py).
add_test(NAME "plugins: rapier: the report's answers are Rapier's own API's on cases made now, bit for bit"
         COMMAND Python3::Interpreter ${CMAKE_CURRENT_LIST_DIR}/direct_check.py --exe $<TARGET_FILE:gjk-validate>
                 --adapter ${_rapier_adapter} --node-path ${PROJECT_SOURCE_DIR}/build/npm/rapier/node_modules
                 --work ${CMAKE_CURRENT_BINARY_DIR}/ci/rapier-direct --family random:1000)
set_tests_properties("plugins: rapier: the report's answers are Rapier's own API's on cases made now, bit for bit"
                     PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 600)
