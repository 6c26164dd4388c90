// The witness checks' floating-point filter: proves, without GMP, that a witness point lies on its
// shape (its distance to the shape, radius subtracted, is 0), so that the exact route
// (exact::pointToShapeDistance) is asked only for the points the filter cannot decide. Where the
// filter answers, its answer is the exact route's bit for bit: 0. The error analysis is in
// witness_filter.cpp, beside the code; docs/validation.md, "Witness checks", states the contract.
#pragma once

#include <exact/exact.hpp>

#include <vector>

namespace gjkval
{

// A shape as the filter sees it: its points moved to the world frame in double (each coordinate
// within `delta` of the exact side's c*x - s*y + px, s*x + c*y + py), and a hull of those rounded
// points in counter-clockwise order. The hull only chooses which chain and edges to try: a
// certificate uses the shape's own points, so a wrong hull (near-degenerate input) costs a
// fallback, never a wrong answer.
struct FilterShape
{
    std::vector<exact::Point> hull;
    double delta = 0;
    double radius = 0;
    bool usable = false; // every rounded coordinate and delta finite
};

FilterShape filterShape(const exact::Shape& s);

// True when max(0, dist(p, hull(s)) - s.radius) is certainly 0 (p strictly inside a polygon of
// the shape's points, or within the radius of one of its segments), so that
// exact::pointToShapeDistance(s, p) returns 0. False: the filter cannot tell; ask the exact route.
bool certainlyOnShape(const FilterShape& f, exact::Point p);

} // namespace gjkval
