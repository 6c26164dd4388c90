# The shipped executable adapters gjk2d-planck and gjk2d-geos (docs/peers.md), each driven by
# adapter_driver.py, a small host side of the protocol (version 2): handshake with the contract,
# hand-derived cases (the overlap ones against the declared contract, and planck's bug that breaks
# it), bad requests, a time request. 77 (skipped) when the adapter was not built (no node or
# build/npm/planck: scripts/setup_npm.sh; no python3-shapely), a failure under GJK2D_REQUIRE_ALL=1.
set(_driver ${CMAKE_CURRENT_SOURCE_DIR}/adapter_driver.py)
set(_adapters ${PROJECT_BINARY_DIR}/validation/plugins)
set(_checks
    "handshake|describes one double variant with radii and no vertex limit, and its contract"
    "squares-3-apart|two unit squares 3 apart give 3 and witnesses on the facing edges"
    "overlap|overlapping squares give 0 and the witness points docs/peers.md names"
    "point-segment|a point and a slanted segment give sqrt 2 and the foot"
    "radius|a disc and a rounded square give the gap minus both radii"
    "radius-overlap|discs whose radii overlap give 0 and the witness points docs/peers.md names"
    "circles-1.5|discs of radius 1 1.5 apart give 0 and one point, (0.75, 0) by the contract"
    "rotated-square|a square turned by (c, s) = (0.6, 0.8) gives 4.3 at its corner (0.7, 0.1)"
    "rotated-segment|a segment turned by (c, s) = (0.6, 0.8) gives 5 and the foot"
    "unnormalised-rotation|(c, s) = (1.2, 1.6) is used as given, not renormalised"
    "gap-below-1e-9|squares 5e-10 apart give the distance docs/peers.md names"
    "1000-points|a 1000-gon is taken (no vertex limit)"
    "bad-requests|a bad request gets error or refused for its id and the stream goes on"
    "nonfinite|nan and inf in a case get an answer for its id"
    "time|a time request gives timed with positive totals for the loop and the preparation")
foreach(peer IN ITEMS planck geos)
  foreach(entry IN LISTS _checks)
    string(REPLACE "|" ";" entry "${entry}")
    list(GET entry 0 check)
    list(GET entry 1 what)
    add_test(NAME "plugins: ${peer}: ${what}"
             COMMAND Python3::Interpreter ${_driver} --adapter ${_adapters}/gjk2d-${peer}
                     --peer ${peer} --check ${check})
    set_tests_properties("plugins: ${peer}: ${what}" PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 60)
  endforeach()
endforeach()
