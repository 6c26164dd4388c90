// The family table's rows. Each group of families has its own file here, each family's row beside
// its generator; inputs/families.cpp gathers the groups, in the order declared below (the order of
// reports and of `gjk-validate list`). A new family is one generator and one row in its group's
// file, listed in that group's function; a new group is one more file and one line in
// inputs/families.cpp. Internal to inputs/: the interface is inputs/families.hpp.
#pragma once

#include "inputs/engine.hpp"
#include "inputs/families.hpp"
#include "inputs/rng.hpp"

#include <functional>
#include <string>
#include <vector>

namespace gjkval::families
{

using M = MakeupMetric;

// Case i of a family: fills c and its tag (the case name's suffix; may stay empty) from r, the
// case's own stream (r.family: the family's seed, for sharedRng).
using Gen = std::function<void(Rng& r, int i, Case& c, std::string& tag)>;

// A generated family: name (without "hard/"), built-in count and reason; generator; make-up.
struct FamilyRow
{
    HardSubFamilyInfo info;
    Gen gen;
    std::vector<MakeupSpec> makeup;
};

// An engine family: name (without "engine/"), default count and reason; the Box2D world and the
// kind of query recorded from it (inputs/engine.hpp); make-up.
struct EngineRow
{
    HardSubFamilyInfo info;
    EngineScene scene;
    EngineQueryKind kind;
    std::vector<MakeupSpec> makeup;
};

// The realistic mix (random.cpp).
FamilyRow randomFamily();

// The hard sub-families, group by group, in table order.
std::vector<FamilyRow> numericalFamilies();    // numerical.cpp: the talk's example, near-parallel
                                               // edges, far from the origin, slivers
std::vector<FamilyRow> contactFamilies();      // contact.cpp: exact contact, one-ulp gaps
std::vector<FamilyRow> degenerateFamilies();   // degenerate.cpp: implicit hulls, segments,
                                               // identical and nested shapes
std::vector<FamilyRow> shapeFamilies();        // shapes.cpp: tiny and huge sizes, many
                                               // vertices, rotations, rounded shapes, points
std::vector<FamilyRow> sweepFamilies();        // sweeps.cpp: scale and offset sweeps, short
                                               // edges, tied supports, near-zero separation
std::vector<FamilyRow> scaleFamilies();        // scale.cpp: mixed and extreme scales, the
                                               // types' ranges
std::vector<FamilyRow> startAndPoseFamilies(); // starts_and_poses.cpp: cold starts, a float
                                               // engine's poses

// The engine families, scene by scene (engine_scenes.cpp).
std::vector<EngineRow> engineFamilies();

} // namespace gjkval::families
