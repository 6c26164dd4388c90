"""A GJK in pure NumPy, after Erin Catto's "Computing Distance" (GDC 2010), validated with
gjk2d.validate against gjk2d's exact ground truth (docs/python.md, "Validating your own GJK from
Python").

    PYTHONPATH=build/release/python /usr/bin/python3 python/examples/numpy_gjk.py --out DIR

runs it on the families random, hard and engine, per pair and then through the batched call, and
prints what the reports say. The GJK is the talk's, kept plain: world coordinates, the
Minkowski difference's support points from each shape's, the simplex solved by barycentric
coordinates, the edge's perpendicular as the search direction, and the talk's termination cases.
"""

import argparse
import sys

import numpy as np

import gjk2d


# --- The GJK: 40 lines ----------------------------------------------------------------------------
def cross(u, v):
    return u[0] * v[1] - u[1] * v[0]


def solve2(w):
    """Segment w[0] w[1]: the origin's barycentric weights (talk, "Point to line segment")."""
    e = w[1] - w[0]
    u, v = w[1] @ e, -(w[0] @ e)  # unnormalised: no divide until the region is known
    if v <= 0:
        return np.array([1.0, 0.0])  # region A
    if u <= 0:
        return np.array([0.0, 1.0])  # region B
    return np.array([u, v]) / (u + v)  # region AB


def solve3(w):
    """Triangle: inside when its three weights are positive, else its nearest edge (the talk's
    vertex and edge regions; a zero area picks an edge and is never divided by)."""
    area = cross(w[1] - w[0], w[2] - w[0])
    uvw = np.array([cross(w[1], w[2]), cross(w[2], w[0]), cross(w[0], w[1])])
    if area != 0 and np.all(uvw * area > 0):
        return uvw / uvw.sum()  # the sum, not the area: the weights must add up to 1
    edges = [np.insert(solve2(w[[i, j]]), k, 0.0) for i, j, k in ((1, 2, 0), (0, 2, 1), (0, 1, 2))]
    return min(edges, key=lambda weights: np.linalg.norm(weights @ w))


def world(points, position, rotation):
    c, s = rotation  # the rotation (c, s) = (cos t, sin t), then the translation
    return np.asarray(points, float) @ np.array([[c, s], [-s, c]]) + np.asarray(position, float)


def gjk(
    points_a,
    points_b,
    radius_a=0.0,
    radius_b=0.0,
    position_a=(0, 0),
    rotation_a=(1, 0),
    position_b=(0, 0),
    rotation_b=(1, 0),
    max_iterations=30,
):
    """gjk2d.distance's arguments; returns (distance, point_a, point_b, iterations)."""
    a, b = world(points_a, position_a, rotation_a), world(points_b, position_b, rotation_b)
    simplex = [(0, 0)]  # vertex pairs (i, j): the simplex vertex w = a[i] - b[j]
    for iteration in range(1, max_iterations + 1):
        w = np.array([a[i] - b[j] for i, j in simplex])
        weights = [lambda w: np.ones(1), solve2, solve3][len(simplex) - 1](w)
        simplex, w, weights = (
            [v for v, k in zip(simplex, weights > 0) if k],
            w[weights > 0],
            weights[weights > 0],
        )  # cull the vertices that do not contribute
        if len(simplex) == 3:
            break  # case 2: containment
        if len(simplex) == 2:  # the edge's perpendicular, turned towards the origin
            n = np.array([w[0][1] - w[1][1], w[1][0] - w[0][0]])
            d = n * np.sign(-(w[0] @ n))
        else:
            d = -w[0]
        if not d.any():
            break  # cases 3a, 3b and 4: the origin on the simplex
        support = (int(np.argmax(a @ d)), int(np.argmax(b @ -d)))
        if support in simplex:
            break  # case 1: a repeated support point
        solved, simplex = simplex, simplex + [support]
    else:
        simplex = solved  # the iteration limit: the last solved simplex
    pa, pb = weights @ a[[i for i, _ in simplex]], weights @ b[[j for _, j in simplex]]
    distance = 0.0 if len(simplex) == 3 else float(np.linalg.norm(pb - pa))
    if distance > radius_a + radius_b:  # onto the rounded surfaces
        n = (pb - pa) / distance
        return distance - radius_a - radius_b, pa + radius_a * n, pb - radius_b * n, iteration
    if radius_a + radius_b > 0:  # rounded shapes that overlap: one point in both
        pa = pb = pa + radius_a / (radius_a + radius_b) * (pb - pa)
    return 0.0, pa, pb, iteration


