// Why an answer breaks its implementation's contract (implementations/contract.hpp): the reasons,
// their report names, and their count. One home: evaluate/contract_judge.cpp decides them,
// statistics/ counts them, report.json names them (docs/report-schema.md, "contract_violations").
#pragma once

namespace gjkval
{

// One reason per answer (the first that applies, in evaluate/contract_judge.cpp's order).
enum class Violation
{
    None,
    Error,            // the implementation answered GJK2D_STATUS_ERROR
    Crashed,          // it crashed
    Hung,             // it did not answer within the timeout
    Nonfinite,        // a non-finite distance, or a non-finite point where points are judged
    NegativeDistance, // a negative distance where the contract promises none (common-point,
                      // midpoint)
    WitnessOffShape,  // a witness point further than W from its shape
    WitnessGap,       // | ||pB - pA|| - d | (midpoint: ||pB - pA||) beyond W
    FalseOverlap,     // a claim of overlap on shapes further apart than the tolerance T
    FalseSeparation,  // a distance beyond T on overlapping shapes
    Distance,         // |d - exact| beyond T on separated shapes (gjk2d's own: beyond its bound)
    MidpointOff,      // a midpoint point further than dc/2 + W from one of the two cores
    PenetrationGap,   // | ||pA - pB|| - |d| | beyond W for a penetration pair
    PerimeterOff,     // a perimeter pair off its perimeters, or not rA + rB - dc apart
    IterationLimit,   // gjk2d's own: the iteration limit was reached
    Interval,         // gjk2d's own: the certified interval misses the exact distance
    BitMismatch,      // gjk2d's own: a correctly rounded distance that is not the exact side's
    // Penetration on overlapping shapes (exact signed distance < 0). Added after the others (the
    // state of shards and checkpoints numbers the reasons; an older state has fewer, which count
    // 0).
    DepthOff, // |d - exact signed distance| beyond a stated depth tolerance (gjk2d's own: beyond
              // its depth bound)
    NoDepth,  // a distance of 0 or more on shapes overlapping deeper than the depth tolerance,
              // where the contract promises minus the depth
};
inline constexpr int kViolationReasons = int(Violation::NoDepth); // the reasons after None

// The report's name of a reason (report.json contract_violations.reasons, cases.jsonl); null for
// None.
inline const char* violationName(Violation r)
{
    constexpr const char* names[kViolationReasons + 1] = {nullptr,
                                                          "error",
                                                          "crashed",
                                                          "hung",
                                                          "nonfinite",
                                                          "negative_distance",
                                                          "witness_off_shape",
                                                          "witness_gap",
                                                          "false_overlap",
                                                          "false_separation",
                                                          "distance",
                                                          "midpoint_off",
                                                          "penetration_gap",
                                                          "perimeter_off",
                                                          "iteration_limit",
                                                          "interval",
                                                          "bit_mismatch",
                                                          "depth_off",
                                                          "no_depth"};
    return names[int(r)];
}

} // namespace gjkval
