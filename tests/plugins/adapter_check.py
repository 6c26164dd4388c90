#!/usr/bin/env python3
"""Executable adapters (protocol 1, issue 32) in a campaign (tests/plugins/CMakeLists.txt).

  adapter_check.py --exe E --kind K --adapter A [--cases C] [--so S] --work W

Runs `gjk-validate run` on C (adapters/adapter_cases.json: two unit squares at distances 1, 2, 3
and 4, derived by hand there) with the variant double and the plugin A, into W/report, and checks:
  good     report.json names A as an executable adapter with its library line; the adapter's
           distances in cases.jsonl are 1, 2, 3, 4 (exact for these squares: the edges x = 1 and
           x = 1 + d are parallel); no failure; it was timed (ns_per_query > 0, `time` requests);
           `list` shows its variant; what it printed on stderr is in its log, not on gjk-validate's.
  crash, hang, garbage
           the third case (d3) costs one case, counted (crashed, hung, plugin_errors = 1), with one
           stderr line naming A and the case; the other three are answered (1, 2, 4); exit code 0
           (a comparison variant), 1 under --judge (docs/validate-your-gjk.md).
  crash-once-more
           crashes on d3, and its restart fails (it exits in the handshake): d3 and d4 are
           counted as crashed, d4 with the restart's reason, one stderr line for d3 and one for
           the failed start; d1, d2 answered.
  pipeline A is pipeline.py (the good adapter, watching its stdin), on 2000 cases written into W
           (pipeline_cases: squares at distances 0.5 + i/256, every 250th and 255th with a
           2048-point A whose hull is the same unit square, so the same distance, derived as for
           adapter_cases.json): every answer is its own case's distance (the host pairs the
           pipelined answers with their cases in order); the adapter saw 64 requests held
           unanswered at some point and never more, never a request sent while those before it
           were 32 KiB or more, and at some point fewer than 64 (the byte bound binding). Then
           crash.py, hang.py and garbage.py on the same cases: they misbehave on case 640
           (B at x = 4) with up to 63 later requests in flight: that case alone is lost, every
           other one answered right (the later ones were sent again to the next process).
  prepared A declares `prepared toy-prepared case` (protocol 2) and answers two figures: its
           distances are 1, 2, 3, 4, it was timed (ns_per_query > 0), and report.json's
           variants[].timing says preparation "case", timed by the adapter.
  prepared-missing, timed-extra, too-fast
           A answers every case right but its `timed` answers are refused: a missing preparation
           figure after a `prepared` line, a second figure without one, 1 ns for K x m queries
           (below 1 ns a query). The distances are 1, 2, 3, 4; ns_per_query is null; stderr has
           one line naming A and saying why; exit code 0.
  bridge   A is gjk2d-adapter-bridge: a two-line script runs it with the shipped gjk2d-box2d.so
           (--so) as box2d-2.4.1-bridge beside box2d-2.4.1 itself, on random and
           rounded cases: every answer (distance, witness points, iterations, refusal) is the
           same, bit for bit (the same function on the same inputs: the protocol's numbers
           round-trip).
  bridge-prepared
           A is gjk2d-adapter-bridge hosting --so, a plugin with prepared shapes
           (prepared_plugin.cpp: test-prepared-shape, scope shape; test-prepared-case, scope
           case): the bridge's handshake is version 2 with a `prepared` line per implementation,
           by its scope; on random and rounded cases every answer through the bridge (prepare,
           distance, release) is the plugin's own (its distance_d), errors included (a shape of
           7 points cannot be prepared); both bridged variants are timed (ns_per_query > 0:
           the `timed` answers carry two figures) and report.json says preparation shape and
           case, timed by the adapter.
  fork-hang, setsid
           A leaves a sleeping child behind at each of its starts (its PID in W/sleepers):
           fork-hang's stays in A's process group and A hangs on d3, setsid's leaves the group
           and the session. After gjk-validate exits, no such child is left (each PID is gone
           within 2 s: killed and reaped, not a zombie); d1, d2, d4 answered (d3 hung for
           fork-hang). Each start counts: the load's handshake, the cases, the start after a hang.
  shared   A is a shared-library plugin with its exec bit set (as CMake links it): it is loaded
           as a shared library (variants[].plugin.kind), not started.
Exit 0 when every check holds; else a message and exit 1.
"""
import argparse
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time


