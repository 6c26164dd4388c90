# The Jolt Physics executable adapter gjk2d-jolt (docs/peers/jolt.md), driven by
# jolt_driver.py (adapter_driver.py's host side of the protocol): the handshake with its input line
# and contract, hand-derived cases (apart, overlapping, deep in the plane, far apart, a nearly
# collinear point, a centre of mass that is not a float, a segment), refusals, bad requests, nan
# and inf, a time request. 77 (skipped) when the adapter was not built (no node or build/npm/jolt:
# scripts/setup_npm.sh), a failure under GJK2D_REQUIRE_ALL=1.
set(_jolt_checks
    "handshake|declares one float no-radius variant, its input world, its contract with sources"
    "squares-3-apart|two unit squares 3 apart give 3 and witnesses on the facing edges"
    "overlap|overlapping squares give minus the depth 0.5 and a penetration pair"
    "deep-in-plane|the prisms keep a deep penetration in the plane: depths 5 and 10"
    "far-apart|squares 999 apart are answered within the contract's 1e-4"
    "hull-tolerance|mHullTolerance 0 keeps a point 4.9e-4 off its hull's edge"
    "centre-of-mass|a triangle and a square whose centres of mass are not floats: within a few ulps"
    "segment|a segment's flat prism is answered"
    "refusals|a transform, a point, a radius, 129 points, a non-float are refused with the reason"
    "bad-requests|a bad request gets error or refused for its id and the stream goes on"
    "nonfinite|nan and inf in a case get an answer for its id"
    "time|a time request gives timed with the loop and the preparation")
foreach(entry IN LISTS _jolt_checks)
  string(REPLACE "|" ";" entry "${entry}")
  list(GET entry 0 check)
  list(GET entry 1 what)
  add_test(NAME "plugins: jolt: ${what}"
           COMMAND Python3::Interpreter ${CMAKE_CURRENT_LIST_DIR}/jolt_driver.py
                   --adapter ${PROJECT_BINARY_DIR}/validation/plugins/gjk2d-jolt --check ${check})
  set_tests_properties("plugins: jolt: ${what}" PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 60)
endforeach()
