#!/usr/bin/env python3
"""The wheel installs and stands alone (python/CMakeLists.txt; docs/python.md, "Install").

  wheel_check.py --build B --source S
      python3 -m build --wheel --no-isolation -C build-dir=B makes the wheel in B/python/wheel/
      from the module already built in B (the backend rebuilds nothing that is up to date); it is
      installed with pip, offline, into a new venv outside S and B (--system-site-packages: Debian's
      NumPy). Then, from /, with S and B out of reach, the venv's Python runs a query, the exact
      distance and gjk2d.validate(gjk2d.distance) with the default case files, and the checks:
      the package, its extension and every case file the report read are in the venv's
      site-packages; the report has a family for each shipped case file; the answers are the hand
      values (two unit squares 3 apart: 3.0 from both sides); mypy type-checks a use of the API
      against the shipped stub (an error is found where there is one).
      Out of reach: as root with `unshare -m`, an empty tmpfs mounted over B and S, as
      tests/validation/installed_check.py does; without it, only run from / (the line printed
      says which).
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

SMOKE = r"""
import json, os, sys
import gjk2d
square = [[0, 0], [1, 0], [1, 1], [0, 1]]
r = gjk2d.distance(square, square, position_b=(4, 0))
e = gjk2d.exact_distance(square, square, position_b=(4, 0))
report = gjk2d.validate(gjk2d.distance, families="random:50", default_cases=True, timing=False,
                        progress=False, out=sys.argv[1])
print(json.dumps({"package": gjk2d.__file__, "extension": gjk2d._gjk2d.__file__,
                  "cases": gjk2d._CASES, "distance": r.distance, "exact": e["distance"],
                  "inputs": [i["file"] for i in report["context"]["inputs"] if "file" in i],
                  "families": [f["name"] for f in report["families"]]}))
"""

# A use of the API that type-checks, and one that must not: DistanceResult.distance is a float in
# the stub (distance() itself is stubbed as (*args, **kwargs) -> Any: stubgen reads no signature
# from its overloads).
TYPED = """
import gjk2d
r = gjk2d.distance([[0.0, 0.0]], [[3.0, 4.0]])
def as_text(r: gjk2d.DistanceResult) -> str:
    return r.distance
"""


def fail(msg):
    print("wheel_check: FAIL: " + msg, file=sys.stderr)
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


def make_wheel(python, source, build):
    out = os.path.join(build, "python", "wheel")
    shutil.rmtree(out, ignore_errors=True)
    run(
        [
            python,
            "-m",
            "build",
            "--wheel",
            "--no-isolation",
            "-C",
            "build-dir=" + build,
            "--outdir",
            out,
            source,
        ],
        cwd=build,
    )
    wheels = glob.glob(os.path.join(out, "gjk2d-*.whl"))
    if len(wheels) != 1:
        fail("expected one wheel in {}, found {}".format(out, wheels))
    return wheels[0]


def check(result, site):
    def inside(path):
        return os.path.realpath(path).startswith(os.path.realpath(site) + os.sep)

    for key in ("package", "extension", "cases"):
        if not inside(result[key]):
            fail("{} {} is not in the venv's {}".format(key, result[key], site))
    shipped = sorted(glob.glob(os.path.join(site, "gjk2d", "cases", "*.json")))
    if not shipped:
        fail("no case files in the wheel's gjk2d/cases")
    if sorted(os.path.realpath(f) for f in result["inputs"]) != [
        os.path.realpath(f) for f in shipped
    ]:
        fail("the report's case files {} are not the wheel's {}".format(result["inputs"], shipped))
    for f in shipped:
        if "file:" + os.path.basename(f) not in result["families"]:
            fail(
                "no family file:{} in the report: {}".format(
                    os.path.basename(f), result["families"]
                )
            )
    # Unit squares [0, 1] and [4, 5] along x: 3 apart, exactly representable.
    if result["distance"] != 3.0 or result["exact"] != 3.0:
        fail(
            "distance {} and exact {}, expected 3.0 and 3.0".format(
                result["distance"], result["exact"]
            )
        )
    return len(shipped)


def check_types(venv_python, tmp):
    """mypy, run by the venv's Python, finds the wheel's stub: one error, on the `wrong` line."""
    snippet = os.path.join(tmp, "typed.py")
    with open(snippet, "w") as f:
        f.write(TYPED)
    p = subprocess.run(
        [
            venv_python,
            "-m",
            "mypy",
            "--cache-dir",
            os.path.join(tmp, "mypy-cache"),
            "--no-error-summary",
            snippet,
        ],
        capture_output=True,
        text=True,
        cwd=tmp,
    )
    errors = [line for line in p.stdout.splitlines() if ": error:" in line]
    if len(errors) != 1 or "typed.py:5:" not in errors[0] or '"float"' not in errors[0]:
        fail(
            "mypy against the stub: expected one error on line 5 (a float returned as str), "
            "got:\n" + p.stdout + p.stderr
        )


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    ap.add_argument("--source", required=True)
    ap.add_argument("--python", default=sys.executable)
    a = ap.parse_args()
    source, build = os.path.realpath(a.source), os.path.realpath(a.build)
    wheel = make_wheel(a.python, source, build)
    with tempfile.TemporaryDirectory(prefix="gjk2d-wheel-venv-") as tmp:
        venv = os.path.join(tmp, "venv")
        # No pip of its own: Debian's, through the system site-packages, installs into the venv.
        run([a.python, "-m", "venv", "--system-site-packages", "--without-pip", venv])
        python = os.path.join(venv, "bin", "python")
        env = {k: v for k, v in os.environ.items() if not k.startswith(("PYTHON", "GJK2D_"))}
        env["PYTHONDONTWRITEBYTECODE"] = "1"
        run(
            [python, "-m", "pip", "install", "--no-index", "--no-cache-dir", "--quiet", wheel],
            env=env,
            cwd="/",
        )
        site = run(
            [python, "-c", "import sysconfig; print(sysconfig.get_path('platlib'))"], env=env
        ).stdout.strip()
        cmd = [python, "-c", SMOKE, os.path.join(tmp, "report")]
        hide = can_hide()
        if hide:  # mounted over in this order: B may lie inside S (build/release)
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
        result = json.loads(run(cmd, env=env, cwd="/").stdout.splitlines()[-1])
        count = check(result, site)
        check_types(python, tmp)
    print(
        "wheel_check: {} installed in a venv; a query, the exact distance and validate with its "
        "{} case files ran from site-packages; the stub type-checks; {}".format(
            os.path.basename(wheel),
            count,
            "source and build trees hidden by tmpfs mounts (unshare -m)"
            if hide
            else "no mount namespace here: run from / only",
        )
    )


if __name__ == "__main__":
    main()