def fail(msg):
    print("adapter_check: FAIL: " + msg, file=sys.stderr)
    sys.exit(1)


def run(cmd, expect=0):
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != expect:
        fail(
            "{} exited {}, expected {}\nstdout:\n{}\nstderr:\n{}".format(
                " ".join(cmd), p.returncode, expect, p.stdout[-3000:], p.stderr[-3000:]
            )
        )
    return p


def campaign(a, extra=(), expect=0):
    out = os.path.join(a.work, "report")
    for f in ["starts"]:  # crash-once-more's count of its starts
        if os.path.exists(os.path.join(a.work, f)):
            os.remove(os.path.join(a.work, f))
    cmd = [
        a.exe,
        "run",
        "--cases",
        a.cases,
        "--variants",
        "double",
        "--no-default-plugins",
        "--plugin",
        a.adapter,
        "--plugin-timeout",
        "2",
        "--per-case",
        "--passes",
        "3",
        "--out",
        out,
        "--no-progress",
    ] + list(extra)
    p = run(cmd, expect)
    report = json.load(open(os.path.join(out, "report.json")))
    lines = [json.loads(l) for l in open(os.path.join(out, "cases.jsonl"))]
    return p, report, lines, out


def plugin_of(report, name):
    """The context.plugins entry of the plugin that gave variant `name`."""
    for p in report["context"]["plugins"]:
        if name in p["variants"]:
            return p
    fail("no plugin gave variant {} in report.json's context.plugins".format(name))


def stats_of(report, name):
    return report["families"][0]["variants"][name]


def answers(lines, name):
    return {l["name"]: l["variants"][name] for l in lines}


def good(a):
    p, report, lines, out = campaign(a)
    pl = plugin_of(report, "toy-good")
    if pl["kind"] != "executable-adapter" or not pl["library"].startswith("toy 1.0"):
        fail("context.plugins: {}".format(pl))
    got = {k: v.get("distance") for k, v in answers(lines, "toy-good").items()}
    if got != {"adapters/d1": 1.0, "adapters/d2": 2.0, "adapters/d3": 3.0, "adapters/d4": 4.0}:
        fail("the adapter's distances: {}".format(got))
    st = stats_of(report, "toy-good")
    if st["cases"] != 4 or st["failures"] != 0 or not (st["ns_per_query"] or 0) > 0:
        fail("stats: {}".format(st))
    if "toy-good" not in run([a.exe, "list", "--no-default-plugins", "--plugin", a.adapter]).stdout:
        fail("`list` does not show toy-good")
    if "toy adapter good: ready" in p.stderr:
        fail("the adapter's stderr reached gjk-validate's during the run:\n" + p.stderr)
    if "toy adapter good: ready" not in open(os.path.join(out, "plugin-good.log")).read():
        fail("the adapter's stderr is not in plugin-good.log")
    print(
        "adapter_check: good: distances 1, 2, 3, 4 in cases.jsonl, timed {:.0f} ns/query".format(
            st["ns_per_query"]
        )
    )


def answered_all(lines, name):
    got = {k: v.get("distance") for k, v in answers(lines, name).items()}
    if got != {"adapters/d1": 1.0, "adapters/d2": 2.0, "adapters/d3": 3.0, "adapters/d4": 4.0}:
        fail("{}'s distances: {}".format(name, got))


def variant_entry(report, name):
    for v in report["variants"]:
        if v["name"] == name:
            return v
    fail("no variant {} in report.json's variants".format(name))


def prepared(a):
    _, report, lines, _ = campaign(a)
    answered_all(lines, "toy-prepared")
    st = stats_of(report, "toy-prepared")
    if st["failures"] != 0 or not (st["ns_per_query"] or 0) > 0:
        fail("stats: {}".format(st))
    timing = variant_entry(report, "toy-prepared")["timing"]
    if timing["preparation"] != "case" or timing["timed_by"] != "adapter":
        fail("variants[].timing: {}".format(timing))
    print(
        "adapter_check: prepared: distances 1, 2, 3, 4, timed {:.0f} ns/query, preparation "
        "case, timed by the adapter".format(st["ns_per_query"])
    )


