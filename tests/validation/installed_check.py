#!/usr/bin/env python3
"""The installed gjk-validate stands alone (issue 30; tests/validation/CMakeLists.txt).

  installed_check.py --build B --source S
      cmake --install B to a temporary prefix outside S and B; then, with S and B out of reach,
      runs PREFIX/bin/gjk-validate run --default-cases --family random:50 from another working
      directory and checks its report: every case file of PREFIX/share/gjk2d/cases is an input,
      read from there, and is a family of the report; the shipped Box2D plugin ran, loaded from
      PREFIX/lib*/gjk2d/plugins; git_revision is S's revision (HEAD's 12 hex digits, as the build
      recorded it), not "unknown".
      Out of reach: as root with `unshare -m`, an empty tmpfs is mounted over S and over B in a
      private mount namespace, so that any read of either fails. Without it (not root, no
      unshare), the install is moved to a second temporary prefix after the install (so a path
      compiled in at install time is gone too) and run from /; the line printed says which.
Exit 0 when every check holds; else a message and exit 1.
"""
import argparse
import glob
import json
import os
import shutil
import subprocess
import sys
import tempfile


def fail(msg):
    print("installed_check: FAIL: " + msg, file=sys.stderr)
    sys.exit(1)


def run(cmd, **kw):
    p = subprocess.run(cmd, capture_output=True, text=True, **kw)
    if p.returncode != 0:
        fail(
            "{} exited {}\nstdout:\n{}\nstderr:\n{}".format(
                " ".join(cmd), p.returncode, p.stdout[-3000:], p.stderr[-3000:]
            )
        )
    return p


def can_hide():
    """Whether `unshare -m` can mount over a directory here (root, a kernel that allows it)."""
    if os.geteuid() != 0 or shutil.which("unshare") is None:
        return False
    probe = tempfile.mkdtemp(prefix="gjk2d-unshare-probe-")
    try:
        p = subprocess.run(
            [
                "unshare",
                "-m",
                "--propagation",
                "private",
                "sh",
                "-c",
                'mount -t tmpfs none "$0" && test ! -e "$0/x"',
                probe,
            ],
            capture_output=True,
        )
        return p.returncode == 0
    finally:
        shutil.rmtree(probe, ignore_errors=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    ap.add_argument("--source", required=True)
    a = ap.parse_args()
    source, build = os.path.realpath(a.source), os.path.realpath(a.build)
    rev = subprocess.run(
        ["git", "-C", source, "rev-parse", "--short=12", "HEAD"], capture_output=True, text=True
    )
    expected = rev.stdout.strip() if rev.returncode == 0 else "unknown"
    with tempfile.TemporaryDirectory(prefix="gjk2d-installed-") as tmp:
        prefix = os.path.join(tmp, "prefix")
        run(["cmake", "--install", build, "--prefix", prefix])
        hide = can_hide()
        if not hide:
            moved = os.path.join(tmp, "moved")
            shutil.move(prefix, moved)
            prefix = moved
        exe = os.path.join(prefix, "bin", "gjk-validate")
        out = os.path.join(tmp, "report")
        cmd = [
            exe,
            "run",
            "--default-cases",
            "--family",
            "random:50",
            "--no-timing",
            "--no-progress",
            "--out",
            out,
        ]
        if hide:
            # Mounted over in this order: B may lie inside S (build/release).
            script = 'mount -t tmpfs none "$1" && mount -t tmpfs none "$2" && shift 2 && exec "$@"'
            cmd = [
                "unshare",
                "-m",
                "--propagation",
                "private",
                "sh",
                "-c",
                script,
                "sh",
                build,
                source,
            ] + cmd
        run(cmd, cwd="/")
        report = json.load(open(os.path.join(out, "report.json")))
        cases_dir = os.path.join(prefix, "share", "gjk2d", "cases")
        installed = sorted(glob.glob(os.path.join(cases_dir, "*.json")))
        if not installed:
            fail("no case files installed in " + cases_dir)
        files = [i["file"] for i in report["context"]["inputs"] if "file" in i]
        if [os.path.realpath(f) for f in files] != [os.path.realpath(f) for f in installed]:
            fail(
                "the report's case files {} are not the installed ones {}".format(files, installed)
            )
        families = {f["name"] for f in report["families"]}
        for f in installed:
            if "file:" + os.path.basename(f) not in families:
                fail("no family file:{} in the report: {}".format(os.path.basename(f), families))
        plugins = sorted({v["plugin"]["path"] for v in report["variants"] if "plugin" in v})
        names = sorted(os.path.basename(p) for p in plugins)
        # The default campaign's peers (validation/src/implementations/peers.hpp), each from the prefix;
        # Box2D v3 is there when the build found a Box2D v3 tree (GJK2D_BOX2D3_SOURCE).
        default_peers = {"gjk2d-box2d.so", "gjk2d-bullet-float.so", "gjk2d-bullet-double.so"}
        if (
            not default_peers <= set(names)
            or not set(names) <= default_peers | {"gjk2d-box2d3.so"}
            or not all(os.path.realpath(p).startswith(os.path.realpath(prefix)) for p in plugins)
        ):
            fail(
                "expected the default campaign's shipped peers from {}: {}".format(prefix, plugins)
            )
        got = report["context"]["git_revision"]
        if got.split(" ")[0] != expected or (expected != "unknown" and got == "unknown"):
            fail(
                "git_revision '{}', expected the checkout's {} (rebuild after a commit)".format(
                    got, expected
                )
            )
        print(
            "installed_check: {} case files and the Box2D plugin read from the prefix, revision "
            "'{}'; {}".format(
                len(installed),
                got,
                "source and build trees hidden by tmpfs mounts (unshare -m)"
                if hide
                else "no mount namespace here: the install was moved, and run from /",
            )
        )


if __name__ == "__main__":
    main()
