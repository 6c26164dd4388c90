#!/usr/bin/env python3
"""Every command in README.md and docs/*.md runs as written, in document order.

What counts as a command:
  - every line of a ```sh block (a trailing backslash joins the next line; `# ...` comments are
    dropped; a comment `# exits N` states the expected exit code, 0 otherwise);
  - every `$ ` line of a ```console block (the lines after it are its output, not checked);
  - every inline `code` span that starts with `gjk-validate <subcommand>` followed by options.
A command with a placeholder (<...>, [...], A|B, or a name such as FILE, CASE or N) is a
synopsis: its options must exist in that subcommand's --help, nothing is run. A command that a doc
repeats runs once; so does a `gjk-validate run` that differs from one above only in --threads.

Where commands run:
  - In one scratch directory that links every top-level entry of the repository, with
    `build/release` linked to the build under test and that build's validation/ on PATH (so both
    `build/release/validation/gjk-validate` and `gjk-validate` work, and count as one command;
    so do `scripts/run.sh ARGS` and `gjk-validate run ARGS`, since the script sets up, builds and
    then runs exactly that); the files a command writes (hard.json, ...) stay there, so later
    commands can read them. reports/ there is the scratch directory's own: the repository's
    reports/latest/ (the default campaign of a person's `scripts/run.sh`) is never written (a docs
    command's small report would replace a person's default campaign). Docs run in the order
    README.md, then docs/ by name.
  - `scripts/*.sh` and `cmake --preset`/`--build --preset` change to the repository root
    themselves; they run there, against the build under test (only when it is build/release).
    `scripts/run.sh ARGS` without `--out` runs with `--out SCRATCH/reports/latest` added, so that
    its report lands where the next commands read `reports/latest/` and not in the repository.

A command that needs an optional part of the build (OPTIONAL below: the Box2D v3 adapter, built
only from Box2D v3 sources the user supplies) must say so beside it, with the part's phrase ("needs
the Box2D v3 sources") in its `# ...` comment (a block's command) or in its paragraph (an inline
span); an unmarked one is an error. Where the part is built the command runs; where it is not, it
is skipped, and each skip is printed first, as a line `skipped: DOC:LINE: REASON: COMMAND`
(scripts/test.sh's summary collects these lines: docs/testing.md, "Skips").

Some commands are not run as written; RULES below lists each with its reason:
  - "ci": CI itself runs it (the README's test command, scripts/fuzz.sh, the flag matrix);
  - "shrink": a long run (minutes to hours) runs with a smaller budget (every matching shrink
    rule applies); the rest of the command is as written, so every option and path is still
    checked;
  - "long": not run (a campaign of its own, e.g. the full mutation run); its options are checked.
--full runs the "shrink" commands as written (hours), for a person on a quiet machine.

Also checked: every relative link of the docs names a file or folder that exists, and the release
preset's displayName states the optimisation flag the build really uses.

Exit codes: 0 every command ran with its expected exit code, 1 some did not, 2 bad usage.
"""
import argparse
import os
import pathlib
import re
import shlex
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
DOCS = [ROOT / "README.md"] + sorted((ROOT / "docs").glob("*.md"))