TIMED_REFUSALS = {
    "prepared-missing": "without the preparation's figure that its `prepared` line promises",
    "timed-extra": "a second figure without a `prepared` line in its handshake",
    "too-fast": "x 4 queries: below 1 ns a query, which no distance query reaches; no ns/query",
}


def timed_refused(a):
    name = "toy-" + a.kind
    p, report, lines, _ = campaign(a)
    answered_all(lines, name)
    st = stats_of(report, name)
    if st["ns_per_query"] is not None or st["failures"] != 0:
        fail("expected ns_per_query null and no failure: {}".format(st))
    said = [
        l
        for l in p.stderr.splitlines()
        if l.startswith("gjk-validate: executable adapter " + os.path.realpath(a.adapter))
    ]
    if (
        len(said) != 1
        or TIMED_REFUSALS[a.kind] not in said[0]
        or not said[0].endswith("; no ns/query")
    ):
        fail("expected one stderr line saying '{}':\n{}".format(TIMED_REFUSALS[a.kind], p.stderr))
    if report["exit_code"] != 0:
        fail("a refused timing decided the exit code")
    print("adapter_check: {}: answers kept, no ns/query, one line: {}".format(a.kind, said[0]))


def contained(a):
    name = "toy-" + a.kind
    counter = {"crash": "crashed", "hang": "hung", "garbage": "plugin_errors"}[a.kind]
    p, report, lines, _ = campaign(a)
    st = stats_of(report, name)
    if st[counter] != 1 or st["failures"] != 1 or st["cases"] != 4:
        fail("expected one case counted as {}: {}".format(counter, st))
    got = answers(lines, name)
    if [got["adapters/d" + k].get("distance") for k in "124"] != [1.0, 2.0, 4.0]:
        fail("the other cases' answers: {}".format(got))
    status = {"crash": "crashed", "hang": "hung", "garbage": "error"}[a.kind]
    if got["adapters/d3"].get("plugin_status") != status:
        fail("d3: {}".format(got["adapters/d3"]))
    if a.kind == "garbage" and not got["adapters/d3"]["plugin_detail"].startswith(
        'malformed answer: "hello there'
    ):
        fail("d3's detail: {}".format(got["adapters/d3"]))
    named = [l for l in p.stderr.splitlines() if "adapters/d3" in l]
    if len(named) != 1 or os.path.realpath(a.adapter) not in named[0]:
        fail("expected one stderr line naming the adapter and the case:\n" + p.stderr)
    if report["exit_code"] != 0:
        fail("a comparison adapter decided the exit code")
    campaign(a, ["--judge", name, "--no-timing"], expect=1)
    print(
        "adapter_check: {}: d3 counted as {}, d1, d2, d4 answered; --judge exits 1".format(
            a.kind, counter
        )
    )


def restart_fails(a):
    p, report, lines, _ = campaign(a, ["--no-timing"])
    st = stats_of(report, "toy-crash-once-more")
    got = answers(lines, "toy-crash-once-more")
    if st["crashed"] != 2 or [got["adapters/d" + k].get("distance") for k in "12"] != [1.0, 2.0]:
        fail("expected d3 and d4 crashed, d1 and d2 answered: {} {}".format(st, got))
    if (
        "restart" not in got["adapters/d4"]["plugin_detail"]
        and "start for the cases failed" not in got["adapters/d4"]["plugin_detail"]
    ):
        fail("d4's detail: {}".format(got["adapters/d4"]))
    lines = [
        l for l in p.stderr.splitlines() if "executable adapter " + os.path.realpath(a.adapter) in l
    ]
    if len(lines) != 2 or "adapters/d3" not in lines[0] or "failed" not in lines[1]:
        fail("expected a line for d3 and one for the failed start:\n" + p.stderr)
    print("adapter_check: crash-once-more: d3 crashed, the restart failed, d4 crashed with it")


PIPELINE_CASES = 2000