# --- The batched form: what gjk2d.validate(..., batch=True) calls ---------------------------------
def gjk_batch(
    points, offsets_a, offsets_b, radius_a, radius_b, position_a, rotation_a, position_b, rotation_b
):
    """gjk2d.distance_batch's packing: pair i is points[offsets_a[i]:offsets_a[i + 1]] and
    points[offsets_b[i]:offsets_b[i + 1]]; returns arrays. A loop here: a vectorised GJK (NumPy
    lanes, JAX) takes the same arguments. An exception would count for every pair of the call:
    a pair that raises is answered NaN instead (a non-finite answer, a failure of that pair)."""
    n = len(offsets_a) - 1
    out = {
        "distance": np.full(n, np.nan),
        "point_a": np.full((n, 2), np.nan),
        "point_b": np.full((n, 2), np.nan),
        "iterations": np.zeros(n, np.int64),
    }
    for i in range(n):
        try:
            d, pa, pb, it = gjk(
                points[offsets_a[i] : offsets_a[i + 1]],
                points[offsets_b[i] : offsets_b[i + 1]],
                radius_a[i],
                radius_b[i],
                position_a[i],
                rotation_a[i],
                position_b[i],
                rotation_b[i],
            )
        except Exception:
            continue
        out["distance"][i], out["point_a"][i], out["point_b"][i], out["iterations"][i] = (
            d,
            pa,
            pb,
            it,
        )
    return out


# --- Validation ------------------------------------------------------------------------------------
def summary(report, name):
    """The families where the variant failed, and its worst errors, from the report."""
    lines = []
    rows = [r for r in report.rows() if r["variant"] == name]
    failing = [r for r in rows if r["failures"] > 0]
    cases = sum(r["cases"] for r in rows)
    failures = sum(r["failures"] for r in rows)
    lines.append(
        f"{name}: {failures} failures in {cases} cases ({len(failing)} of {len(rows)} "
        f"families); exit code {report['exit_code']}"
    )
    header = ("family", "failed", "beyond", "f.o+s", "inval.", "nonfin", "raised", "err/bound")
    lines.append("  {:26} {:>9} {:>6} {:>6} {:>6} {:>6} {:>6} {:>9}".format(*header))
    for r in sorted(failing, key=lambda r: (-r["failures"], r["family"])):
        lines.append(
            "  {:26} {:>9} {:>6} {:>6} {:>6} {:>6} {:>6} {:>9.3g}".format(
                r["family"],
                f"{r['failures']}/{r['cases']}",
                r["beyond_bound"],
                r["false_separation"] + r["false_overlap"],
                r["invalid"],
                r["nonfinite"],
                r["plugin_errors"],
                r["bound_ratio_max"] or 0.0,
            )
        )
    timed = [r["ns_per_query"] for r in rows if r["ns_per_query"]]
    double = [
        r["ns_per_query"] for r in report.rows() if r["variant"] == "double" and r["ns_per_query"]
    ]
    if timed and double:
        lines.append(
            f"  time per query: median over families {np.median(timed) / 1e3:.1f} us "
            f"(gjk2d's double: {np.median(double) / 1e3:.2f} us)"
        )
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", required=True, help="directory for the two report directories")
    parser.add_argument("--random", type=int, default=2000, help="cases of random")
    parser.add_argument(
        "--hard",
        type=int,
        default=None,
        help="cases of each hard sub-family (default: their built-in counts)",
    )
    parser.add_argument("--engine", type=int, default=200, help="cases of each engine family")
    parser.add_argument("--passes", type=int, default=None, help="timed passes (run --passes)")
    args = parser.parse_args()
    families = [
        f"random:{args.random}",
        "hard" if args.hard is None else f"hard:{args.hard}",
        f"engine:{args.engine}",
    ]
    common = dict(families=families, passes=args.passes, progress=False)
    np.seterr(over="ignore", invalid="ignore")  # the extreme-scale family overflows: counted
    per_pair = gjk2d.validate(gjk, out=args.out + "/numpy-gjk", name="numpy-gjk", **common)
    print(summary(per_pair, "numpy-gjk"))
    batched = gjk2d.validate(
        gjk_batch, out=args.out + "/numpy-gjk-batch", name="numpy-gjk", batch=True, **common
    )
    print(summary(batched, "numpy-gjk") + "  (batched)")
    same = [(r["family"], r["failures"]) for r in per_pair.rows()] == [
        (r["family"], r["failures"]) for r in batched.rows()
    ]
    print("the batched call's failures are the per-pair call's:", same)
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
