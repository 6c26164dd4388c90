// What an implementation under test promises (gjk2d/plugin.h, gjk2d_contract; the adapter
// protocol's `contract` lines; docs/peers.md, "What each peer promises (its contract)"): one plain
// struct, every clause with where the library says so. The judge (evaluate/) holds each answer to
// it; gjk2d's own variants, and version-1 plugins, have gjk2d's own contract (ownContract()).
//
// One meaning of "contract" in the runner: what an implementation promises about its answers.
// (plugin.h's rules for a call, the status codes and the result's fields, are "the ABI".)
#pragma once

#include "common/common.hpp"
#include "implementations/variants.hpp"

#include <string>

namespace gjkval
{

// What an implementation answers on overlapping shapes (gjk2d_overlap, the same order).
enum class Overlap
{
    CommonPoint, // distance 0, both points at one point of both shapes (gjk2d)
    Zero,        // a distance of 0 or below; no points promised: only the sign is judged
    Midpoint,    // distance 0, both points at the midpoint between the shapes' cores
    Penetration, // minus the depth, and a penetration pair (each point on its shape)
    // Distance 0; cores apart: each point on its own shape, ||pA - pB|| = rA + rB - core distance
    // (the rounded shapes' exact depth); cores meeting: one common point.
    Perimeter,
};
inline constexpr int kOverlapKinds = 5;
// "common-point", "zero", "midpoint", "penetration", "perimeter": the report's and the protocol's
// words.
const char* overlapName(Overlap o);
// The kind a word names; false for none.
bool parseOverlap(const std::string& word, Overlap& out);

// What an implementation is given of each case: the case as it is (its points and transforms),
// or its world case (inputs/geometry.hpp, worldCase: world points in the implementation's scalar
// type, identity transforms), for a library that cannot take the case's transform exactly (an
// adapter's `input NAME world` line; not in the C plugin ABI). Its truth, bounds and every
// judgement are then on the world case (evaluate/evaluate.hpp, CaseOutcome::world).
enum class InputForm
{
    Case,
    World,
};
const char* inputFormName(InputForm f); // "case", "world": the report's and the protocol's words

struct Contract
{
    // gjk2d's own contract: every failure of gjk2d's judge (evaluate/evaluate.hpp, failedAnswer)
    // breaks it; the rest of the struct is its description (common-point, gjk2d's bound).
    bool own = true;
    // On separated shapes: |distance - exact| <= abs + rel * exact, plus gjk2d's bound for the
    // scalar type (the rounding a stopping rule does not cover: evaluate/contract_judge.cpp,
    // setTolerances). Negative: not stated; both not stated: gjk2d's bound alone stands in, and
    // the report says so.
    double absTolerance = -1, relTolerance = -1;
    std::string toleranceSource; // "" none stated
    Overlap overlap = Overlap::CommonPoint;
    std::string overlapSource;
    double margin = 0; // the skin the library keeps around each shape, as the adapter sets it
    std::string marginSource;
    // On overlapping shapes, for overlap == Penetration: |depth - exact depth| <= depthAbs +
    // depthRel * exact depth (gjk2d_plugin_depth; the protocol's `contract NAME depth` line).
    // Negative: not stated: gjk2d's depth bound for the scalar type stands in.
    double depthAbsTolerance = -1, depthRelTolerance = -1;
    std::string depthSource; // "" none stated
    InputForm input = InputForm::Case;
    std::string inputSource; // why the library cannot take the case as given ("" for Case)

    bool statesTolerance() const { return absTolerance >= 0 || relTolerance >= 0; }
    bool statesDepthTolerance() const { return depthAbsTolerance >= 0 || depthRelTolerance >= 0; }
    bool operator==(const Contract&) const = default;
};

// gjk2d's own: what its variants, version-1 plugins and version-1 adapters are held to. With
// Options::signedDistance its overlap answer is Penetration (minus the depth, a penetration pair),
// the depth held to gjk2d's depth bound (evaluate/bounds.hpp, depthBound): no depth clause stated.
Contract ownContract(const gjk::Options& options = {});
// A plugin's declared contract (version 2), checked: InputError-worthy problems are returned as
// one line ("" when it is sound): an unknown overlap kind, a non-finite or negative margin, a
// NaN tolerance, a non-finite depth tolerance, or a depth tolerance on a contract whose overlap is
// not `penetration` (only a penetration answers a depth).
std::string checkContract(const Contract& c);
// The contract a variant is held to: its plugin's, or gjk2d's own.
const Contract& contractOf(const VariantInfo& v);
// report.json's variants[].contract: {"own", "overlap", "overlap_source", "tolerance": {"abs",
// "rel", "source"} (null members: not stated), "margin", "margin_source", "depth": {"abs", "rel",
// "source"} (null members: not stated), "input": {"form": "case"|"world", "source"}, "judged_by",
// "judged_by_depth"} where judged_by says in words what the distance is held to ("FCL's stated
// tolerance ..." or "gjk2d's bound for double: no tolerance stated") and judged_by_depth what the
// depth is held to (judgedByDepth).
Json contractJson(const VariantInfo& v);
// In words, what the variant's distance is held to: "its stated tolerance: abs 1e-06, rel none
// (SOURCE), plus gjk2d's bound for double", "no tolerance stated: gjk2d's bound for double",
// "gjk2d's own contract: ...".
std::string judgedBy(const VariantInfo& v);
// In words, what the variant's penetration depth is held to: "its stated tolerance: abs 0.0001, rel
// none (SOURCE), plus gjk2d's depth bound for double", "no depth tolerance stated: gjk2d's depth
// bound for double", "gjk2d's own contract: gjk2d's depth bound for double" (double-signed), or,
// for an overlap kind that answers no depth, "no depth answered (overlap zero)" (gjk2d's double:
// "... (overlap common-point)").
std::string judgedByDepth(const VariantInfo& v);
// In words, what the variant is given of each case: "the case as given", or "world points rounded
// to float (SOURCE)" ("world points in double (SOURCE)" for a double implementation).
std::string givenInput(const VariantInfo& v);

} // namespace gjkval
