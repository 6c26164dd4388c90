// The realistic mix: the family `random`.
#include "inputs/families/construct.hpp"
#include "inputs/families/rows.hpp"

namespace gjkval::families
{
namespace
{

void genRandom(Rng& r, int, Case& c, std::string&)
{
    // 10% near contact (gap 1e-9 .. 1e-2), 10% shallow penetration, 20% deep overlap, 60%
    // independent positions.
    const double u = r.uniform();
    randomPair(r, c, u < 0.1 ? 0 : (u < 0.2 ? 1 : (u < 0.4 ? 2 : 3)));
}

} // namespace

FamilyRow randomFamily()
{
    return {
        {"random", kDefaultRandomCount,
         "Realistic mix: 3 to 8 vertices on circles of radius 0.5 to 2 at random angles, random "
         "positions "
         "in [-4, 4]^2 and rotations; 10% placed at a gap of 1e-9..1e-2, 10% at a penetration of "
         "that "
         "size, 20% within [-1, 1]^2 of each other (deep overlap), the rest independent."},
        genRandom,
        {
            {"overlapping fraction", M::OverlapFraction, 0.2, 0.8},
            {"near-touching fraction (0 < d <= 1e-2)", M::NearTouchingFraction, 0.05, 1},
            {"min vertices", M::MinVertices, 3, 8, MakeupScope::EveryCase},
            {"max vertices", M::MaxVertices, 3, 8, MakeupScope::EveryCase},
            {"max |coordinate|", M::MaxCoordinate, 0, 16, MakeupScope::EveryCase},
        }};
}

} // namespace gjkval::families
