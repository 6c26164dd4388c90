"""gjk2d.exact_distance is the C++ exact side: the same distance, exact squared distance and
witnesses as gjk-validate's truth (`exact`, and `exact_float_input` for float-rounded inputs) on
the default campaign's families (conftest.py); and a case by hand."""

from fractions import Fraction

import numpy as np
import pytest

import gjk2d


def as_fraction(text):
    num, _, den = text.partition("/")
    return Fraction(int(num), int(den or 1))


def test_two_unit_squares_three_apart():
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]])
    r = gjk2d.exact_distance(square, square, position_b=(4, 0))
    assert r["distance"] == 3.0 and r["squared"] == Fraction(9)
    assert not r["overlap"]
    assert r["interval"] == (3.0, 3.0)
    # The closest features are the parallel edges x = 1 and x = 4: the exact side's witnesses lie
    # on them, at one common height in [0, 1].
    (ax, ay), (bx, by) = r["exact_point_a"], r["exact_point_b"]
    assert (ax, bx) == (1, 4) and ay == by and 0 <= ay <= 1
    assert isinstance(ay, Fraction)


def test_two_unit_squares_one_apart_and_radii():
    # Squares of half-width 1 with centres 3 apart: edges x = 1 and x = 2, 1 apart.
    square = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]])
    r = gjk2d.exact_distance(square, square, position_b=(3, 0))
    assert r["distance"] == 1.0 and r["squared"] == Fraction(1)
    # Radii: 1 - 0.25 - 0.5, exact in binary; the squared distance stays the hulls'.
    r = gjk2d.exact_distance(square, square, position_b=(3, 0), radius_a=0.25, radius_b=0.5)
    assert r["distance"] == 0.25 and r["squared"] == Fraction(1)
    # Overlap: squared distance 0.
    r = gjk2d.exact_distance(square, square, position_b=(1.5, 1.5))
    assert r["overlap"] and r["squared"] == 0 and r["distance"] == 0


def test_same_as_gjk_validates_truth_on_the_default_campaign(campaign):
    cases, answers = campaign
    compared = 0
    for name, case in cases.items():
        want = answers[name]["exact"]
        got = gjk2d.exact_distance(**gjk2d.case_args(case))
        assert got["distance"] == want["distance"], name
        assert got["squared"] == as_fraction(want["squared"]), name
        assert got["overlap"] == want["overlap"], name
        assert list(got["point_a"]) == want["witnessA"] and list(got["point_b"]) == want["witnessB"]
        assert got["interval"] == (want["lower"], want["upper"]), name
        compared += 1
    assert compared > 7500


def test_bad_input_raises_a_value_error_naming_the_argument():
    with pytest.raises(ValueError, match="^points_b: "):
        gjk2d.exact_distance([[0.0, 0.0]], np.zeros((0, 2)))
    with pytest.raises(ValueError, match="^radius_a: "):
        gjk2d.exact_distance([[0.0, 0.0]], [[1.0, 1.0]], radius_a=-0.5)
