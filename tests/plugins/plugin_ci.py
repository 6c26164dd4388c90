#!/usr/bin/env python3
"""CI steps of the plugin interface and the SDK (tests/plugins/CMakeLists.txt).

  plugin_ci.py sdk --build B --source S --work W
      cmake --install B to W/prefix; copy examples/plugin to W (nothing else of the source tree) and
      build it with find_package(gjk2d CONFIG), CMAKE_PREFIX_PATH=W/prefix only; run the installed
      gjk-validate with it; check that report.json has its two variants (and the shipped Box2D
      adapter's) in every family, with counts and ns/query, and that example-gjk gives double's
      answer on every case (cases.jsonl); build tests/plugins/sdk_consumer (every query of the
      SDK, checked against hand-derived values) with `pkg-config --cflags --libs gjk2d`, and
      with find_package, and run it; compile the old include paths and see their warnings.
  plugin_ci.py contained --exe E --plugin P --kind good-but-quirky|crash|hang --work W
      a campaign with a misbehaving test plugin: exit 0 (compared, not judged), the plugin's
      refusals, error statuses and crashes or hangs counted, every other result kept, each
      crash or hang named with its case on stderr; then with --judge: exit 1.
  plugin_ci.py tree --exe E --plugin P --work W
      P is the fork-hang test plugin: on each case where it hangs it first leaves two sleeping
      children (their PIDs in W/pids), one in its child's process group, one out of it (setsid).
      After the campaign, none of them is left (each PID gone within 2 s: killed and reaped).
  plugin_ci.py box2d --exe E --work W
      the shipped Box2D 2.4.1 adapter, named in --variants: cases of more than 256 points refused
      (its cache's 8-bit indices), every random case answered, with iterations.
  plugin_ci.py deb --build B --work W
      cpack -G DEB; dpkg-deb: package name, Depends, and the SDK's files in the package.
Exit 0 when every check holds; else a message and exit 1.
"""
import argparse
import glob
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time


def fail(msg):
    print("plugin_ci: FAIL: " + msg, file=sys.stderr)
    sys.exit(1)


def run(cmd, expect=0, **kw):
    p = subprocess.run(cmd, capture_output=True, text=True, **kw)
    if expect is not None and p.returncode != expect:
        fail(
            "{} exited {} (expected {})\nstdout:\n{}\nstderr:\n{}".format(
                " ".join(cmd), p.returncode, expect, p.stdout[-4000:], p.stderr[-4000:]
            )
        )
    return p


def fresh(path):
    shutil.rmtree(path, ignore_errors=True)
    os.makedirs(path)


def variant_stats(report, name):
    """family -> the variant's stats, for every family."""
    out = {}
    for f in report["families"]:
        if name not in f["variants"]:
            fail("family {} has no variant {}".format(f["name"], name))
        out[f["name"]] = f["variants"][name]
    return out


def same_answers(cases_jsonl, name, ref_name):
    """Fails unless variant `name` gives `ref_name`'s answer on every case; returns the count.
    The answer is what a plugin returns (gjk2d/plugin.h, gjk2d_result_d): the distance, the witness
    points and the iteration count. A plugin's normal is the runner's, from its witness points, and
    its stop reason is "plugin": neither is the plugin's to match."""
    compared = 0
    with open(cases_jsonl) as f:
        for line in f:
            c = json.loads(line)
            if "rejected" in c:
                fail("{}: case {} rejected: {}".format(cases_jsonl, c["name"], c["rejected"]))
            mine, ref = c["variants"][name], c["variants"][ref_name]
            for key in ("distance", "pointA", "pointB", "iterations"):
                if key not in ref or mine.get(key) != ref[key]:
                    fail(
                        "{} differs from {} on {}: {} {} against {}".format(
                            name, ref_name, c["name"], key, mine.get(key), ref.get(key)
                        )
                    )
            compared += 1
    return compared