def pipeline_cases(path):
    """The 2000 cases of the pipeline check, and their distances by name."""
    square = [[0, 0], [1, 0], [1, 1], [0, 1]]
    k = [j / 512 for j in range(512)]  # 512 points on each edge of the unit square, in order
    dense = (
        [[x, 0] for x in k]
        + [[1, y] for y in k]
        + [[1 - x, 1] for x in k]
        + [[0, 1 - y] for y in k]
    )
    cases, want = [], {}
    for i in range(PIPELINE_CASES):
        d = 0.5 + i / 256  # B's edge x = 1 + d faces A's edge x = 1: the distance is d, exactly
        name = "pipeline/{:04d}".format(i)
        a = dense if i % 250 in (125, 130) else square
        cases.append(
            {
                "name": name,
                "a": {"points": a},
                "b": {"points": square, "transform": {"p": [1 + d, 0.0], "q": [1.0, 0.0]}},
            }
        )
        want[name] = d
    with open(path, "w") as f:
        json.dump({"format": "gjk-cases/1", "cases": cases}, f)
    return want


def gone(pid, grace):
    """Whether no process has the PID within `grace` seconds (a zombie still has it)."""
    deadline = time.monotonic() + grace
    while True:
        try:
            os.kill(pid, 0)
        except ProcessLookupError:
            return True
        if time.monotonic() > deadline:
            return False
        time.sleep(0.05)


def tree(a):
    name = "toy-" + a.kind
    _, report, lines, _ = campaign(a, ["--no-timing"])
    pids = [int(l) for l in open(os.path.join(a.work, "sleepers"))]
    starts = 3 if a.kind == "fork-hang" else 2
    left = [pid for pid in pids if not gone(pid, 2)]
    for pid in left:  # the check fails; nothing of it outlives it either
        os.kill(pid, signal.SIGKILL)
    if left:
        fail("children of the adapter outlived gjk-validate: {} of {}".format(left, pids))
    if len(pids) != starts:
        fail("expected {} starts, each leaving a child: {}".format(starts, pids))
    got = answers(lines, name)
    expect = {"adapters/d1": 1.0, "adapters/d2": 2.0, "adapters/d4": 4.0}
    expect["adapters/d3"] = None if a.kind == "fork-hang" else 3.0
    if {k: v.get("distance") for k, v in got.items()} != expect:
        fail("the adapter's answers: {}".format(got))
    print(
        "adapter_check: {}: the children of its {} starts ended with gjk-validate".format(
            a.kind, starts
        )
    )


def pipeline_window(a):
    """The window the pipeline adapter saw: the host never exceeded it, and filled it."""
    snaps = [tuple(map(int, l.split())) for l in open(os.path.join(a.work, "window"))]
    if len(snaps) != 8 or max(n for n, _ in snaps) != 64 or min(n for n, _ in snaps) >= 64:
        fail("expected 8 snapshots, one with 64 requests held, one with fewer: {}".format(snaps))
    if any(before >= 32 * 1024 for _, before in snaps):
        fail("a request was sent while 32 KiB or more were unanswered: {}".format(snaps))
    return snaps


def pipeline(a):
    a.cases = os.path.join(a.work, "pipeline_cases.json")
    want = pipeline_cases(a.cases)
    here = os.path.dirname(a.adapter)
    for kind in ["pipeline", "crash", "hang", "garbage"]:
        a.adapter = os.path.join(here, kind + ".py")
        p, report, lines, _ = campaign(a, ["--no-timing"])
        got = answers(lines, "toy-" + kind)
        status = {"crash": "crashed", "hang": "hung", "garbage": "error"}.get(kind)
        named = [l for l in p.stderr.splitlines() if "case 'pipeline/" in l]
        if status and (
            got["pipeline/0640"].get("plugin_status") != status
            or len(named) != 1
            or "pipeline/0640" not in named[0]
        ):
            fail(
                "{}: expected case 640 {} and one stderr line naming it: {}\n{}".format(
                    kind, status, got["pipeline/0640"], p.stderr
                )
            )
        lost = {n for n, v in got.items() if v.get("distance") != want[n]}
        expect = set() if kind == "pipeline" else {"pipeline/0640"}
        if len(got) != PIPELINE_CASES or lost != expect:
            fail(
                "{}: cases not answered with their distance: {} (expected {})".format(
                    kind, {n: got.get(n) for n in sorted(lost)[:5]}, expect
                )
            )
        if kind == "pipeline":
            snaps = pipeline_window(a)
    print(
        "adapter_check: pipeline: 2000 answers in order, window {} (requests, bytes before the "
        "last); crash, hang, garbage lose case 640 alone".format(snaps)
    )


