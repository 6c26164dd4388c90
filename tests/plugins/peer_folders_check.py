#!/usr/bin/env python3
"""CTest "plugins: every peer folder has its rows, and the table is theirs" (docs/code-map.md, "A peer
is one folder"). Reads every validation/plugins/<folder>/peer.txt itself and checks:
  - every folder has a peer.txt that parses, with `peer` rows or a `not-a-peer` line;
  - every `repro` line names a row's file of its own folder and a template that is in the folder,
    and the build put the template beside the plugins (<plugin dir>/<folder>/);
  - `gjk-validate list` lists exactly those rows' files, in the folders' order by name, each as
    `default` or `--peers` as its row says, or as not built;
  - every file the build put in the plugin directory is a row's file, or named by a `not-a-peer` line;
  - the same check on a copy of the folders where one has lost its peer.txt and another has a row
    whose file no folder builds and a repro line whose template is missing must fail, naming all
    three.
Exit 0 when every check holds, 1 with one line per problem."""
import argparse
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

ROW = re.compile(r"^peer ([A-Za-z0-9._-]+) (default|peers) ([A-Za-z0-9._-]+) (.+)$")
REPRO = re.compile(
    r"^repro ([A-Za-z0-9._-]+) ([A-Za-z0-9._+*-]+) ([A-Za-z0-9._-]+\.in)( +[A-Z][A-Z0-9_]*=[^ ]+)*$"
)


def read_folders(plugins):
    """[(folder, [(file, campaign)], [not-a-peer text], [(repro file, template)])] and the problems
    of the files."""
    out, problems = [], []
    for d in sorted(p for p in plugins.iterdir() if p.is_dir()):
        f = d / "peer.txt"
        if not f.is_file():
            problems.append(f"validation/plugins/{d.name}/ has no peer.txt")
            continue
        rows, nots, repros = [], [], []
        for no, line in enumerate(f.read_text().splitlines(), 1):
            if (
                not line.strip()
                or line.lstrip().startswith("#")
                or re.match(r"^package( \S+)+$", line)
            ):
                continue
            m = ROW.match(line)
            r = REPRO.match(line)
            if m:
                rows.append((m.group(1), m.group(2)))
            elif r:
                repros.append((r.group(1), r.group(3)))
                if not (d / r.group(3)).is_file():
                    problems.append(
                        f"validation/plugins/{d.name}/peer.txt:{no}: the repro template "
                        f"{r.group(3)} is not in the folder"
                    )
            elif line.startswith("not-a-peer "):
                nots.append(line)
            else:
                problems.append(
                    f"validation/plugins/{d.name}/peer.txt:{no}: not a line of its format"
                )
        if not rows and not nots:
            problems.append(f"validation/plugins/{d.name}/peer.txt: no row and no not-a-peer line")
        for file, template in repros:
            if file not in [f for f, _ in rows]:
                problems.append(
                    f"validation/plugins/{d.name}/peer.txt: the repro line for {file} "
                    f"names no row of the folder"
                )
        out.append((d.name, rows, nots, repros))
    return out, problems


def check(plugins, listed, built, built_root=None):
    """The problems of the folders under `plugins` against `list`'s peer lines and the built files."""
    folders, problems = read_folders(plugins)
    rows = [(f, c) for _, rs, _, _ in folders for f, c in rs]
    nots = " ".join(n for _, _, ns, _ in folders for n in ns)
    if [f for f, _ in rows] != [f for f, _ in listed]:
        problems.append(
            f"gjk-validate list shows {[f for f, _ in listed]}, the folders' rows are "
            f"{[f for f, _ in rows]}"
        )
    for (f, campaign), (g, shown) in zip(rows, listed):
        want = "default" if campaign == "default" else "--peers"
        if f == g and shown != want and shown != "not":
            problems.append(f"{f}: its row says {campaign}, gjk-validate list says {shown}")
    names = {f for f, _ in rows}
    built_dir = pathlib.Path(built_root) if built_root else None
    for folder, _, _, repros in folders:
        for _, template in repros:
            if built_dir and not (built_dir / folder / template).is_file():
                problems.append(f"the build did not put {folder}/{template} beside the plugins")
    for b in built:
        if b not in names and b not in nots:
            problems.append(f"the build made plugins/{b}, which no peer.txt names")
    return problems


def list_peers(exe):
    text = subprocess.run([exe, "list"], capture_output=True, text=True, check=True).stdout
    part = text[text.index("shipped peers") :].splitlines()[1:]
    out = []
    for line in part:
        m = re.match(r"^  (\S+)\s+(default|--peers|not)\b", line)
        if not m:
            break
        out.append((m.group(1), m.group(2)))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--plugins", required=True, help="validation/plugins of the source tree")
    ap.add_argument("--built", required=True, help="the build's plugin directory")
    a = ap.parse_args()
    plugins = pathlib.Path(a.plugins)
    built = sorted(
        p.name
        for p in pathlib.Path(a.built).iterdir()
        if p.name.startswith("gjk2d-") and (p.is_file())
    )
    listed = list_peers(a.exe)
    problems = check(plugins, listed, built, a.built)
    # The check must fail on a planted copy: a folder without its peer.txt, a row of no folder's.
    with tempfile.TemporaryDirectory(prefix="peer_folders_check.") as t:
        copy = pathlib.Path(t) / "plugins"
        shutil.copytree(plugins, copy)
        lost = sorted(copy.iterdir())[0]
        (lost / "peer.txt").unlink()
        extra = copy / sorted(copy.iterdir())[-1].name / "peer.txt"
        extra.write_text(
            extra.read_text() + "peer gjk2d-nowhere.so peers - nothing\n"
            "repro gjk2d-nowhere.so * missing-repro.c.in\n"
        )
        planted = check(copy, listed, built)
        for want in (
            f"validation/plugins/{lost.name}/ has no peer.txt",
            "gjk2d-nowhere.so",
            "missing-repro.c.in is not in the folder",
        ):
            if not any(want in p for p in planted):
                problems.append(
                    f"the planted copy was not caught: no problem names '{want}' " f"({planted})"
                )
    for p in problems:
        print("FAIL: " + p)
    print(f"{len(listed)} rows listed, {len(built)} files built, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
