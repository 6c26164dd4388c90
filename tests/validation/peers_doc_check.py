#!/usr/bin/env python3
"""CTest "docs: peers.md generator runs on a small campaign": scripts/peers_doc.py on a tiny
campaign, into a temporary document seeded with hand-written text around the markers. Checks:
the overview has a contract row and a verdict row for every variant of every plugin the report's
context lists, each linking its page (peers/<peer>.md); the pages have a table row per family
group, its largest and p99 errors those of the report (one family per group here), and an SVG per
plugin variant; the title, and the hand-written text kept byte for byte (the overview's, and a
page's). Each
worst case's command loads every plugin the README's first command builds, and an optional one
(the Box2D v3 adapter, check_doc_commands.OPTIONAL) only in its own variant's paragraph, which says
what it needs. The default campaign the script runs without options is the one `gjk-validate list`
names. Writes only under a temporary directory."""
import argparse
import json
import pathlib
import re
import subprocess
import sys
import tempfile

BEGIN, END = "<!-- peers_doc.py: begin -->", "<!-- peers_doc.py: end -->"
TITLE = "# How accurate are the distance queries people use?"


def worst_case_commands(text, plugins, script):
    """The errors of the worst cases' commands: which plugins each loads, and its mark."""
    sys.path.insert(0, str(pathlib.Path(script).parent))
    from check_doc_commands import OPTIONAL

    errors, seen = [], 0
    for p in plugins:
        optional = [o for o in OPTIONAL if re.search(o[1], p["file"])]
        for v in p["variants"]:
            para = next((l for l in text.splitlines() if l.startswith(f"**{v}**")), None)
            if para is None or "Command: `" not in para:
                continue  # a variant with no case to draw has no command
            seen += 1
            for q in plugins:
                loads = f"--plugin {q['file']}" in para or re.search(
                    r"--plugin \S*" + re.escape(pathlib.Path(q["file"]).name) + r"\b", para
                )
                other = [o for o in OPTIONAL if re.search(o[1], q["file"])]
                if bool(loads) != (not other or q is p):
                    errors.append(
                        f"{v}'s worst case command {'loads' if loads else 'lacks'} " f"{q['file']}"
                    )
            if optional and f"**{v}** ({optional[0][2]})" not in para:
                errors.append(f"{v}'s worst case needs {optional[0][0]} and does not say so")
            if not optional and "(needs" in para.split("Command:")[0]:
                errors.append(f"{v}'s worst case says it needs an optional part")
    if seen == 0:
        errors.append("no worst case with a command: nothing checked")
    return errors


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--script", required=True)
    a = ap.parse_args()
    with tempfile.TemporaryDirectory(prefix="peers_doc_check.") as t:
        t = pathlib.Path(t)
        doc = t / "peers.md"
        before = TITLE + "\n\nHand-written intro.\n\n"
        after = "\n\n## box2d-2.4.1\n\nA hand-written section.\n"
        doc.write_text(before + BEGIN + "\nstale\n" + END + after)
        (t / "peers").mkdir()
        (t / "peers" / "gone-peer.svg").write_text("<svg/>")  # a peer no longer in the report
        page_before, page_after = "# Box2D: a hand-written title\n\n", "\n\n## Hand-written\n"
        (t / "peers" / "box2d.md").write_text(page_before + BEGIN + "\nstale\n" + END + page_after)
        # Two family groups (hard, random), no timing: seconds.
        cmd = [
            sys.executable,
            a.script,
            "--gjk-validate",
            a.exe,
            "--doc",
            str(doc),
            "--out",
            str(t / "run"),
            "--",
            "--family",
            "hard/near-parallel:20",
            "--family",
            "random:40",
            "--no-timing",
        ]
        done = subprocess.run(cmd)
        if done.returncode != 0:
            print(f"FAIL: {cmd} exited {done.returncode}")
            return 1
        overview = doc.read_text()
        report = json.loads((t / "run" / "report.json").read_text())
        plugins = report["context"]["plugins"]
        errors = []
        pages = {
            p: (t / "peers" / p).read_text()
            for p in sorted(f.name for f in (t / "peers").glob("*.md"))
        }
        box2d = pages.get("box2d.md", "")
        if not box2d.startswith(page_before + BEGIN) or not box2d.endswith(END + page_after):
            errors.append("the text around the markers of peers/box2d.md was not kept as it was")
        for p in plugins:
            for v in p["variants"]:
                if not any(
                    l.startswith(f"| {v} | [") and "](peers/" in l for l in overview.splitlines()
                ):
                    errors.append(f"no verdict row linking a page for {v} in the overview")
        text = "\n".join([overview] + list(pages.values()))
        if not plugins:
            errors.append(
                "the report's context lists no plugin: the shipped Box2D 2.4.1 "
                "adapter should be loaded"
            )
        if not overview.startswith(before + BEGIN) or not overview.endswith(END + after):
            errors.append("the text around the markers was not kept as it was")
        if "stale" in text:
            errors.append("the old generated part was not replaced")
        if (t / "peers" / "gone-peer.svg").exists():
            errors.append("the drawing of a peer no longer in the report was kept")
        rows = [l for l in text.splitlines() if l.startswith("| ")]
        for p in plugins:
            for v in p["variants"]:
                for group in ("hard", "random"):
                    if not any(l.startswith(f"| {v} | {group} | ") for l in rows):
                        errors.append(f"no table row for {v} in {group}")
                if not (t / "peers" / f"{v}.svg").is_file():
                    errors.append(f"no drawing peers/{v}.svg")
        errors += worst_case_commands(text, plugins, a.script)
        # Every variant's contract has a row of the contract table, which names what it is given
        # (variants[].input.given) and its overlap kind.
        for v in report["variants"]:
            kind = (v.get("contract") or {}).get("overlap")
            given = (v.get("input") or {}).get("given")
            if v["name"] in ("double", "float") or "plugin" in v:
                if (
                    not kind
                    or not given
                    or not any(
                        l.startswith(f"| {v['name']} | {v['type']} | {given} | {kind} | ")
                        for l in rows
                    )
                ):
                    errors.append(f"no contract row for {v['name']} (overlap {kind})")
        if "### Each peer's worst contract violation, with a repro" not in text:
            errors.append("no section of the peers' contract violations")
        # Without options the script runs the default campaign, as `gjk-validate list` says it:
        # families, then the default case files.
        sys.path.insert(0, str(pathlib.Path(a.script).parent))
        import peers_doc

        default = peers_doc.default_campaign(a.exe)
        families = default[:-1]
        if (
            default[-1:] != ["--default-cases"]
            or not families
            or len(families) % 2
            or set(families[::2]) != {"--family"}
        ):
            errors.append(f"the default campaign read from `list` is {default}")
        # Each group here holds one family: the joined histograms' p99 and max must be that
        # family's, as the runner computed them (Hist::percentile).
        cols = {
            "largest rel. error": ("rel", "max"),
            "p99 rel. error": ("rel", "p99"),
            "largest error / gjk2d's bound": ("bound_ratio", "max"),
            "p99 error / bound": ("bound_ratio", "p99"),
        }
        head = next(l for l in rows if l.startswith("| variant | family group |"))
        names = [c.strip() for c in head.strip("|").split("|")]
        for fam in report["families"]:
            group = fam["name"].split("/")[0]
            for v, st in fam["variants"].items():
                row = next((l for l in rows if l.startswith(f"| {v} | {group} | ")), None)
                if row is None:
                    continue
                cells = [c.strip() for c in row.strip("|").split("|")]
                for col, (hist, key) in cols.items():
                    value = float(st["errors"][hist][key])
                    if key == "p99":  # the bin's upper edge, at most the exact max
                        value = min(value, float(st["errors"][hist]["max"]))
                    want = format(value, ".3g")
                    got = cells[names.index(col)]
                    if got != want:
                        errors.append(f"{v} in {group}: {col} {got}, the report says {want}")
        for e in errors:
            print("FAIL: " + e)
        if errors:
            print(text)
        return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