# (pattern on the command, disposition, replacement or None, reason). First match wins.
RULES = [
    (r"^scripts/test\.sh\b", "ci", None, "the README's test command: .ci/run runs it"),
    (r"^ctest --preset", "ci", None, "scripts/test.sh runs it"),
    (r"(^|\s)scripts/fuzz\.sh\b", "ci", None, "scripts/test.sh runs `scripts/fuzz.sh 30`"),
    (
        r"^cmake -S \. -B build/h20|^ctest --test-dir build/h20|^tests/consumer/flag_table\.sh",
        "ci",
        None,
        "the flag matrix: the release build's `ctest -L flags` runs it",
    ),
    (
        r"^scripts/bench\.sh\b",
        "long",
        None,
        "builds and runs every benchmark (minutes); speed.md's next commands run its parts",
    ),
    (
        r"^python3 scripts/adapter_timing_check\.py\b",
        "long",
        None,
        "a timing comparison whose verdict depends on the machine's load",
    ),
    (
        r"^scripts/mutate\.py( --fast)?\s*$|^scripts/mutate\.py --(rev|only)\b",
        "long",
        None,
        "the mutation run builds and tests every mutant (tens of minutes)",
    ),
    (
        r"^valgrind --tool=callgrind\b",
        "shrink",
        (r"random:\d+", "random:200"),
        "callgrind runs the campaign some 50 times slower",
    ),
    (
        r"GJK2D_TRUTH_RANDOM_COUNT=\d{6,}",
        "shrink",
        (r"GJK2D_TRUTH_RANDOM_COUNT=\d+", "GJK2D_TRUTH_RANDOM_COUNT=20000"),
        "1e6 cases both ways",
    ),
    (r"--seconds \d+", "shrink", ("--seconds \\d+", "--seconds 2"), "search runs 600 s"),
    # Not repro or explain: they name one case of the family, which a smaller one may not hold.
    (
        r"^(?!.*gjk-validate (repro|explain)\b).*random:\d{6,}",
        "shrink",
        (r"random:\d{6,}", "random:3000"),
        "1e5 to 1e7 cases",
    ),
    (
        r"random:\d{5}\b.*--per-case",
        "shrink",
        (r"random:\d{5}\b", "random:3000"),
        "every variant's answer of 1e4 to 1e5 cases written to cases.jsonl",
    ),
    (
        r"gjk-validate run --peers\b(?!.*--no-timing)(?!.*--passes)",
        "shrink",
        (r"$", " --passes 2"),
        "the peers' timing phase: 15 passes of eight peers, 80 of the run's 90 s",
    ),
    (
        r"python/examples/numpy_gjk\.py --out \S+$",
        "shrink",
        (r"$", " --random 300 --hard 10 --engine 30 --passes 1"),
        "docs/python.md's worked example: two campaigns of a GJK in NumPy, 40 s",
    ),
    (
        r"pip install --no-build-isolation \.$",
        "shrink",
        (r"$", " --config-settings build-dir=build/release"),
        "the wheel's backend would build the module from scratch: the build under test's is packed",
    ),
    (
        r"-m build --wheel --no-isolation\b",
        "shrink",
        (r"$", " -C build-dir=build/release"),
        "the wheel's backend would build the module from scratch: the build under test's is packed",
    ),
    (
        r"--benchmark_min_time=(0\.\d*[1-9]\d*[0-9]|0\.[0-9][1-9]|0\.[1-9]|[1-9])",
        "shrink",
        (r"--benchmark_min_time=[0-9.]+", "--benchmark_min_time=0.001"),
        "each Google Benchmark program runs for minutes",
    ),
]

# The optional parts a documented command may need: (name, pattern on the command, the phrase that
# marks it in the doc, the file of the build that is there when the part is built, how to get it).
# A user's clone has no Box2D v3 sources (they are in no Debian package): README.md, "Box2D v3".
OPTIONAL = [
    (
        "box2d-v3",
        r"--against box2d-v3\b|gjk2d-box2d3\.so|\bbox2d-3-[0-9a-f]{6,}\b",
        "needs the Box2D v3 sources",
        "validation/plugins/gjk2d-box2d3.so",
        'name a Box2D v3 source tree in GJK2D_BOX2D3_SOURCE (README.md, "Box2D v3")',
    ),
]

SUBCOMMANDS = ["run", "generate", "explain", "bench", "search", "list", "compare", "merge", "repro"]
# A placeholder: <...>, [...], A|B, "...", or one of the upper-case names the docs use for one.
PLACEHOLDER = re.compile(
    r"<[^>]*>|\[[^\]]*\]|\w\|\w|\.\.\.|\b(FILE|CASE|OUT|NAME|REV|ID|DIR|SPEC|N|"
    r"SECONDS\w*|TARGET\w*|[A-Z]+_[A-Z_]+)\b"
)
COMMAND_WORD = re.compile(r"^(gjk-validate|build/|scripts/|cmake|ctest|python3)\b")
# A fence opens or closes a code block: three or more backticks, an info string without backticks
# (CommonMark; "```` ```sh ```` block" is inline code, not a fence).
FENCE = re.compile(r"^(```+)([^`]*)$")
LINK = re.compile(r"\]\(([^)#\s]+)(#[^)]*)?\)")


