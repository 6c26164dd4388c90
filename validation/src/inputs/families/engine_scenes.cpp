// The engine families: queries recorded from Box2D 2.4.1 worlds (inputs/engine.hpp), a
// proximity and a time-of-impact family per scene.
//
// The make-up ranges are the values measured at the default count (2000) for seeds 1..10 and at 300
// cases for seeds 1..8 (`gjk-validate run --family engine[:300] --seed S`, report.json
// families[].makeup), widened by a margin; exact where Box2D fixes the value: every Box2D proxy has
// a radius (polygons and edges b2_polygonRadius = 0.01, circles their own), b2TimeOfImpact asks
// with useRadii = false (radius 0) and stops within b2_linearSlop / 4 of its target
// max(b2_linearSlop, rA + rB - 3 b2_linearSlop) = 0.005 for two skins of 0.01.
#include "inputs/families/rows.hpp"

#include <utility>

namespace gjkval::families
{
namespace
{
using S = EngineScene;
using K = EngineQueryKind;
constexpr double kSkin = 0.01; // b2_polygonRadius as a float: 0.00999999977

// Box2D 2.4.1's testbed pyramid on a long ground edge.
std::vector<EngineRow> pyramidRows()
{
    return {
        {{"pyramid-proximity", kDefaultEngineCount,
          "Box2D 2.4.1's testbed pyramid (10 to 20 rows of boxes of half size 0.3 to 0.6) resting "
          "on an 80 m edge, 600 steps at 60 Hz: per contact of the world's list, the query an "
          "engine makes (b2DistanceProxy of each fixture, the bodies' float transforms, radii "
          "used). Boxes touching within their 0.01 skins, a segment 100 times longer than the "
          "boxes, rotations that are unit vectors only to float rounding."},
         S::Pyramid,
         K::Proximity,
         {{"non-unit rotation fraction", M::NonUnitRotationFraction, 0.8, 1},
          {"rounded fraction (every proxy has a radius)", M::RadiusFraction, 1, 1},
          {"max polygon radius (b2_polygonRadius only)", M::MaxPolygonRadius, 0.99 * kSkin,
           1.01 * kSkin},
          {"min vertices (the ground edge)", M::MinVertices, 2, 2},
          {"max vertices", M::MaxVertices, 4, 4},
          {"overlapping fraction", M::OverlapFraction, 0.4, 0.85},
          {"max distance (fat AABBs)", M::MaxDistance, 0.05, 2}}},
        {{"pyramid-toi", kDefaultEngineCount,
          "The pyramid's continuous collision: the b2Distance calls b2TimeOfImpact makes for each "
          "box touching the 80 m ground edge (dynamic against static) at every step, captured "
          "verbatim by interposing b2Distance. Core shapes (useRadii = false, radius 0) at the "
          "root finder's target distance 0.005: the naive search direction fails on the long "
          "edge here, as the talk predicts."},
         S::Pyramid,
         K::Toi,
         {{"non-unit rotation fraction", M::NonUnitRotationFraction, 0.8, 1},
          {"no radius (useRadii = false)", M::RadiusFraction, 0, 0},
          {"min vertices (the ground edge)", M::MinVertices, 2, 2},
          {"separated fraction", M::SeparatedFraction, 0.99, 1},
          {"min positive distance (TOI target 0.005 - 0.00125)", M::MinPositiveDistance, 0.003,
           0.0063},
          {"near-touching fraction (0 < d <= 1e-2)", M::NearTouchingFraction, 0.03, 0.5}}},
    };
}

// A turning kinematic container of mixed shapes.
std::vector<EngineRow> containerRows()
{
    return {
        {{"container-proximity", kDefaultEngineCount,
          "A kinematic box container (inner half size 5 to 8) turning at 0.15 to 0.5 rad/s, filled "
          "with 3..8-gons, circles and rounded polygons (a b2PolygonShape whose m_radius, 0.05 to "
          "0.25, exceeds the 0.01 skin): per contact, the engine's query with radii. Mixed types, "
          "rounded shapes, the turning walls' fat AABBs (pairs up to several metres apart)."},
         S::Container,
         K::Proximity,
         {{"non-unit rotation fraction", M::NonUnitRotationFraction, 0.8, 1},
          {"rounded fraction (every proxy has a radius)", M::RadiusFraction, 1, 1},
          {"max polygon radius (rounded polygons)", M::MaxPolygonRadius, 0.05, 0.25},
          {"min vertices (circles)", M::MinVertices, 1, 1},
          {"max vertices", M::MaxVertices, 6, 8},
          {"overlapping fraction", M::OverlapFraction, 0.15, 0.5},
          {"max distance (fat AABBs of turning walls)", M::MaxDistance, 1, 20}}},
        {{"container-toi", kDefaultEngineCount,
          "The container's continuous collision: b2TimeOfImpact's own b2Distance calls "
          "(interposed) for every shape near the kinematic walls, core shapes without radius: "
          "circles become points, rounded polygons their cores."},
         S::Container,
         K::Toi,
         {{"non-unit rotation fraction", M::NonUnitRotationFraction, 0.8, 1},
          {"no radius (useRadii = false)", M::RadiusFraction, 0, 0},
          {"min vertices (circle centres)", M::MinVertices, 1, 1},
          {"max vertices", M::MaxVertices, 6, 8},
          {"separated fraction", M::SeparatedFraction, 0.99, 1},
          {"min positive distance (near the TOI targets)", M::MinPositiveDistance, 0.001, 0.02}}},
    };
}

// Bullets fired into stacks of boxes.
std::vector<EngineRow> bulletsRows()
{
    return {
        {{"bullets-proximity", kDefaultEngineCount,
          "Bullets (SetBullet: circles, boxes, rounded boxes of 0.05 to 0.25) fired at 40 to 120 "
          "m/s every 15 to 40 steps into 2 to 4 stacks of 5 to 10 boxes on an 80 m edge: per "
          "contact, the engine's query with radii; fast bodies far from the origin, a scattered "
          "stack."},
         S::Bullets,
         K::Proximity,
         {{"non-unit rotation fraction", M::NonUnitRotationFraction, 0.8, 1},
          {"rounded fraction (every proxy has a radius)", M::RadiusFraction, 1, 1},
          {"max polygon radius (rounded bullets)", M::MaxPolygonRadius, 0.02, 0.1},
          {"min vertices (circles)", M::MinVertices, 1, 1},
          {"overlapping fraction", M::OverlapFraction, 0.1, 0.7},
          {"max |coordinate| (bullets in flight)", M::MaxCoordinate, 30, 1e4}}},
        {{"bullets-toi", kDefaultEngineCount,
          "The bullets' continuous collision: b2TimeOfImpact's own b2Distance calls (interposed) "
          "for bullets against boxes and for boxes against the ground, core shapes without "
          "radius."},
         S::Bullets,
         K::Toi,
         {{"non-unit rotation fraction", M::NonUnitRotationFraction, 0.8, 1},
          {"no radius (useRadii = false)", M::RadiusFraction, 0, 0},
          {"min vertices (circle centres)", M::MinVertices, 1, 1},
          {"separated fraction", M::SeparatedFraction, 0.98, 1},
          {"max |coordinate| (bullets in flight)", M::MaxCoordinate, 30, 1e4}}},
    };
}

} // namespace

std::vector<EngineRow> engineFamilies()
{
    std::vector<EngineRow> rows;
    for (auto scene : {pyramidRows, containerRows, bulletsRows})
        for (auto& row : scene())
            rows.push_back(std::move(row));
    return rows;
}

} // namespace gjkval::families