def bridge(a):
    wrapper = os.path.join(a.work, "box2d-bridge")
    with open(wrapper, "w") as f:
        f.write("#!/bin/sh\nexec {} {} -bridge\n".format(a.adapter, a.so))
    os.chmod(wrapper, 0o755)
    out = os.path.join(a.work, "report")
    run(
        [
            a.exe,
            "run",
            "--family",
            "random:300",
            "--family",
            "hard/rounded:40",
            "--variants",
            "double,box2d-2.4.1,box2d-2.4.1-bridge",
            "--plugin",
            wrapper,
            "--per-case",
            "--no-timing",
            "--out",
            out,
            "--no-progress",
        ]
    )
    keys = ("distance", "pointA", "pointB", "iterations", "skipped")
    n = 0
    for l in open(os.path.join(out, "cases.jsonl")):
        j = json.loads(l)
        mine, theirs = (j["variants"][v] for v in ("box2d-2.4.1-bridge", "box2d-2.4.1"))
        if [mine.get(k) for k in keys] != [theirs.get(k) for k in keys]:
            fail(
                "{}: the bridge answered {}, the shared library {}".format(j["name"], mine, theirs)
            )
        n += 1
    if n != 340:
        fail("expected 340 cases, got {}".format(n))
    print("adapter_check: bridge: 340 cases, every answer the shared library's, bit for bit")
    # The contract (ABI and protocol version 2): the bridge speaks the plugin's version and forwards
    # its declared contract as the three `contract` lines (box2d.cpp's kContract: midpoint, its
    # source, no tolerance, margin 0), and a `prepared` line when the plugin exports
    # gjk2d_plugin_prepared.
    h = subprocess.run(
        [a.adapter, a.so, "-bridge"],
        input="gjk2d-adapter 1\n",
        capture_output=True,
        text=True,
        timeout=30,
    ).stdout.splitlines()
    name = "box2d-2.4.1-bridge"
    want = [
        r"gjk2d-adapter 2",
        r"library .*",
        r"implementation {} .*".format(name),
        r"contract {} overlap midpoint src/collision/b2_distance\.cpp:588-596 .*Box2D 2\.4\.1.*".format(
            name
        ),
        r"contract {} tolerance none none".format(name),
        r"contract {} margin 0".format(name),
        r"ready",
    ]
    if len(h) == len(want) + 1:  # a plugin with prepared shapes: the bridge's `prepared` line
        want.insert(-1, r"prepared {} (shape|case)".format(name))
    if len(h) != len(want) or not all(re.fullmatch(w, l) for w, l in zip(want, h)):
        fail("the bridge's handshake {} does not match {}".format(h, want))
    print("adapter_check: bridge: protocol 2, the plugin's contract forwarded")