def fenced_commands(path):
    """[(line, command, expected exit, its marks)] of the sh and console blocks of one doc; the
    marks are the text of the command's `# ...` comment."""
    out = []
    lang, pending, start = None, "", 0
    for no, line in enumerate(path.read_text().splitlines(), 1):
        fence = FENCE.match(line)
        if fence:
            lang = None if lang is not None else fence.group(2).strip()
            continue
        if lang == "console":
            if line.startswith("$ "):
                out.append((no, line[2:].strip(), 0, ""))
            continue
        if lang != "sh":
            continue
        if not pending:
            start = no
        pending += line.rstrip()
        if pending.endswith("\\"):
            pending = pending[:-1] + " "
            continue
        text, pending = pending, ""
        expect = re.search(r"#\s*exits (\d+)", text)
        comment = re.search(r"(^|\s)#(.*)$", text)
        command = re.sub(r"(^|\s)#.*$", "", text).strip()
        if command:
            out.append(
                (
                    start,
                    re.sub(r"\s+", " ", command),
                    int(expect.group(1)) if expect else 0,
                    comment.group(2) if comment else "",
                )
            )
    return out


def inline_commands(path):
    """[(line, span, 0, its paragraph)] of the inline `gjk-validate SUB ...` spans that have options
    (also `build/release/validation/gjk-validate ...`); a span may wrap across the lines of a
    paragraph, whose text is the span's marks."""
    out, fenced, para, start = [], False, [], 0

    def flush():
        for span in re.findall(r"`([^`]+)`", " ".join(para)):
            words = re.sub(r"^build/release/validation/", "", span.strip()).split()
            if len(words) > 2 and words[0] == "gjk-validate" and words[1] in SUBCOMMANDS:
                out.append((start, re.sub(r"\s+", " ", span.strip()), 0, " ".join(para)))

    for no, line in enumerate(path.read_text().splitlines(), 1):
        if FENCE.match(line):
            flush()
            para, fenced = [], not fenced
            continue
        if fenced:
            continue
        if not line.strip():
            flush()
            para = []
            continue
        if not para:
            start = no
        para.append(line.strip())
    flush()
    return out


def disposition(command, full):
    if PLACEHOLDER.search(re.sub(r"'[^']*'|\"[^\"]*\"", "''", command)):  # quoted text is literal
        for pattern, kind, _, reason in RULES:
            if kind in ("ci", "long") and re.search(pattern, command):
                return kind, command, reason
        return "synopsis", command, "has a placeholder: options checked"
    shrunk, reasons = command, []  # every shrink rule that matches applies, in RULES' order
    for pattern, kind, replacement, reason in RULES:
        if re.search(pattern, shrunk):
            if kind != "shrink":
                return kind, command, reason
            shrunk = re.sub(replacement[0], replacement[1], shrunk)
            reasons.append(reason)
    if not reasons:
        return "run", command, ""
    return ("run", command, reasons[0]) if full else ("shrink", shrunk, "; ".join(reasons))


def help_options(exe, cache={}):
    """subcommand -> the set of its long and short options, from `gjk-validate SUB --help`."""
    if not cache:
        for sub in SUBCOMMANDS:
            text = subprocess.run([exe, sub, "--help"], capture_output=True, text=True).stdout
            cache[sub] = set(re.findall(r"(?<![\w-])(--?[A-Za-z][\w-]*)", text))
    return cache


def unknown_options(command, exe):
    """The options of a `gjk-validate SUB ...` command that SUB's --help does not list."""
    words = re.sub(r"^build/release/validation/", "", command).split()
    if len(words) < 2 or words[0] != "gjk-validate" or words[1] not in SUBCOMMANDS:
        return []
    known = help_options(exe)[words[1]]
    options = [w.split("=")[0] for w in words[2:] if re.match(r"^--?[A-Za-z]", w)]
    return [o for o in options if o not in known and o not in ("--help", "-h")]


