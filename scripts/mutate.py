#!/usr/bin/env python3
"""Hand-made mutation testing of gjk2d (docs/testing.md).

Applies each mutant of scripts/mutants.json (one plausible single-line slip in gjk/, exact/ or the
runner's judgement) to a private git worktree, rebuilds only what the tests need, runs them, and
restores the file. Two stages:
  fast  the area's unit tests: gjk -> gjk_tests, exact -> exact_tests, runner -> validation_tests
  full  (mutants the fast stage left alive) every test of the release build (ctest) plus the default
        validation campaign (gjk-validate run, default families)
It prints a table, the scores and the survivors. Exit codes: 0 every non-equivalent mutant was
killed by the last stage run; 1 a non-equivalent mutant survived it, or a mutant marked equivalent
was killed (the list is wrong); 2 a bad list or a failing baseline (see the message).

The shared working tree is never modified: everything happens in a detached worktree of HEAD (by
default under /tmp), removed at the end (--keep leaves it). --uncommitted also carries the working
tree's uncommitted changes and untracked files over.

  scripts/mutate.py            fast stage on every mutant, full stage on the survivors
  scripts/mutate.py --fast     fast stage only
  scripts/mutate.py --only ID  one mutant (repeatable)
  scripts/mutate.py --list     the mutants
  scripts/mutate.py --check    check the list against HEAD (every file found, every text once), no build
  scripts/mutate.py --rev REV  the tree of another commit (for example the score before new tests)
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
MUTANTS = os.path.join(HERE, "mutants.json")

# What each area's fast stage builds and runs: (build dir, targets, test command relative to it).
FAST = {
    "gjk": ("gjk", ["gjk_tests"], ["tests/gjk_tests"]),
    "exact": ("full", ["exact_tests"], ["tests/exact/exact_tests"]),
    "runner": ("full", ["validation_tests", "gjk-validate"], ["tests/validation/validation_tests"]),
}
BUILD_DIRS = {
    "gjk": ["-DGJK2D_BUILD_VALIDATION=OFF", "-DGJK2D_BUILD_BENCHMARKS=OFF"],
    "full": ["-DGJK2D_BUILD_VALIDATION=ON", "-DGJK2D_BUILD_BENCHMARKS=OFF"],
}


def log(msg):
    print(msg, flush=True)


def run(cmd, cwd, timeout=None, quiet=True):
    """Runs cmd; returns (status, seconds, tail of output). status: 'ok', 'fail' or 'timeout'."""
    t0 = time.time()
    try:
        p = subprocess.run(
            cmd,
            cwd=cwd,
            timeout=timeout,
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            text=True,
            errors="replace",
        )
        out = p.stdout
        status = "ok" if p.returncode == 0 else "fail"
    except subprocess.TimeoutExpired as e:
        out = (
            (e.stdout or b"").decode("utf-8", "replace")
            if isinstance(e.stdout, bytes)
            else (e.stdout or "")
        )
        status = "timeout"
    if not quiet:
        sys.stdout.write(out)
    return status, time.time() - t0, "\n".join(out.splitlines()[-15:])


def load(path):
    with open(path) as f:
        data = json.load(f)
    mutants = data["mutants"]
    seen = set()
    for m in mutants:
        for key in ("id", "area", "file", "find", "replace"):
            if key not in m:
                die(f"{path}: mutant {m.get('id', '?')}: missing '{key}'")
        if m["id"] in seen:
            die(f"{path}: duplicate mutant id {m['id']}")
        if m["area"] not in FAST:
            die(f"{path}: mutant {m['id']}: unknown area {m['area']}")
        if isinstance(m["file"], str):
            m["file"] = [m["file"]]
        seen.add(m["id"])
    return mutants


def locate(m, root=None, repo=None, rev="HEAD"):
    """The mutant's file (the first candidate that exists) and its text: in the worktree root, or
    at commit rev of repo (--check)."""
    for rel in m["file"]:
        if root is not None:
            path = os.path.join(root, rel)
            if not os.path.isfile(path):
                continue
            with open(path) as f:
                text = f.read()
        else:
            p = subprocess.run(
                ["git", "show", f"{rev}:{rel}"],
                cwd=repo,
                stdout=subprocess.PIPE,
                stderr=subprocess.DEVNULL,
                text=True,
            )
            if p.returncode != 0:
                continue
            text = p.stdout
        n = text.count(m["find"])
        if n != 1:
            stale(
                f"mutant {m['id']}: the text to replace occurs {n} times in {rel} (must be exactly once)"
            )
        return rel, text
    stale(f"mutant {m['id']}: file {' or '.join(m['file'])} not found")


def stale(msg):
    die(f"{msg}: update scripts/mutants.json")


def die(msg):
    """A bad list, a bad command line or a failing baseline: exit code 2 (sys.exit with a message
    would give 1, the code of a surviving mutant)."""
    print(msg, file=sys.stderr, flush=True)
    raise SystemExit(2)


class Worktree:
    def __init__(self, repo, path, jobs):
        self.repo, self.path, self.jobs = repo, path, jobs
        self.configured = set()
        self.baseline = {}

    def configure(self, name):
        if name in self.configured:
            return
        bdir = os.path.join(self.path, "build", name)
        log(f"configure build/{name}")
        st, _, tail = run(
            ["cmake", "-S", self.path, "-B", bdir, "-DCMAKE_BUILD_TYPE=Release"] + BUILD_DIRS[name],
            self.path,
        )
        if st != "ok":
            die(f"configure of build/{name} failed:\n{tail}")
        self.configured.add(name)

    def build(self, name, targets, timeout):
        self.configure(name)
        cmd = ["cmake", "--build", os.path.join(self.path, "build", name), "-j", str(self.jobs)]
        for t in targets:
            cmd += ["--target", t]
        return run(cmd, self.path, timeout)

    def fast(self, area, timeout):
        name, targets, test = FAST[area]
        st, tb, tail = self.build(name, targets, timeout)
        if st != "ok":
            return "build-error", tb, tail
        st, tt, tail = run(test, os.path.join(self.path, "build", name), timeout)
        return ("survived" if st == "ok" else "killed"), tb + tt, tail

    def full(self, timeout):
        st, tb, tail = self.build("full", ["all"], timeout)
        if st != "ok":
            return "build-error", tb, tail
        bdir = os.path.join(self.path, "build", "full")
        st, tt, tail = run(
            ["ctest", "--test-dir", bdir, "-j", str(self.jobs), "--timeout", str(timeout)],
            bdir,
            timeout,
        )
        if st != "ok":
            return "killed", tb + tt, tail
        out = os.path.join(bdir, "mutate-campaign")
        st2, tc, tail = run(
            [
                os.path.join(bdir, "validation", "gjk-validate"),
                "run",
                "--no-progress",
                "--out",
                out,
            ],
            bdir,
            timeout,
        )
        return ("survived" if st2 == "ok" else "killed"), tb + tt + tc, tail

    def ensure_baseline(self, stage, area, timeout):
        """The unmutated tree must pass what a stage runs, or every mutant would look killed."""
        key = stage if stage == "full" else area
        if key in self.baseline:
            return
        log(f"baseline: {key} (building and running the unmutated tree)")
        st, t, tail = self.full(timeout) if stage == "full" else self.fast(area, timeout)
        if st != "survived":
            die(f"baseline {key} does not pass ({st}); fix the tree first:\n{tail}")
        log(f"baseline {key}: passes ({t:.0f} s)")
        self.baseline[key] = t


def apply_and_test(wt, m, stage, timeout):
    rel, original = locate(m, wt.path)
    path = os.path.join(wt.path, rel)
    with open(path, "w") as f:
        f.write(original.replace(m["find"], m["replace"], 1))
    try:
        if stage == "fast":
            return wt.fast(m["area"], timeout)
        return wt.full(timeout)
    finally:
        # Restored with a new modification time, so that whatever was built from the mutant is
        # rebuilt from the original.
        with open(path, "w") as f:
            f.write(original)


def main():
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("--fast", action="store_true", help="the fast stage only (unit tests)")
    ap.add_argument("--full-all", action="store_true", help="run the full stage on every mutant")
    ap.add_argument(
        "--only", action="append", default=[], metavar="ID", help="only this mutant (repeatable)"
    )
    ap.add_argument("--list", action="store_true", help="list the mutants and exit")
    ap.add_argument(
        "--check",
        action="store_true",
        help="check the list against --rev (file found, text exactly once) and exit; no build",
    )
    ap.add_argument(
        "--mutants", default=MUTANTS, help="the mutant list (default scripts/mutants.json)"
    )
    ap.add_argument(
        "--workdir", help="where to create the worktree (default: a new directory in /tmp)"
    )
    ap.add_argument("--keep", action="store_true", help="keep the worktree and its builds")
    ap.add_argument(
        "--rev",
        default="HEAD",
        help="the commit whose tree is mutated (default HEAD); the list is always this one",
    )
    ap.add_argument(
        "--uncommitted",
        action="store_true",
        help="carry the working tree's uncommitted changes and untracked files over",
    )
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    ap.add_argument(
        "--timeout-fast", type=int, default=600, help="seconds per build or test run (fast)"
    )
    ap.add_argument(
        "--timeout-full", type=int, default=3600, help="seconds per build or test run (full)"
    )
    args = ap.parse_args()
    if args.uncommitted and args.rev != "HEAD":
        die("--uncommitted carries changes against HEAD: not with --rev")

    mutants = load(args.mutants)
    if args.only:
        unknown = set(args.only) - {m["id"] for m in mutants}
        if unknown:
            die(f"unknown mutant id(s): {', '.join(sorted(unknown))}")
        mutants = [m for m in mutants if m["id"] in args.only]
    if args.list:
        for m in mutants:
            eq = f"  [equivalent: {m['equivalent']}]" if m.get("equivalent") else ""
            log(f"{m['id']:40} {m['area']:7} {m['file'][0]}{eq}")
        log(f"{len(mutants)} mutants")
        return 0

    repo = subprocess.run(
        ["git", "rev-parse", "--show-toplevel"],
        cwd=HERE,
        stdout=subprocess.PIPE,
        text=True,
        check=True,
    ).stdout.strip()
    if args.check:  # a stale entry exits 2 with its message (locate)
        for m in mutants:
            locate(m, repo=repo, rev=args.rev)
        log(
            f"{len(mutants)} mutants: every file found at {args.rev}, every text occurs exactly once"
        )
        return 0
    base = args.workdir or tempfile.mkdtemp(prefix="gjk2d-mutate-")
    wtpath = os.path.join(base, "tree")  # only this is removed at the end (and base if we made it)
    if os.path.exists(wtpath):
        die(f"{wtpath} exists: pass another --workdir")
    subprocess.run(
        ["git", "worktree", "add", "--detach", wtpath, args.rev],
        cwd=repo,
        check=True,
        stdout=subprocess.DEVNULL,
    )
    t_start = time.time()
    try:
        if args.uncommitted:
            diff = subprocess.run(
                ["git", "diff", "HEAD", "--binary"], cwd=repo, stdout=subprocess.PIPE, check=True
            ).stdout
            if diff:
                subprocess.run(
                    ["git", "apply", "--whitespace=nowarn"], cwd=wtpath, input=diff, check=True
                )
            untracked = (
                subprocess.run(
                    ["git", "ls-files", "--others", "--exclude-standard", "-z"],
                    cwd=repo,
                    stdout=subprocess.PIPE,
                    check=True,
                )
                .stdout.decode()
                .split("\0")
            )
            for rel in filter(None, untracked):
                if rel.startswith("build/"):
                    continue
                os.makedirs(os.path.dirname(os.path.join(wtpath, rel)) or wtpath, exist_ok=True)
                shutil.copy2(os.path.join(repo, rel), os.path.join(wtpath, rel))
        for m in mutants:  # a stale list fails here, before any build
            locate(m, wtpath)

        wt = Worktree(repo, wtpath, args.jobs)
        results = {m["id"]: {"fast": None, "full": None, "seconds": 0.0} for m in mutants}
        log(
            f"worktree {wtpath} ({args.rev}{' + uncommitted changes' if args.uncommitted else ''}); "
            f"{len(mutants)} mutants"
        )

        for m in mutants:
            # The baseline builds from scratch (the CGAL side takes many minutes): the long timeout.
            wt.ensure_baseline("fast", m["area"], args.timeout_full)
            st, t, tail = apply_and_test(wt, m, "fast", args.timeout_fast)
            results[m["id"]]["fast"] = st
            results[m["id"]]["seconds"] += t
            log(f"fast  {m['id']:40} {st:12} {t:6.0f} s")
            if st == "build-error":
                log(tail)

        if not args.fast:
            todo = [m for m in mutants if args.full_all or results[m["id"]]["fast"] == "survived"]
            for m in todo:
                wt.ensure_baseline("full", m["area"], args.timeout_full)
                st, t, tail = apply_and_test(wt, m, "full", args.timeout_full)
                results[m["id"]]["full"] = st
                results[m["id"]]["seconds"] += t
                log(f"full  {m['id']:40} {st:12} {t:6.0f} s")
                if st == "build-error":
                    log(tail)

        # Report.
        log("")
        log(f"{'mutant':40} {'area':7} {'fast':12} {'full':12} {'seconds':>7}")
        for m in mutants:
            r = results[m["id"]]
            eq = "  (equivalent)" if m.get("equivalent") else ""
            log(
                f"{m['id']:40} {m['area']:7} {r['fast'] or '-':12} {r['full'] or '-':12} {r['seconds']:7.0f}{eq}"
            )
        real = [m for m in mutants if not m.get("equivalent")]
        fast_killed = [m for m in real if results[m["id"]]["fast"] == "killed"]
        any_killed = [
            m for m in real if "killed" in (results[m["id"]]["fast"], results[m["id"]]["full"])
        ]
        broken = [
            m
            for m in mutants
            if "build-error" in (results[m["id"]]["fast"], results[m["id"]]["full"])
        ]
        survivors = [m for m in real if m not in any_killed and m not in broken]
        eq_killed = [
            m
            for m in mutants
            if m.get("equivalent")
            and "killed" in (results[m["id"]]["fast"], results[m["id"]]["full"])
        ]
        n = len(real)
        log("")
        log(f"non-equivalent mutants: {n}  (equivalent, not counted: {len(mutants) - n})")
        if n:
            log(
                f"killed by the fast unit tests: {len(fast_killed)} of {n} ({100 * len(fast_killed) / n:.0f} %)"
            )
            if not args.fast:
                log(
                    f"killed by the fast or the full stage: {len(any_killed)} of {n} "
                    f"({100 * len(any_killed) / n:.0f} %)"
                )
        for m in [m for m in mutants if m.get("equivalent")]:
            log(f"equivalent: {m['id']}: {m['equivalent']}")
        for m in broken:
            log(f"BUILD ERROR (fix the mutant): {m['id']}")
        for m in survivors:
            log(
                f"SURVIVOR: {m['id']} ({m['file'][0]}): {m['find'].strip()!r} -> {m['replace'].strip()!r}"
            )
        for m in eq_killed:
            log(f"MARKED EQUIVALENT BUT KILLED: {m['id']}")
        log(f"total time {time.time() - t_start:.0f} s")
        return 1 if (survivors or eq_killed or broken) else 0
    finally:
        if args.keep:
            log(f"kept {wtpath}")
        else:
            subprocess.run(["git", "worktree", "remove", "--force", wtpath], cwd=repo)
            if not args.workdir:
                shutil.rmtree(base, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