def sdk(a):
    fresh(a.work)
    prefix = os.path.join(a.work, "prefix")
    run(["cmake", "--install", a.build, "--prefix", prefix])
    src = os.path.join(a.work, "example-plugin")
    shutil.copytree(os.path.join(a.source, "examples", "plugin"), src)
    build = os.path.join(a.work, "example-build")
    env = dict(os.environ)
    env.pop("CMAKE_PREFIX_PATH", None)
    run(
        [
            "cmake",
            "-S",
            src,
            "-B",
            build,
            "-DCMAKE_PREFIX_PATH=" + prefix,
            "-DCMAKE_BUILD_TYPE=Release",
        ],
        env=env,
    )
    run(["cmake", "--build", build], env=env)
    plugin = os.path.join(build, "example_gjk_plugin.so")
    out = os.path.join(a.work, "report")
    p = run(
        [
            os.path.join(prefix, "bin", "gjk-validate"),
            "run",
            "--family",
            "random:300",
            "--family",
            "hard/sliver:20",
            "--plugin",
            plugin,
            "--passes",
            "1",
            "--out",
            out,
            "--no-progress",
            "--per-case",
        ]
    )
    report = json.load(open(os.path.join(out, "report.json")))
    names = [v["name"] for v in report["variants"]]
    for name in ["example-gjk", "example-naive-f32", "box2d-2.4.1"]:
        if name not in names:
            fail("report.json variants {} lack {}".format(names, name))
        v = [v for v in report["variants"] if v["name"] == name][0]
        if v["judged"] or "plugin" not in v:
            fail("{}: expected a comparison variant with a 'plugin' block: {}".format(name, v))
        for fam, st in variant_stats(report, name).items():
            if st["cases"] == 0 or not isinstance(st["ns_per_query"], (int, float)):
                fail("{} in {}: no cases or no ns/query: {}".format(name, fam, st))
    # example-gjk is gjk2d's reference double behind the ABI: the same answers as `double`, case by
    # case and bit for bit (cases.jsonl: JSON numbers round-trip doubles).
    compared = same_answers(os.path.join(out, "cases.jsonl"), "example-gjk", "double")
    if compared != 320:
        fail(
            "cases.jsonl compared {} cases, expected 320 (random:300, hard/sliver:20)".format(
                compared
            )
        )
    # A user's program (tests/plugins/sdk_consumer/): the plain, certified and correctly rounded
    # queries, the batch in SIMD lanes and the exact side, through the installed headers
    # (gjk2d/...) and libraries, each checked against hand-derived values. Built out of tree twice:
    # from gjk2d.pc alone, and with find_package (the link dependencies come with the targets).
    consumer_src = os.path.join(a.source, "tests", "plugins", "sdk_consumer")
    env["PKG_CONFIG_PATH"] = os.path.join(prefix, "lib", "pkgconfig")
    flags = run(["pkg-config", "--cflags", "--libs", "gjk2d"], env=env).stdout.split()
    exe = os.path.join(a.work, "sdk_consumer")
    run(["c++", "-std=c++20", os.path.join(consumer_src, "sdk_consumer.cpp"), "-o", exe] + flags)
    checked = run([exe]).stdout
    cm = os.path.join(a.work, "sdk-consumer-cmake")
    shutil.copytree(consumer_src, cm)
    run(
        ["cmake", "-S", cm, "-B", os.path.join(cm, "build"), "-DCMAKE_PREFIX_PATH=" + prefix],
        env=env,
    )
    run(["cmake", "--build", os.path.join(cm, "build")], env=env)
    run([os.path.join(cm, "build", "sdk_consumer")])
    # The old include paths still compile for one release, and say which path replaces them.
    old = os.path.join(a.work, "old_paths.cpp")
    open(old, "w").write("#include <gjk/distance.hpp>\n#include <exact/exact.hpp>\nint main() {}\n")
    p = run(["c++", "-std=c++20", "-c", old, "-o", os.path.join(a.work, "old_paths.o")] + flags)
    for path, new_path in [
        ("gjk/distance.hpp", "gjk2d/distance.hpp"),
        ("exact/exact.hpp", "gjk2d/exact.hpp"),
    ]:
        warning = "<{}> is deprecated: include <{}>".format(path, new_path)
        if warning not in p.stderr:
            fail("compiling <{}> gave no warning '{}':\n{}".format(path, warning, p.stderr))
    print(
        "plugin_ci: sdk: installed, example plugin built out of tree, variants {} in report.json; "
        "tests/plugins/sdk_consumer linked through pkg-config and find_package, {}; the old "
        "include paths warn".format(names[-3:], checked.strip().splitlines()[-1])
    )


def generated(exe, family, work):
    """The cases of a built-in family, as `exe generate` writes them."""
    path = os.path.join(work, "cases.json")
    run([exe, "generate", "--family", family, "--out", path])
    return json.load(open(path))["cases"]