def scratch_dir(build):
    d = pathlib.Path(tempfile.mkdtemp(prefix="gjk2d-doc-commands-"))
    for entry in ROOT.iterdir():
        if entry.name not in ("build", ".git", "reports"):
            (d / entry.name).symlink_to(entry)
    (d / "reports").mkdir()  # its own: the repository's reports/ is a person's
    (d / "build").mkdir()
    (d / "build" / "release").symlink_to(build)
    if (ROOT / "build" / "npm").is_dir():  # the JavaScript peers' packages (scripts/setup_npm.sh)
        (d / "build" / "npm").symlink_to(ROOT / "build" / "npm")
    return d


def repository_latest():
    """The repository's reports/latest/report.json as it is (None when there is none): a person's
    `scripts/run.sh` report, which no documented command may replace."""
    f = ROOT / "reports" / "latest" / "report.json"
    try:
        return f.read_bytes()
    except OSError:
        return None


def runs_in_root(command):
    return re.match(r"^(scripts/\w+\.sh|cmake (--preset|--build --preset))", command) is not None


def check_links(errors):
    """Relative links name files that exist; no command hides in an indented code block."""
    for path in DOCS:
        fenced = False
        for no, line in enumerate(path.read_text().splitlines(), 1):
            fenced = fenced != bool(FENCE.match(line))
            if not fenced and line.startswith("    ") and COMMAND_WORD.match(line.strip()):
                errors.append(
                    f"{path.relative_to(ROOT)}:{no}: a command in an indented block: "
                    "put it in a ```sh block, where it is run"
                )
            for target, _ in LINK.findall(line):
                if re.match(r"^[a-z]+:", target):
                    continue
                if not (path.parent / target).exists():
                    errors.append(
                        f"{path.relative_to(ROOT)}:{no}: link to '{target}', which is not "
                        "in the repository"
                    )


def check_presets(build, errors):
    """The release preset's displayName names the -O level that CMAKE_CXX_FLAGS_RELEASE has."""
    import json

    presets = json.loads((ROOT / "CMakePresets.json").read_text())["configurePresets"]
    release = next(p for p in presets if p["name"] == "release")
    cache = (build / "CMakeCache.txt").read_text()
    flags = re.search(r"^CMAKE_CXX_FLAGS_RELEASE:STRING=(.*)$", cache, re.M).group(1)
    said = re.findall(r"-O\d", release["displayName"])
    real = re.findall(r"-O\d", flags)
    if said != real[-1:]:
        errors.append(
            f"CMakePresets.json: release displayName says {said}, the build uses "
            f"{real[-1:]} ({flags})"
        )


def lacking_part(rel, no, command, marks, build, errors):
    """Why `command` is skipped: an optional part (OPTIONAL) it needs that this build lacks, or
    None. One it needs that its doc does not mark is an error, built or not."""
    reason = None
    for name, pattern, phrase, built, how in OPTIONAL:
        if not re.search(pattern, command):
            continue
        if phrase.lower() not in re.sub(r"\s+", " ", marks).lower():
            errors.append(
                f"{rel}:{no}: `{command}` needs an optional part ({name}): say "
                f'"{phrase}" beside it (its # comment, or its paragraph)'
            )
        if not (build / built).exists():
            reason = f"{phrase}, not given to this build: {how}"
    return reason