def bridge_prepared(a):
    wrapper = os.path.join(a.work, "prepared-bridge")
    with open(wrapper, "w") as f:
        f.write("#!/bin/sh\nexec {} {} -bridge\n".format(a.adapter, a.so))
    os.chmod(wrapper, 0o755)
    h = subprocess.run(
        [wrapper], input="gjk2d-adapter 1\n", capture_output=True, text=True, timeout=30
    ).stdout.splitlines()
    want = [
        r"gjk2d-adapter 2",
        r"library .*",
        r"implementation test-prepared-shape-bridge .*",
        r"prepared test-prepared-shape-bridge shape",
        r"implementation test-prepared-case-bridge .*",
        r"prepared test-prepared-case-bridge case",
        r"ready",
    ]
    if len(h) != len(want) or not all(re.fullmatch(w, l) for w, l in zip(want, h)):
        fail("the bridge's handshake {} does not match {}".format(h, want))
    out = os.path.join(a.work, "report")
    names = ["test-prepared-shape", "test-prepared-case"]
    run(
        [
            a.exe,
            "run",
            "--family",
            "random:300",
            "--family",
            "hard/rounded:40",
            "--variants",
            ",".join(["double"] + names + [n + "-bridge" for n in names]),
            "--no-default-plugins",
            "--plugin",
            a.so,
            "--plugin",
            wrapper,
            "--per-case",
            "--passes",
            "3",
            "--out",
            out,
            "--no-progress",
        ]
    )
    keys = ("distance", "pointA", "pointB", "iterations", "skipped", "plugin_status")
    n, errors = 0, 0
    for l in open(os.path.join(out, "cases.jsonl")):
        j = json.loads(l)
        for name in names:
            mine, theirs = j["variants"][name + "-bridge"], j["variants"][name]
            if [mine.get(k) for k in keys] != [theirs.get(k) for k in keys]:
                fail("{}: the bridge answered {}, the plugin {}".format(j["name"], mine, theirs))
            errors += theirs.get("plugin_status") == "error"
        n += 1
    if n != 340 or errors == 0:
        fail("expected 340 cases, some of them errors (7 points), got {} and {}".format(n, errors))
    report = json.load(open(os.path.join(out, "report.json")))
    for name, scope in zip(names, ["shape", "case"]):
        st = [f["variants"][name + "-bridge"]["ns_per_query"] for f in report["families"]]
        timing = variant_entry(report, name + "-bridge")["timing"]
        if (
            not all((x or 0) > 0 for x in st)
            or timing["preparation"] != scope
            or timing["timed_by"] != "adapter"
        ):
            fail("{}-bridge: ns_per_query {}, timing {}".format(name, st, timing))
    print(
        "adapter_check: bridge-prepared: prepared lines by scope, 340 cases ({} errors) the "
        "plugin's answers bit for bit, timed with two figures".format(errors)
    )


def shared(a):
    if not os.access(a.adapter, os.X_OK):
        fail(a.adapter + " has no exec bit: the check would prove nothing")
    listed = run([a.exe, "list", "--no-default-plugins", "--plugin", a.adapter]).stdout
    if "test-good-but-quirky" not in listed:
        fail("list does not show the shared library's variants:\n" + listed)
    out = os.path.join(a.work, "report")
    run(
        [
            a.exe,
            "run",
            "--family",
            "random:5",
            "--variants",
            "double",
            "--no-default-plugins",
            "--plugin",
            a.adapter,
            "--no-timing",
            "--out",
            out,
            "--no-progress",
        ]
    )
    pl = plugin_of(json.load(open(os.path.join(out, "report.json"))), "test-good-but-quirky")
    if pl["kind"] != "shared-library" or pl["library"] != "":
        fail("context.plugins: {}".format(pl))
    print("adapter_check: shared: an executable .so is loaded as a shared library")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument(
        "--kind",
        required=True,
        choices=[
            "good",
            "crash",
            "hang",
            "garbage",
            "crash-once-more",
            "pipeline",
            "bridge",
            "shared",
            "prepared",
            "bridge-prepared",
            "fork-hang",
            "setsid",
        ]
        + list(TIMED_REFUSALS),
    )
    ap.add_argument("--adapter", required=True)
    ap.add_argument("--cases")
    ap.add_argument("--so", help="bridge: the shared-library plugin the bridge hosts")
    ap.add_argument("--work", required=True)
    a = ap.parse_args()
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    os.environ["TOY_STATE_DIR"] = a.work  # inherited by gjk-validate and its adapters
    {
        "good": good,
        "shared": shared,
        "crash-once-more": restart_fails,
        "bridge": bridge,
        "pipeline": pipeline,
        "prepared": prepared,
        "bridge-prepared": bridge_prepared,
        "fork-hang": tree,
        "setsid": tree,
        **{k: timed_refused for k in TIMED_REFUSALS},
    }.get(a.kind, contained)(a)


if __name__ == "__main__":
    main()
