"""gjk2d: 2D GJK distance, its exact ground truth, cases and validation (docs/python.md)."""

from ._gjk2d import (
    STOP_REASONS,
    DistanceResult,
    InputError,
    SimplexCache,
    distance,
    distance_batch,
    exact_distance,
    families,
    generate,
    read_cases,
    write_cases,
)
from ._validate import Report, load_report, validate


def case_args(case):
    """The keyword arguments of distance and exact_distance for a case dict (generate,
    read_cases): gjk2d.distance(**gjk2d.case_args(case))."""
    args = {}
    for side in ("a", "b"):
        shape = case[side]
        args["points_" + side] = shape["points"]
        args["radius_" + side] = shape.get("radius", 0.0)
        args["position_" + side] = shape.get("position", (0.0, 0.0))
        args["rotation_" + side] = shape.get("rotation", (1.0, 0.0))
    return args


__all__ = [
    "STOP_REASONS",
    "DistanceResult",
    "InputError",
    "Report",
    "SimplexCache",
    "case_args",
    "distance",
    "distance_batch",
    "exact_distance",
    "families",
    "generate",
    "load_report",
    "read_cases",
    "validate",
    "write_cases",
]
