#!/usr/bin/env python3
"""An adapter given world points (`input NAME world SOURCE`; tests/plugins/CMakeLists.txt).

  world_check.py --exe E --adapter A --cases C --work W

A is adapters/world.py: a float implementation, toy-world, that declares `input toy-world world
...` and appends every request it reads to $TOY_STATE_DIR/requests. C is adapters/world_cases.json:
  world/rotated   A the point (0, 0); B the point (0.1, 0.3) under the rotation (0.6, 0.8) and the
                  translation (2, 1). (0.6, 0.8) is no unit rotation in binary, so the world point
                  computed in double, x' = (c*x - s*y) + px, y' = (s*x + c*y) + py, and rounded to
                  float, (1.8200000524520874, 1.2599999904632568), is not the exact image of the
                  case's point: the world case's exact distance, 2.213594399815153, is not the
                  case's, 2.2135943621178655 (both derived below, here in Python: its floats are
                  IEEE doubles without FMA, struct rounds to float, Fraction and a 100-digit
                  Decimal square root give the exact values).
  world/overflow  B the point (3e38, 0) moved by (1e38, 0): every number of the case fits in float,
                  its world point 4e38 does not: toy-world skips it, with the reason.
The checks: the one `distance` request of toy-world carries identity transforms and the world
points rounded to float, bit for bit, and no request carries the overflowing case; cases.jsonl
judges toy-world on the world case's truth (its key, the exact distance above, the input change
|world - case|) and says why it skipped the other; report.json's variants[] gives the contract's
input clause and variants[].input with the count; a timed run's `time` requests carry the same
world points; `explain` (text and --json) shows the world case and says toy-world is judged on
it; report.md's contracts say what toy-world is given. Exit 0 when every check holds; else a
message and exit 1.
"""
import argparse
import json
import os
import shutil
import struct
import subprocess
import sys
from decimal import Decimal, getcontext
from fractions import Fraction

getcontext().prec = 100  # the square roots below: far more digits than a double's 17


def fail(msg):
    print("world_check: FAIL: " + msg, file=sys.stderr)
    sys.exit(1)


def check(cond, msg):
    if not cond:
        fail(msg)


def to_float(v):
    return struct.unpack("f", struct.pack("f", v))[0]


def sqrt_double(sq):
    """The double nearest sqrt(sq) for an exact rational sq (100 digits, then rounded once)."""
    return float((Decimal(sq.numerator) / Decimal(sq.denominator)).sqrt())


# world/rotated, by hand: the world point in double (Python's float operations are IEEE double,
# each rounded, no FMA), then rounded to float; the case's own exact image in rationals.
C, S, PX, PY, X, Y = 0.6, 0.8, 2.0, 1.0, 0.1, 0.3
WX, WY = to_float((C * X - S * Y) + PX), to_float((S * X + C * Y) + PY)
WORLD_EXACT = sqrt_double(Fraction(WX) ** 2 + Fraction(WY) ** 2)
EX = Fraction(C) * Fraction(X) - Fraction(S) * Fraction(Y) + Fraction(PX)
EY = Fraction(S) * Fraction(X) + Fraction(C) * Fraction(Y) + Fraction(PY)
CASE_EXACT = sqrt_double(EX * EX + EY * EY)
SOURCE = "tests/plugins/adapters/toy.py (a float library that takes world points)"


def campaign(a, out, state, extra):
    shutil.rmtree(out, ignore_errors=True)
    shutil.rmtree(state, ignore_errors=True)
    os.makedirs(state)
    cmd = [
        a.exe,
        "run",
        "--cases",
        a.cases,
        "--variants",
        "float,toy-world",
        "--no-default-plugins",
        "--plugin",
        a.adapter,
        "--no-progress",
        "--per-case",
        "--out",
        out,
    ] + extra
    p = subprocess.run(
        cmd, capture_output=True, text=True, env=dict(os.environ, TOY_STATE_DIR=state)
    )
    if p.returncode != 0:
        fail(
            "{} exited {}\nstdout:\n{}\nstderr:\n{}".format(
                " ".join(cmd), p.returncode, p.stdout[-3000:], p.stderr[-3000:]
            )
        )
    with open(os.path.join(state, "requests")) as f:
        requests = [line.split() for line in f if line.strip()]
    with open(os.path.join(out, "report.json")) as f:
        return json.load(f), requests


def shapes(tok):
    """The shapes of one case's text (A ... B ...): [(r, px, py, c, s, [points])]."""
    out, i = [], 0
    while i < len(tok):
        check(tok[i] in ("A", "B"), "a shape starts with {}".format(tok[i]))
        r, px, py, c, s = (float(x) for x in tok[i + 1 : i + 6])
        n = int(tok[i + 6])
        v = [float(x) for x in tok[i + 7 : i + 7 + 2 * n]]
        out.append((r, px, py, c, s, [(v[2 * k], v[2 * k + 1]) for k in range(n)]))
        i += 7 + 2 * n
    return out


def check_sent(case_tokens, where):
    got = shapes(case_tokens)
    want = [(0.0, 0.0, 0.0, 1.0, 0.0, [(0.0, 0.0)]), (0.0, 0.0, 0.0, 1.0, 0.0, [(WX, WY)])]
    check(got == want, "{}: sent {}, expected the world case {}".format(where, got, want))