def contained(a):
    fresh(a.work)
    name = "test-" + a.kind
    out = os.path.join(a.work, "report")
    # Two children answer a chunk of 128 tasks or more, one each half (PluginServers): a crash
    # must be found in either. A hang costs its timeout (twice in a block): fewer cases there.
    count = 80 if a.kind == "hang" else 400
    cmd = [
        a.exe,
        "run",
        "--family",
        "random:{}".format(count),
        "--variants",
        "double",
        "--no-default-plugins",
        "--threads",
        "2",
        # A hang costs its timeout; a crash must be told apart from a hang even in a slow
        # (sanitized) build.
        "--plugin",
        a.plugin,
        "--plugin-timeout",
        "0.3" if a.kind == "hang" else "10",
        "--passes",
        "1",
        "--out",
        out,
        "--no-progress",
    ]
    p = run(cmd)
    report = json.load(open(os.path.join(out, "report.json")))
    st = variant_stats(report, name)["random"]
    dbl = variant_stats(report, "double")["random"]
    if dbl["cases"] != count:
        fail("double ran {} of {} cases".format(dbl["cases"], count))
    if st["refused"] == 0 or st["plugin_errors"] == 0:
        fail("expected refusals and error statuses: {}".format(st))
    incident = {"crash": "crashed", "hang": "hung"}.get(a.kind)
    if incident:
        if st[incident] == 0:
            fail("no case counted as {}: {}".format(incident, st))
        lines = [l for l in p.stderr.splitlines() if "plugin variant '{}'".format(name) in l]
        if len(lines) != st[incident] or not all(" on case 'random" in l for l in lines):
            fail(
                "expected {} stderr lines naming the case, got:\n{}".format(st[incident], p.stderr)
            )
        # The plugin crashes or hangs exactly where (countA + countB) % 5 == 0 (test_plugin.cpp):
        # each such case, and no other, is named, however the child's answers cross the pipe
        # (in blocks: a lost block is answered again one case at a time to find the case).
        named = sorted(re.search(r" on case '([^']+)'", l).group(1) for l in lines)
        expected = sorted(
            c["name"]
            for c in generated(a.exe, "random:{}".format(count), a.work)
            if (len(c["a"]["points"]) + len(c["b"]["points"])) % 5 == 0
        )
        if named != expected:
            fail("the {} cases named {}, expected {}".format(incident, named, expected))
        ok = st["cases"] - st[incident] - st["plugin_errors"]
        if ok <= 0:
            fail("no case answered after the {}: {}".format(incident, st))
    if st["refused"] + st["cases"] != count:
        fail("refused + cases != {}: {}".format(count, st))
    if st["failures"] != st["plugin_errors"] + st["crashed"] + st["hung"]:
        fail("failures are not the error statuses, crashes and hangs: {}".format(st))
    if report["exit_code"] != 0:
        fail("a comparison plugin decided the exit code")
    # Judged on request: the error statuses (and crashes, hangs) fail the campaign.
    run(cmd + ["--judge", name, "--no-timing"], expect=1)
    print(
        "plugin_ci: {}: {} cases, {} refused, {} error statuses, {} crashed, {} hung; "
        "double's {} cases kept".format(
            a.kind,
            st["cases"],
            st["refused"],
            st["plugin_errors"],
            st["crashed"],
            st["hung"],
            count,
        )
    )


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
    fresh(a.work)
    pids_file = os.path.join(a.work, "pids")
    env = dict(os.environ, GJK2D_TEST_PIDS=pids_file)
    run(
        [
            a.exe,
            "run",
            "--family",
            "random:40",
            "--variants",
            "double",
            "--no-default-plugins",
            "--threads",
            "2",
            "--plugin",
            a.plugin,
            "--plugin-timeout",
            "0.3",
            "--no-timing",
            "--out",
            os.path.join(a.work, "report"),
            "--no-progress",
        ],
        env=env,
    )
    pids = [int(l) for l in open(pids_file)] if os.path.exists(pids_file) else []
    left = [pid for pid in pids if not gone(pid, 2)]
    for pid in left:  # the check fails; nothing of it outlives it either
        os.kill(pid, signal.SIGKILL)
    if left:
        fail("children of the plugin outlived gjk-validate: {} of {}".format(left, pids))
    if not pids:
        fail("the plugin hung on no case: nothing was checked")
    print("plugin_ci: tree: the plugin's {} children ended with gjk-validate".format(len(pids)))


