#!/usr/bin/env python3
"""Instructions per query per stage from a callgrind profile (--dump-instr=yes).

  stages.py CALLGRIND_OUT BINARY NQUERIES FNSUBSTR...

Counts the instructions of the functions whose name contains one of FNSUBSTR and attributes each
instruction, through its inline chain (addr2line -i), to the innermost function that names a stage
in STAGES (gjk2d's or Box2D v3's); "other" is the rest (the call, the copy of the output). Run by
stage_profile.sh. Exit codes: 0 printed; a Python error (1) on an unreadable file."""
import re, sys, collections, subprocess

path, binp, n = sys.argv[1], sys.argv[2], float(sys.argv[3])
fnsubs = sys.argv[4:]
cost = collections.Counter()
fn = None
addr = 0
skip = False
names = {}
for raw in open(path):
    if raw.startswith(("fn=", "cfn=")):
        m = re.match(r"c?fn=\((\d+)\)(?: (.*))?", raw.strip())
        if m.group(2):
            names[m.group(1)] = m.group(2)
        if raw.startswith("fn="):
            fn = names.get(m.group(1))
        continue
    if raw.startswith("calls="):
        skip = True
        continue
    m = re.match(r"^(0x[0-9a-f]+|[+-](?:0x)?[0-9a-f]+|\*)\s+([+-]?\d+|\*)\s+(\d+)", raw)
    if not m:
        continue
    t = m.group(1)
    if t == "*":
        pass
    elif t.startswith("0x"):
        addr = int(t, 16)
    else:
        v = int(t[1:], 16) if t[1:].startswith("0x") else int(t[1:])
        addr = addr + v if t[0] == "+" else addr - v
    if skip:
        skip = False
        continue
    if fn and any(s in fn for s in fnsubs):
        cost[addr] += int(m.group(3))
addrs = sorted(cost)
# addr2line -a prints each address, then a (function, file:line) pair per inline level.
out = subprocess.run(
    ["addr2line", "-a", "-f", "-i", "-C", "-e", binp] + [hex(a) for a in addrs],
    capture_output=True,
    text=True,
).stdout.splitlines()
chains = {}
cur = None
for l in out:
    if re.match(r"^0x[0-9a-f]+$", l):
        cur = int(l, 16)
        chains[cur] = []
        continue
    if cur is not None and not re.match(r".*:\d+", l) and not l.startswith("??:"):
        chains[cur].append(l)
STAGES = [
    (
        "set-up: frame and transform into A",
        [
            "setUpShapes",
            "invMulTransforms",
            "invMulRot",
            "distanceImpl",
            "cacheFits",
            "iterationLimit",
            "usesBinarySearch",
            "TransformedShape<double, false>::TransformedShape",
            "startLoop",
        ],
    ),
    ("start simplex (first support)", ["startSimplex"]),
    ("support scans (+ direction into B)", ["findSupportSum", "findSupport", "::support("]),
    ("chosen points: transform, vertex", ["makeVertex", "::vertex(", "transformPoint"]),
    (
        "solve2 / solve3 (edgeOfSafeSize)",
        [
            "solve2",
            "solve3",
            "keepEdge",
            "keepVertex",
            "keepTriangle",
            "keepClosestEdge",
            "edgeOfSafeSize",
            "solveSimplex",
            "scaleUpEdge",
            "accurateCross",
        ],
    ),
    ("search direction", ["searchDirection"]),
    ("loop: repeat keys, range max, control", ["runLoop"]),
    ("end: world frame (non-unit rotation)", ["toWorldFrame"]),
    ("end: range checks", ["rangeExceeded", "overflowed"]),
    (
        "end: answer, radii, cache",
        ["finishQuery", "readSimplex", "applyRadii", "writeCache", "computeWitnessPoints"],
    ),
    # Box2D
    ("b2: support scans", ["b2FindSupport"]),
    ("b2: B into A frame, start", ["b2MakeSimplexFromCache", "b2TransformPoint"]),
    ("b2: solvers", ["b2SolveSimplex2", "b2SolveSimplex3"]),
    (
        "b2: end (witness, cache, radii)",
        ["b2ComputeWitnessPoints", "b2MakeSimplexCache", "b2Normalize", "b2Distance"],
    ),
    ("b2: loop", ["b2ShapeDistance"]),
]
by = collections.Counter()
for a, c in cost.items():
    st = "other"
    for f in chains.get(a, []):
        hit = [s for s, keys in STAGES if any(k in f for k in keys)]
        if hit:
            st = hit[0]
            break
    by[st] += c
for s, _ in STAGES + [("other", [])]:
    if by[s]:
        print(f"{by[s]/n:8.1f}  {s}")
print(f"{sum(by.values())/n:8.1f}  total")
