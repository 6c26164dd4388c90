"""Test adapters of the executable-adapter protocol, version 1 (tests/plugins/CMakeLists.txt,
docs/plugin-abi.md, "Executable adapters"): good.py, crash.py, hang.py,
garbage.py, version.py, bad-description.py, crash-once-more.py, pipeline.py, fork-hang.py and
setsid.py each call main() with their behaviour.

The distance is brute force, exact enough for the test's cases: the smallest distance between a
vertex of one shape and an edge of the other (right for shapes that do not overlap; the tests'
cases are separated squares), less the radii. The misbehaving adapters answer like the good one
but on the case whose shape B is at x = 4 (the third case of adapter_cases.json): crash exits by
SIGSEGV, hang sleeps an hour, garbage answers a line that is no answer. pipeline answers like
good but reads its stdin itself to see the requests the host sent ahead (serve_watching).
fork-hang and setsid leave a process behind at each start (spawn_sleeper): a child that sleeps
300 s, its PID appended to $TOY_STATE_DIR/sleepers; fork-hang's child stays in the adapter's
process group and the adapter hangs on B at x = 4 as hang does, setsid's child calls setsid()
(out of the group, out of the session) and the adapter answers like good.

contract.py speaks protocol version 2 and declares a contract, as FCL without signed distance
does: overlap `zero` (it answers -1 and no points on overlap) and an absolute tolerance of 1e-6
(tests/plugins/contract_check.py, on contract_cases.json). It answers like good, but -1 and points
(0, 0) on overlap, below 1e-6 apart (within its tolerance) and on B at x = 1.25 (a false
overlap: 0.25 apart), and adds 5e-7 to the
distance with B at x = 4 (within its tolerance, beyond gjk2d's bound) and 1e-3 with B at x = 5
(beyond its tolerance).

depth.py (protocol version 2) declares overlap `penetration` and a depth clause, `contract
toy-depth depth 1e-3 none SOURCE` (tests/plugins/depth_contract_check.py, on contract_cases.json);
it answers like good, but on the overlapping squares (B at x = 0.5) minus the depth 0.5 and the
penetration pair (1, 0.5), (0.5, 0.5), derived by hand. depth-bad.py declares the clause with a
NaN tolerance, depth-zero.py one on overlap `zero`: both are refused at the handshake.

The `prepared` line and the `timed` figures (protocol version 2): prepared.py declares
`prepared toy-prepared case` and answers `timed ID NS PREPARE_NS`, its cases' world points built
once before the timed loop (prepare()), the `distance` requests through the same prepare() and
query. The misbehaving ones answer right but time wrong, or describe themselves wrong:
prepared-missing declares `prepared ... shape` and answers one figure; timed-extra declares none
and answers two; too-fast answers `timed ID 1` (below 1 ns a query); prepared-bad-scope declares
the scope `world`; prepared-v1 gives a prepared line in a version-1 handshake.

The `input NAME world SOURCE` line (protocol version 2): world.py is a float implementation that
declares `input toy-world world ...`, so the host sends it every case as its world points rounded
to float with identity transforms (tests/plugins/world_check.py checks what it was sent); it
appends every request line it reads to $TOY_STATE_DIR/requests and answers like good on what it
was given. The malformed ones are refused at the handshake: world-bad-form (`input NAME local`),
world-twice (two input lines for one name), world-unknown (a name no implementation has),
world-v1 (an input line in a version-1 handshake).
"""
import os
import select
import signal
import sys
import time


def world(tok, i):
    """The shape at tok[i] ('A' or 'B'): its world points and radius, and the index after it."""
    r, px, py, c, s = (float(x) for x in tok[i + 1 : i + 6])
    n = int(tok[i + 6])
    v = [float(x) for x in tok[i + 7 : i + 7 + 2 * n]]
    pts = [
        (c * v[2 * k] - s * v[2 * k + 1] + px, s * v[2 * k] + c * v[2 * k + 1] + py)
        for k in range(n)
    ]
    return pts, r, px, i + 7 + 2 * n


def closest_on_segment(p, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    dd = dx * dx + dy * dy
    t = 0.0 if dd == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / dd))
    return (a[0] + t * dx, a[1] + t * dy)


def edges(pts):
    return [(pts[k], pts[(k + 1) % len(pts)]) for k in range(len(pts))]