def plan(args, build, exe, errors, counts):
    """[(doc, line, kind, command as run, reason, expected exit)] of every documented command, in
    document order: what is done with each (disposition, a repeat, a lacking optional part), its
    options checked against its subcommand's --help."""
    in_release = build == (ROOT / "build" / "release").resolve()
    out, done = [], set()
    for path in DOCS:
        rel = str(path.relative_to(ROOT))
        if args.only and rel not in args.only:
            continue
        for no, command, expect, marks in sorted(fenced_commands(path) + inline_commands(path)):
            kind, shown, reason = disposition(command, args.full)
            if runs_in_root(command) and not in_release and kind in ("run", "shrink"):
                kind, reason = "ci", "changes to the repository root: checked in build/release only"
            key = re.sub(r"^build/release/validation/gjk-validate\b", "gjk-validate", shown)
            key = re.sub(r"^scripts/run\.sh\b", "gjk-validate run", key)  # set-up, build, then this
            if key.startswith("gjk-validate run "):  # its report is the same on any thread count
                key = re.sub(r" --threads \d+\b", "", key)
            lacking = lacking_part(rel, no, command, marks, build, errors)
            if kind in ("run", "shrink") and lacking:
                kind, reason = "skipped", lacking
            elif kind in ("run", "shrink") and key in done:
                kind, reason = "repeat", "ran above"
            elif kind in ("run", "shrink"):
                done.add(key)
            counts[kind] += 1
            for o in unknown_options(command, exe):
                errors.append(f"{rel}:{no}: {command}: {o} is not an option of that subcommand")
            out.append((rel, no, kind, shown, reason, expect))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", required=True, help="the build under test (build/release)")
    ap.add_argument("--list", action="store_true", help="list the commands and what is done")
    ap.add_argument("--full", action="store_true", help="run the shrunk commands as written")
    ap.add_argument("--only", action="append", default=[], help="only this doc (repeatable)")
    args = ap.parse_args()
    build = pathlib.Path(args.build).resolve()
    exe = build / "validation" / "gjk-validate"
    if not exe.exists():
        print(f"check_doc_commands: no {exe}: build gjk-validate first", file=sys.stderr)
        return 2
    # OpenMPI refuses to run as root (CI, containers) unless told twice (docs/cli.md, "Shards, merge, MPI, resume").
    env = dict(
        os.environ,
        PATH=f"{build / 'validation'}:{os.environ['PATH']}",
        OMPI_ALLOW_RUN_AS_ROOT="1",
        OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
    )
    errors = []
    counts = {"run": 0, "shrink": 0, "ci": 0, "long": 0, "synopsis": 0, "repeat": 0, "skipped": 0}
    latest_before = repository_latest()
    check_links(errors)
    check_presets(build, errors)
    commands = plan(args, build, exe, errors, counts)
    # The skips first: CTest keeps only the head of a passing test's output (1,024 bytes) unless
    # told otherwise (scripts/test.sh does: --test-output-size-passed).
    for rel, no, kind, shown, reason, _ in commands:
        if kind == "skipped":
            print(f"skipped: {rel}:{no}: {reason}: {shown}", flush=True)
    work = None
    for rel, no, kind, shown, reason, expect in commands:
        if args.list or kind not in ("run", "shrink"):
            if kind != "skipped":
                print(f"{rel}:{no}: {kind}{' (' + reason + ')' if reason else ''}: {shown}")
            continue
        if work is None:
            work = scratch_dir(build)
        cwd = ROOT if runs_in_root(shown) else work
        if re.match(r"^scripts/run\.sh\b", shown) and "--out" not in shown.split():
            shown += " --out " + shlex.quote(str(work / "reports" / "latest"))
        t0 = time.monotonic()
        r = subprocess.run(["bash", "-c", shown], cwd=cwd, env=env, capture_output=True, text=True)
        took = time.monotonic() - t0
        status = "ok" if r.returncode == expect else "FAILED"
        print(f"{rel}:{no}: {status} in {took:.1f} s (exit {r.returncode}): {shown}", flush=True)
        if r.returncode != expect:
            tail = "\n".join((r.stdout + r.stderr).strip().splitlines()[-8:])
            errors.append(
                f"{rel}:{no}: `{shown}` exited {r.returncode}, expected {expect}:\n" f"{tail}"
            )
    print(
        "commands: {run} run as written, {shrink} shrunk, {ci} run by CI elsewhere, {long} not "
        "run (long), {synopsis} synopses option-checked, {repeat} repeats, {skipped} skipped "
        "(an optional part not built)".format(**counts)
    )
    if repository_latest() != latest_before:
        errors.append(
            "a documented command replaced the repository's reports/latest/ (a "
            "person's default campaign): commands must write in the scratch directory"
        )
    if errors:
        print("\n".join(errors), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
