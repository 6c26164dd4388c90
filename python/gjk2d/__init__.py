"""gjk2d: 2D GJK distance, its exact ground truth, cases and validation (docs/python.md)."""

from . import _gjk2d
from ._validate import load_report, validate

__all__ = ["load_report", "validate"]
