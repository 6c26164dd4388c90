// Engine query families: the distance queries a real physics engine (Box2D 2.4.1, Debian's
// libbox2d) makes while its worlds step, recorded with the engine's floats verbatim. No Box2D type
// appears here: families.cpp wires these generators into the `engine/<scene>-<kind>` families.
//
// Two kinds of query per scene:
// - proximity: after each step, for every contact of the world's contact list, the query an engine
//   would make on that pair: b2DistanceProxy::Set from each fixture's shape and child index, the
//   two bodies' b2Transform, useRadii = true (the case's radius is the proxy's m_radius);
// - toi: the b2Distance calls Box2D itself makes inside b2TimeOfImpact while the world steps,
//   captured by interposing b2Distance (engine.cpp): the executable defines and exports
//   `b2Distance`, libbox2d.so calls it through its PLT, the definition records the input and
//   forwards to the library's (dlsym(RTLD_NEXT)). b2TimeOfImpact asks with useRadii = false, so
//   these cases have radius 0.
// Points are the proxy's m_vertices and the transforms' p and (c, s) = (q.c, q.s) exactly as the
// engine holds them (floats converted to double exactly): a float rotation is not a unit vector in
// double (|c^2 + s^2 - 1| up to ~1e-7).
#pragma once

#include "inputs/cases.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace gjkval
{

enum class EngineScene
{
    Pyramid,   // a resting pyramid of boxes on a long static edge (the Box2D testbed's)
    Container, // a rotating (kinematic) container of polygons, circles and rounded polygons
    Bullets,   // bullets (SetBullet) shot into a stack of boxes: continuous collision
};
inline constexpr const char* kEngineSceneNames[] = {"pyramid", "container", "bullets"};

enum class EngineQueryKind
{
    Proximity, // per contact after each step, useRadii = true
    Toi,       // b2TimeOfImpact's own b2Distance calls (interposed), useRadii = false
};
inline constexpr const char* kEngineQueryKindNames[] = {"proximity", "toi"};

struct EngineQuery
{
    Case c;          // c.name is left empty (the family names its cases)
    std::string tag; // "step42-polygon-circle": the step (from 1) and the two proxies' types
    int step = 0;
    bool useRadii = false; // as the engine asked: the radii are the proxies' m_radius, else 0
};

// Builds the scene from `seed` (sizes, positions, counts, speeds), steps it at 60 Hz and returns
// `count` queries of the kind, sampled uniformly from the run (reservoir sampling seeded from
// `seed`) and in the order the engine made them: it runs at least kEngineMinSteps steps and until
// at least `count` queries were made. Same seed and count, same queries. Throws std::logic_error
// when the capture is broken (the interposition is not in effect, a scene makes no queries, or it
// stops making them before kEngineMaxStepsPerQuery * count more steps): a bug of the build or of
// this code, never bad input.
std::vector<EngineQuery> engineQueries(EngineScene scene, EngineQueryKind kind, std::uint64_t seed,
                                       int count);

inline constexpr int kEngineMinSteps = 600; // 10 s of simulated time
inline constexpr int kEngineMaxStepsPerQuery = 10;

// Throws std::logic_error unless libbox2d.so's own calls of b2Distance reach the interposer:
// calls b2TestOverlap (which calls b2Distance through libbox2d's PLT) and checks that the call was
// seen. engineQueries(…, Toi, …) runs it first; tests call it directly.
void checkB2DistanceInterposed();

// Calls of the interposed b2Distance on this thread since the program started (all callers,
// recording or not): for tests.
std::uint64_t interposedB2DistanceCalls();

} // namespace gjkval