def box2d(a):
    fresh(a.work)
    out = os.path.join(a.work, "report")
    run(
        [
            a.exe,
            "run",
            "--family",
            "random:100",
            "--family",
            "hard/many-vertices:3",
            "--variants",
            "float,box2d-2.4.1",
            "--no-timing",
            "--out",
            out,
            "--no-progress",
        ]
    )
    report = json.load(open(os.path.join(out, "report.json")))
    st = variant_stats(report, "box2d-2.4.1")
    many = st["hard/many-vertices"]
    if many["refused"] != 3 or many["cases"] != 0:
        fail("hard/many-vertices (1000 to 4096 points): expected 3 refused: {}".format(many))
    rnd = st["random"]
    if rnd["cases"] != 100 or rnd["refused"] != 0 or rnd["iterations"]["max"] < 1:
        fail("random: expected 100 answered cases with iteration counts: {}".format(rnd))
    if rnd["nonfinite"] != 0:
        fail("random: Box2D gave non-finite answers on ordinary shapes: {}".format(rnd))
    print(
        "plugin_ci: box2d: 3 many-vertex cases refused, 100 random cases answered "
        "(max error/bound {})".format(rnd["errors"]["bound_ratio"]["max"])
    )


def python_files(build):
    """The Python package's files in the .deb, when the build has it (GJK2D_BUILD_PYTHON)."""
    if not os.path.exists(os.path.join(build, "python", "gjk2d", "__init__.py")):
        return []
    return ["./usr/lib/python3/dist-packages/gjk2d/__init__.py"] + [
        "./usr/lib/python3/dist-packages/gjk2d/" + os.path.basename(so)
        for so in glob.glob(os.path.join(build, "python", "gjk2d", "_gjk2d*.so"))
    ]


def deb(a):
    fresh(a.work)
    run(
        [
            "cpack",
            "-G",
            "DEB",
            "--config",
            os.path.join(a.build, "CPackConfig.cmake"),
            "-B",
            a.work,
        ],
        cwd=a.build,
    )
    debs = glob.glob(os.path.join(a.work, "gjk2d_*.deb"))
    if len(debs) != 1:
        fail("expected one gjk2d_*.deb in {}: {}".format(a.work, os.listdir(a.work)))
    fields = run(["dpkg-deb", "-f", debs[0], "Package", "Depends"]).stdout
    if "Package: gjk2d" not in fields:
        fail("package name: " + fields)
    for dep in ["libbox2d2", "libgmp-dev", "libmpfr-dev", "libc6"]:
        if dep not in fields:
            fail("Depends lacks {}: {}".format(dep, fields))
    files = run(["dpkg-deb", "-c", debs[0]]).stdout
    for path in [
        "./usr/bin/gjk-validate",
        "./usr/include/gjk2d/plugin.h",
        "./usr/include/gjk2d/distance.hpp",
        "./usr/include/gjk2d/batch.hpp",
        "./usr/include/gjk2d/exact.hpp",
        "./usr/include/gjk/distance.hpp",
        "./usr/include/exact/exact.hpp",
        "./usr/lib/libgjk2d_batch.a",
        "./usr/lib/libgjk2d_exact.a",
        "./usr/lib/cmake/gjk2d/gjk2d-config.cmake",
        "./usr/lib/pkgconfig/gjk2d.pc",
        "./usr/lib/gjk2d/plugins/gjk2d-box2d.so",
        "./usr/share/gjk2d/cases/talk.json",
    ] + python_files(a.build):
        if path not in files:
            fail("{} is not in the package:\n{}".format(path, files))
    print("plugin_ci: deb: {}\n{}".format(os.path.basename(debs[0]), fields.strip()))


def main():
    ap = argparse.ArgumentParser()
    sub = ap.add_subparsers(dest="step", required=True)
    s = sub.add_parser("sdk")
    s.add_argument("--build", required=True)
    s.add_argument("--source", required=True)
    s.add_argument("--work", required=True)
    c = sub.add_parser("contained")
    c.add_argument("--exe", required=True)
    c.add_argument("--plugin", required=True)
    c.add_argument("--kind", required=True, choices=["good-but-quirky", "crash", "hang"])
    c.add_argument("--work", required=True)
    t = sub.add_parser("tree")
    t.add_argument("--exe", required=True)
    t.add_argument("--plugin", required=True)
    t.add_argument("--work", required=True)
    b = sub.add_parser("box2d")
    b.add_argument("--exe", required=True)
    b.add_argument("--work", required=True)
    d = sub.add_parser("deb")
    d.add_argument("--build", required=True)
    d.add_argument("--work", required=True)
    a = ap.parse_args()
    {"sdk": sdk, "contained": contained, "tree": tree, "box2d": box2d, "deb": deb}[a.step](a)


if __name__ == "__main__":
    main()
