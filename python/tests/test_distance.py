"""gjk2d.distance answers as gjk-validate's `double` and `float` variants do, bit for bit, on every
family of the default campaign and its case files (conftest.py); and its own contract on hand
cases: fields, certify, correctly rounded, warm cache, dtype, bad arrays."""

import math
import struct

import numpy as np
import pytest

import gjk2d

# A report writes a non-finite number as a string (docs/report-schema.md).
NON_FINITE = {"nan": math.nan, "inf": math.inf, "-inf": -math.inf}


def bits(v):
    return struct.pack("<d", NON_FINITE.get(v, v) if isinstance(v, str) else v)


def float_args(case):
    """The case as the float variant receives it: every number rounded to float32."""
    args = gjk2d.case_args(case)
    with np.errstate(over="ignore"):  # a number beyond float's range: the case is left out
        for side in ("a", "b"):
            args["points_" + side] = np.asarray(args["points_" + side], np.float32)
            for key in ("radius_", "position_", "rotation_"):
                args[key + side] = np.float32(args[key + side]).astype(np.float64)
    return args


def representable_in_float(args):
    return all(np.all(np.isfinite(np.asarray(v, np.float32))) for v in args.values()) and all(
        np.any(np.asarray(args["rotation_" + s]) != 0) for s in "ab"
    )


@pytest.mark.parametrize("variant", ["double", "float"])
def test_same_bits_as_gjk_validate_on_the_default_campaign(campaign, variant):
    cases, answers = campaign
    compared = 0
    for name, case in cases.items():
        want = answers[name]["variants"][variant]
        args = gjk2d.case_args(case) if variant == "double" else float_args(case)
        if variant == "float" and not representable_in_float(args):
            continue  # the float variant does not run it (invalid input in float)
        got = gjk2d.distance(**args)
        assert bits(got.distance) == bits(want["distance"]), name
        for field, key in (("point_a", "pointA"), ("point_b", "pointB"), ("normal", "normal")):
            assert [bits(x) for x in getattr(got, field)] == [bits(x) for x in want[key]], (
                name,
                field,
            )
        assert (got.iterations, got.stop) == (want["iterations"], want["stop"]), name
        compared += 1
    assert compared > 7500


def test_two_unit_squares_three_apart():
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], np.float64)
    for dtype in (np.float64, np.float32):
        r = gjk2d.distance(square.astype(dtype), square.astype(dtype), position_b=(4, 0))
        assert r.distance == 3.0
        assert r.point_a[0] == 1.0 and r.point_b[0] == 4.0 and r.point_a[1] == r.point_b[1]
        assert r.normal == (1.0, 0.0)
        assert r.stop in gjk2d.STOP_REASONS
        assert r.interval is None


def test_radii_rotation_certify_and_correct_rounding():
    segment = np.array([[-1.0, 0.0], [1.0, 0.0]])
    # B: the segment turned by 90 degrees (c, s) = (0, 1), at (0, 5), radius 0.5; A radius 1.
    # Hand: B's lowest point is (0, 4), A's highest (0, 0): 4 - 1 - 0.5 = 2.5.
    r = gjk2d.distance(
        segment,
        segment,
        radius_a=1.0,
        radius_b=0.5,
        position_b=(0, 5),
        rotation_b=(0, 1),
        certify=True,
        correctly_rounded=True,
    )
    assert r.distance == 2.5
    assert r.point_a == (0.0, 1.0) and r.point_b == (0.0, 3.5)
    lower, upper = r.interval
    assert lower <= 2.5 <= upper
    assert r.path != "plain"