def distance(a, ra, b, rb):
    best = None
    for p in a:  # a vertex of A against an edge of B, then the other way round
        for e in edges(b):
            q = closest_on_segment(p, *e)
            d = ((p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2) ** 0.5
            if best is None or d < best[0]:
                best = (d, p, q)
    for q in b:
        for e in edges(a):
            p = closest_on_segment(q, *e)
            d = ((p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2) ** 0.5
            if d < best[0]:
                best = (d, p, q)
    d, p, q = best
    if d == 0 or d <= ra + rb:
        return 0.0, p, q
    u = ((q[0] - p[0]) / d, (q[1] - p[1]) / d)
    return (d - ra - rb, (p[0] + ra * u[0], p[1] + ra * u[1]), (q[0] - rb * u[0], q[1] - rb * u[1]))


def say(line):
    sys.stdout.write(line + "\n")
    sys.stdout.flush()


def prepare(tok, i):
    """The case at tok[i] prepared (its world points, baked in) and the index after it."""
    a, ra, _, i = world(tok, i)
    b, rb, bx, i = world(tok, i)
    return (a, ra, b, rb, bx), i


def answer(tok, behaviour):
    (a, ra, b, rb, bx), _ = prepare(tok, 3)
    if bx == 4 and behaviour in ("crash", "crash-once-more"):
        os.kill(os.getpid(), signal.SIGSEGV)
    if bx == 4 and behaviour in ("hang", "fork-hang"):
        time.sleep(3600)
    if bx == 4 and behaviour == "garbage":
        return "hello there " + tok[1]
    d, p, q = distance(a, ra, b, rb)
    if behaviour == "depth" and bx == 0.5:  # two unit squares 0.5 deep along x
        return "ok {} -0.5 1.0 0.5 0.5 0.5 -1".format(tok[1])
    if behaviour == "contract":
        if d < 1e-6 or bx == 1.25:  # what FCL's tolerance does to a near touch
            return "ok {} -1.0 0.0 0.0 0.0 0.0 -1".format(tok[1])
        d += {4: 5e-7, 5: 1e-3}.get(bx, 0.0)
    return "ok {} {!r} {!r} {!r} {!r} {!r} -1".format(tok[1], d, p[0], p[1], q[0], q[1])


def timed(tok, behaviour):
    k, m = int(tok[3]), int(tok[4])
    cases, i = [], 5
    p0 = time.monotonic_ns()
    for _ in range(m):
        c, i = prepare(tok, i)
        cases.append(c[:4])
    p1 = time.monotonic_ns()
    t0 = time.monotonic_ns()
    for _ in range(k):
        for c in cases:
            distance(*c)
    ns = time.monotonic_ns() - t0
    if behaviour == "too-fast":
        return "timed {} 1".format(tok[1])
    if behaviour in ("prepared", "timed-extra"):
        return "timed {} {} {}".format(tok[1], ns, p1 - p0)
    return "timed {} {}".format(tok[1], ns)


def start_number():
    """This process's start, counted in $TOY_STATE_DIR/starts (1 for the first)."""
    path = os.path.join(os.environ["TOY_STATE_DIR"], "starts")
    n = int(open(path).read()) + 1 if os.path.exists(path) else 1
    with open(path, "w") as f:
        f.write(str(n))
    return n


def spawn_sleeper(new_session):
    """A child that outlives this process unless the host ends it: it sleeps 300 s, with
    /dev/null for stdin and stdout (the host's pipes are this process's alone). Its PID is in
    $TOY_STATE_DIR/sleepers before this returns, and with new_session it has left the process
    group and the session (setsid) by then too."""
    ready_r, ready_w = os.pipe()
    pid = os.fork()
    if pid == 0:
        os.close(ready_r)
        if new_session:
            os.setsid()
        null = os.open(os.devnull, os.O_RDWR)
        os.dup2(null, 0)
        os.dup2(null, 1)
        os.write(ready_w, b"1")
        os.close(ready_w)
        time.sleep(300)
        os._exit(0)
    os.close(ready_w)
    os.read(ready_r, 1)
    os.close(ready_r)
    with open(os.path.join(os.environ["TOY_STATE_DIR"], "sleepers"), "a") as f:
        f.write("{}\n".format(pid))


def wait_for_window(fd, buf):
    """Reads what the host sends without answering: until 64 requests are held and 0.1 s pass
    with nothing more (a 65th would come within it), or 0.3 s of quiet before that (a window
    that the 32 KiB bound closed earlier). The host sends nothing more until an answer comes."""
    while True:
        quiet = 0.1 if buf.count(b"\n") >= 64 else 0.3
        if not select.select([fd], [], [], quiet)[0]:
            return buf
        chunk = os.read(fd, 1 << 16)
        if not chunk:
            return buf
        buf += chunk


def serve_watching():
    """pipeline: at its 1st, 101st, 501st, ... distance request (every 500th and 100 after it),
    waits for the host's window to fill and appends to $TOY_STATE_DIR/window one line: the
    requests held unanswered, and the bytes of all but the last of them (the host sends a
    request while those are under 32 KiB)."""
    fd, buf, seen = sys.stdin.fileno(), b"", 0
    log = open(os.path.join(os.environ["TOY_STATE_DIR"], "window"), "a")
    while True:
        while b"\n" not in buf:
            chunk = os.read(fd, 1 << 16)
            if not chunk:
                return
            buf += chunk
        if seen % 500 in (0, 100):
            buf = wait_for_window(fd, buf)
            held = [len(x) + 1 for x in buf.split(b"\n")[:-1]]
            log.write("{} {}\n".format(len(held), sum(held[:-1])))
            log.flush()
        line, buf = buf.split(b"\n", 1)
        seen += 1
        tok = line.decode().split()
        say(timed(tok, "pipeline") if tok[0] == "time" else answer(tok, "pipeline"))


def input_lines(behaviour):
    """The `input` lines of world.py and its malformed kin (protocol version 2)."""
    name = "toy-" + behaviour
    source = "tests/plugins/adapters/toy.py (a float library that takes world points)"
    if behaviour == "world-unknown":
        name = "toy-nobody"
    form = "local" if behaviour == "world-bad-form" else "world"
    say("input {} {} {}".format(name, form, source))
    if behaviour == "world-twice":
        say("input {} world {}".format(name, source))


def main(behaviour):
    if sys.stdin.readline().split() != ["gjk2d-adapter", "1"]:
        sys.exit(1)
    # crash-once-more: crashes on d3 like crash, and its restart after that (its third start: the
    # load's handshake, the first case, then the restart) exits in the handshake.
    if behaviour == "crash-once-more" and start_number() >= 3:
        print("toy adapter: this start fails on purpose", file=sys.stderr)
        sys.exit(3)
    if behaviour in ("fork-hang", "setsid"):
        spawn_sleeper(behaviour == "setsid")
    version = {
        "version": 3,
        "contract": 2,
        "prepared": 2,
        "prepared-missing": 2,
        "prepared-bad-scope": 2,
        "depth": 2,
        "depth-bad": 2,
        "depth-zero": 2,
        "world": 2,
        "world-bad-form": 2,
        "world-twice": 2,
        "world-unknown": 2,
    }.get(behaviour, 1)
    say("gjk2d-adapter {}".format(version))
    say("library toy 1.0 (brute force, tests/plugins/adapters)")
    scalar = {"bad-description": "quad", "world": "float"}.get(behaviour, "double")
    say("implementation toy-{} {} radius 0 vertex-edge brute force".format(behaviour, scalar))
    if behaviour == "contract":
        say("contract toy-contract overlap zero tests/plugins/adapters/toy.py, answer()")
        say("contract toy-contract tolerance 1e-6 none tests/plugins/adapters/toy.py, answer()")
    if behaviour in ("depth", "depth-bad", "depth-zero"):  # the depth line before its overlap's
        tolerance = "nan none" if behaviour == "depth-bad" else "1e-3 none"
        say("contract toy-{} depth {} tests/plugins/adapters/toy.py".format(behaviour, tolerance))
        overlap = "zero" if behaviour == "depth-zero" else "penetration"
        say(
            "contract toy-{} overlap {} tests/plugins/adapters/toy.py, answer()".format(
                behaviour, overlap
            )
        )
    scope = {
        "prepared": "case",
        "prepared-missing": "shape",
        "prepared-bad-scope": "world",
        "prepared-v1": "case",
    }.get(behaviour)
    if scope:
        say("prepared toy-{} {}".format(behaviour, scope))
    if behaviour.startswith("world"):
        input_lines(behaviour)
    say("ready")
    print("toy adapter {}: ready".format(behaviour), file=sys.stderr)  # into the plugin's log
    if behaviour == "pipeline":
        return serve_watching()
    requests = None
    if behaviour == "world":
        requests = open(os.path.join(os.environ["TOY_STATE_DIR"], "requests"), "a")
    for line in sys.stdin:
        if requests:
            requests.write(line)
            requests.flush()
        tok = line.split()
        if tok and tok[0] == "distance":
            say(answer(tok, behaviour))
        elif tok and tok[0] == "time":
            say(timed(tok, behaviour))
        elif tok:
            say("error {} unknown request".format(tok[1]))
