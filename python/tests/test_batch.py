"""gjk2d.distance_batch: ragged shapes packed with offsets, the same bits as one gjk2d.distance per
pair (gjk2d/batch.hpp promises the single query's bits), float32 and float64, and its bad input."""

import numpy as np
import pytest

import gjk2d


def packed(rng, pairs):
    """Random convex-ish point clouds of 1 to 20 points, A shapes then B shapes in one array."""
    shapes = [rng.normal(size=(rng.integers(1, 21), 2)) for _ in range(2 * pairs)]
    offsets = np.concatenate([[0], np.cumsum([len(s) for s in shapes])])
    return np.vstack(shapes), offsets[: pairs + 1], offsets[pairs:]


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_each_pair_as_its_own_query(dtype):
    rng = np.random.default_rng(11)
    pairs = 300
    points, oa, ob = packed(rng, pairs)
    points = points.astype(dtype)
    position_b = rng.normal(scale=3, size=(pairs, 2))
    angle = rng.uniform(0, 6.3, pairs)
    rotation_b = np.stack([np.cos(angle), np.sin(angle)], axis=1)
    radius_a = rng.uniform(0, 0.3, pairs)
    out = gjk2d.distance_batch(
        points,
        oa,
        ob,
        radius_a=radius_a,
        position_b=position_b,
        rotation_b=rotation_b,
        certify=True,
    )
    assert out["distance"].dtype == dtype and out["point_a"].shape == (pairs, 2)
    for i in range(pairs):
        one = gjk2d.distance(
            points[oa[i] : oa[i + 1]],
            points[ob[i] : ob[i + 1]],
            radius_a=radius_a[i],
            position_b=position_b[i],
            rotation_b=rotation_b[i],
            certify=True,
        )
        assert out["distance"][i].tobytes() == dtype(one.distance).tobytes(), i
        assert np.array_equal(out["point_b"][i], np.array(one.point_b, dtype)), i
        assert np.array_equal(out["normal"][i], np.array(one.normal, dtype)), i
        assert out["iterations"][i] == one.iterations
        assert gjk2d.STOP_REASONS[out["stop"][i]] == one.stop
        assert (out["lower"][i], out["upper"][i]) == one.interval
    assert np.any(out["distance"] > 0) and np.any(out["distance"] == 0)


def test_bad_offsets_and_per_pair_values_raise_naming_the_argument():
    points = np.zeros((6, 2))
    with pytest.raises(ValueError, match="^offsets_a: "):
        gjk2d.distance_batch(points, [0, 3, 3], [3, 4, 6])  # an empty shape
    with pytest.raises(ValueError, match="^offsets_b: "):
        gjk2d.distance_batch(points, [0, 1, 2], [3, 4, 7])  # beyond the points
    with pytest.raises(ValueError, match="^offsets_b: "):
        gjk2d.distance_batch(points, [0, 1, 2], [3, 4])
    with pytest.raises(ValueError, match="^radius_b: "):
        gjk2d.distance_batch(points, [0, 1, 2], [3, 4, 6], radius_b=[0.1, 0.2, 0.3])
    with pytest.raises(ValueError, match="^points: "):
        gjk2d.distance_batch(np.full((6, 2), np.inf), [0, 1, 2], [3, 4, 6])