def test_signed_distance_on_overlap_separation_and_touching():
    square = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    # B = the unit square moved by (0.75, 0.5): they overlap by 0.25 along x and 0.5 along y, so
    # the depth is 0.25 and B leaves A along +x: pA on A's side x = 1, pB on B's side x = 0.75.
    r = gjk2d.distance(square, square, position_b=(0.75, 0.5), signed=True)
    assert r.distance == pytest.approx(-0.25, abs=1e-15)
    assert r.normal == pytest.approx((1.0, 0.0), abs=1e-15)
    assert r.point_a[0] == pytest.approx(1.0, abs=1e-15)
    assert r.point_b[0] == pytest.approx(0.75, abs=1e-15)
    assert r.point_a[1] == pytest.approx(r.point_b[1], abs=1e-15)
    assert r.expand in ("gap-closed", "repeated-support")
    lower, upper = r.interval
    assert lower <= -0.25 <= upper
    # Without signed: the overlap is distance 0, no expansion.
    plain = gjk2d.distance(square, square, position_b=(0.75, 0.5))
    assert plain.distance == 0.0 and plain.expand == "none" and plain.interval is None
    # Capsules: parallel cores 0.75 apart, radii 0.5 each: 0.75 - 1 = -0.25, B leaves along +y,
    # pA on A's rounded surface y = 0.5, pB on B's y = 0.75 - 0.5 = 0.25.
    segment = np.array([[-1.0, 0.0], [1.0, 0.0]])
    c = gjk2d.distance(
        segment,
        segment,
        radius_a=0.5,
        radius_b=0.5,
        position_b=(0.5, 0.75),
        signed=True,
        dtype="float32",
    )
    assert c.distance == pytest.approx(-0.25, abs=1e-6)
    assert c.normal == pytest.approx((0.0, 1.0), abs=1e-6)
    assert c.point_a[1] == pytest.approx(0.5, abs=1e-6)
    assert c.point_b[1] == pytest.approx(0.25, abs=1e-6)
    assert c.expand == "none"
    # Touching edge to edge (B = the square moved by exactly 1): depth 0.
    t = gjk2d.distance(square, square, position_b=(1.0, 0.0), signed=True)
    assert t.distance == 0.0 and t.expand == "touching"
    # Separated: the very bits of the unsigned query.
    s = gjk2d.distance(square, square, position_b=(3.0, 0.5), signed=True)
    u = gjk2d.distance(square, square, position_b=(3.0, 0.5))
    assert bits(s.distance) == bits(u.distance) == bits(2.0)
    assert s.point_a == u.point_a and s.point_b == u.point_b and s.expand == "none"


def test_a_warm_query_gives_the_cold_bits_in_fewer_iterations():
    rng = np.random.default_rng(5)
    a, b = rng.normal(size=(12, 2)), rng.normal(size=(9, 2)) + [6, 1]
    cold = gjk2d.distance(a, b)
    warm = gjk2d.distance(a, b, cache=cold.cache)
    assert cold.cache.count >= 1
    assert bits(warm.distance) == bits(cold.distance)
    assert warm.iterations < cold.iterations


def test_a_cache_of_other_shapes_is_refused():
    big = gjk2d.distance(np.array([[0.0, 0], [1, 0], [1, 1], [0, 1]]), [[5.0, 5.0]])
    assert max(big.cache.index_a) > 0
    with pytest.raises(ValueError, match="^cache: "):
        gjk2d.distance([[0.0, 0.0]], [[5.0, 5.0]], cache=big.cache)


def test_dtype_chooses_the_scalar_type():
    a = np.array([[0.1, 0.2], [0.3, -0.7]])
    b = np.array([[1.1, 0.9]])
    as_float = gjk2d.distance(a, b, dtype="float32")
    assert as_float.distance == gjk2d.distance(a.astype(np.float32), b.astype(np.float32)).distance
    assert as_float.distance == float(np.float32(as_float.distance))
    assert gjk2d.distance(a, b).distance != as_float.distance


@pytest.mark.parametrize(
    "kwargs, argument",
    [
        (dict(points_a=np.zeros((0, 2))), "points_a"),
        (dict(points_a=np.zeros((3, 3))), "points_a"),
        (dict(points_b=np.zeros(4)), "points_b"),
        (dict(points_b=[[0.0, math.nan]]), "points_b"),
        (dict(points_a=[[1e39, 0.0]], dtype="float32"), "points_a"),
        (dict(points_a=np.zeros((1_000_001, 2))), "points_a"),
        (dict(radius_a=-1.0), "radius_a"),
        (dict(radius_b=math.inf), "radius_b"),
        (dict(rotation_a=(0, 0)), "rotation_a"),
        (dict(position_b=(1, 2, 3)), "position_b"),
        (dict(dtype="int32"), "dtype"),
        (dict(dtype="float32", correctly_rounded=True), "correctly_rounded"),
        (dict(signed=True, correctly_rounded=True), "signed"),
    ],
)
def test_bad_input_raises_a_value_error_naming_the_argument(kwargs, argument):
    args = dict(points_a=[[0.0, 0.0]], points_b=[[1.0, 0.0]])
    args.update(kwargs)
    with pytest.raises(ValueError, match="^" + argument + ": "), np.errstate(over="ignore"):
        gjk2d.distance(**args)
