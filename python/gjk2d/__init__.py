"""gjk2d: 2D GJK distance, its exact ground truth, cases and validation (docs/python.md)."""

import os as _os

from . import _gjk2d
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

# The runner finds the default campaign's case files beside its program, which is Python here:
# the package's own cases/ (the wheel's copy, or the build tree's link) is given instead.
_CASES = _os.path.join(_os.path.dirname(_os.path.abspath(__file__)), "cases")
if _os.path.isdir(_CASES):
    _gjk2d._set_case_dir(_CASES)


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
