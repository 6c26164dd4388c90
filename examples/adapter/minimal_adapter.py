#!/usr/bin/python3
# [snippet: python-adapter]
# A minimal executable adapter (protocol 1, docs/validate-your-gjk.md): the distance between two
# shapes by brute force over vertex-edge pairs: right for shapes apart, wrong when they overlap.
import sys, time


def shape(t, i):  # t[i] is 'A' or 'B': r px py c s n x0 y0 ...; world = R local + p
    px, py, c, s, n = (
        float(t[i + 2]),
        float(t[i + 3]),
        float(t[i + 4]),
        float(t[i + 5]),
        int(t[i + 6]),
    )
    v = [float(x) for x in t[i + 7 : i + 7 + 2 * n]]
    return [
        (c * v[2 * k] - s * v[2 * k + 1] + px, s * v[2 * k] + c * v[2 * k + 1] + py)
        for k in range(n)
    ], i + 7 + 2 * n


def near(p, a, b):  # the point of segment ab closest to p
    dx, dy = b[0] - a[0], b[1] - a[1]
    dd = dx * dx + dy * dy
    u = 0.0 if dd == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / dd))
    return (a[0] + u * dx, a[1] + u * dy)


def distance(a, b):  # (d, point on A, point on B)
    pairs = [(p, near(p, q, b[(k + 1) % len(b)])) for p in a for k, q in enumerate(b)]
    pairs += [(near(q, p, a[(k + 1) % len(a)]), q) for q in b for k, p in enumerate(a)]
    return min((((p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2) ** 0.5, p, q) for p, q in pairs)


def cases(t, i, m):
    for _ in range(m):
        a, i = shape(t, i)
        b, i = shape(t, i)
        yield a, b


def answer(t):
    if t[0] == "distance":
        d, p, q = distance(*next(cases(t, 3, 1)))
        return f"ok {t[1]} {d!r} {p[0]!r} {p[1]!r} {q[0]!r} {q[1]!r} -1"
    k, todo = int(t[3]), list(cases(t, 5, int(t[4])))  # time <id> <impl> <K> <m> ...
    t0 = time.monotonic_ns()
    for _ in range(k):
        for a, b in todo:
            distance(a, b)
    return f"timed {t[1]} {time.monotonic_ns() - t0}"


sys.stdin.readline()  # "gjk2d-adapter 1"
print("gjk2d-adapter 1\nlibrary minimal Python adapter 1.0", flush=True)
print("implementation minimal-py double no-radius 0 vertex-edge brute force\nready", flush=True)
for line in sys.stdin:
    if line.split():
        print(answer(line.split()), flush=True)
# [end snippet]