def check_cases(out):
    with open(os.path.join(out, "cases.jsonl")) as f:
        cases = {c["name"]: c for c in map(json.loads, f)}
    r = cases["world/rotated"]
    v = r["variants"]["toy-world"]
    check(
        v["truth"] == "world_input.float.exact" and v.get("input") == "world",
        "toy-world judged on {} (input {})".format(v["truth"], v.get("input")),
    )
    w = r["world_input"]["float"]
    check(
        w["exact"]["distance"] == WORLD_EXACT,
        "world case's exact distance {} != {}".format(w["exact"]["distance"], WORLD_EXACT),
    )
    check(
        r["exact"]["distance"] == CASE_EXACT,
        "case's exact distance {} != {}".format(r["exact"]["distance"], CASE_EXACT),
    )
    check(WORLD_EXACT != CASE_EXACT, "the test case does not tell the two truths apart")
    check(
        w["input_rounding"] == abs(WORLD_EXACT - CASE_EXACT),
        "input_rounding {} != {}".format(w["input_rounding"], abs(WORLD_EXACT - CASE_EXACT)),
    )
    check(not v["failed"], "toy-world's exact answer on its world case failed")
    check("input" not in r["variants"]["float"], "gjk2d's float variant given world points")
    skipped = cases["world/overflow"]["variants"]["toy-world"].get("skipped")
    check(
        skipped == "world points not representable in the implementation's scalar type",
        "world/overflow: toy-world skipped {!r}".format(skipped),
    )


def check_report(r):
    v = next(x for x in r["variants"] if x["name"] == "toy-world")
    check(
        v["contract"]["input"] == {"form": "world", "source": SOURCE},
        "contract.input {}".format(v["contract"]["input"]),
    )
    want = {
        "form": "world",
        "source": SOURCE,
        "cases": 1,
        "given": "world points rounded to float ({})".format(SOURCE),
    }
    check(v["input"] == want, "variants[].input {} != {}".format(v["input"], want))
    f = next(x for x in r["variants"] if x["name"] == "float")
    check(
        f["input"]["form"] == "case" and f["input"]["given"] == "the case as given",
        "float's input {}".format(f["input"]),
    )
    st = r["families"][0]["variants"]["toy-world"]
    check(
        st["cases"] == 1 and st["skipped"] == 1,
        "toy-world: {} cases, {} skipped".format(st["cases"], st["skipped"]),
    )
    ir = st["errors"]["input_rounding"]
    check(
        ir["count"] == 1 and ir["max"] == abs(WORLD_EXACT - CASE_EXACT),
        "toy-world's input_rounding {}".format(ir),
    )


def check_explain(a, state):
    """`explain` shows the world case toy-world was given, and says it is judged on it."""
    detail = os.path.join(a.work, "detail.json")
    cmd = [
        a.exe,
        "explain",
        a.cases,
        "world/rotated",
        "--variants",
        "toy-world",
        "--no-default-plugins",
        "--plugin",
        a.adapter,
        "--json",
        detail,
    ]
    p = subprocess.run(
        cmd, capture_output=True, text=True, env=dict(os.environ, TOY_STATE_DIR=state)
    )
    check(p.returncode == 0, "{} exited {}: {}".format(" ".join(cmd), p.returncode, p.stderr))
    for text in (
        "world case in float",
        "[0] local ({!r}, {!r})".format(WX, WY),
        "exact (world case, float): distance {!r}".format(WORLD_EXACT),
        "given the world case in float: judged on its exact result",
    ):
        check(text in p.stdout, "explain does not say {!r}:\n{}".format(text, p.stdout))
    with open(detail) as f:
        w = json.load(f)["world_input"]["float"]
    check(
        w["b"]["transform"] == {"p": [0.0, 0.0], "q": [1.0, 0.0]}
        and w["b"]["points"] == [[WX, WY]],
        "explain --json world_input.float.b {}".format(w["b"]),
    )


def main():
    ap = argparse.ArgumentParser()
    for k in ("--exe", "--adapter", "--cases", "--work"):
        ap.add_argument(k, required=True)
    a = ap.parse_args()
    out, state = os.path.join(a.work, "report"), os.path.join(a.work, "state")
    r, requests = campaign(a, out, state, ["--no-timing"])
    distance = [t for t in requests if t[0] == "distance"]
    check(
        len(distance) == 1 and len(requests) == 1,
        "{} requests, {} distance: expected one (the overflow case is not sent)".format(
            len(requests), len(distance)
        ),
    )
    check(distance[0][2] == "toy-world", "the request names {}".format(distance[0][2]))
    check_sent(distance[0][3:], "the distance request")
    check_cases(out)
    check_report(r)
    with open(os.path.join(out, "report.md")) as f:
        md = f.read()
    check(
        "- **toy-world**: on overlap `common-point` (gjk2d/distance.hpp, DistanceOutput); given "
        "world points rounded to float (" in md,
        "report.md's contracts do not say what " "toy-world is given",
    )
    # Timed: every case of a `time` request (time ID NAME K M, then M cases) is the world case.
    _, requests = campaign(a, out + "-timed", state, ["--passes", "1"])
    timed = [t for t in requests if t[0] == "time"]
    check(timed, "no time request in a timed run")
    for t in timed:
        m, body = int(t[4]), t[5:]
        check(m >= 1 and len(body) % m == 0, "time request of {} cases: {}".format(m, t))
        step = len(body) // m
        for k in range(m):
            check_sent(body[k * step : (k + 1) * step], "a time request's case")
    check_explain(a, state)
    print(
        "world_check: ok: toy-world was sent ({!r}, {!r}) with identity transforms and judged "
        "on the world case's exact distance {!r} (the case's: {!r})".format(
            WX, WY, WORLD_EXACT, CASE_EXACT
        )
    )


if __name__ == "__main__":
    main()
