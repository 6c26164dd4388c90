#!/usr/bin/env python3
"""What a plugin prints is kept apart from gjk-validate's output (issue 30; tests/plugins/CMakeLists.txt).

  plugin_output.py --exe E --plugin P --work W
      runs in W a campaign of a few hundred cases (timed) with the printing plugin P (the example
      plugin built with PRINT_EVERY_CALL: a line on stdout and one on stderr per call), given
      through a relative symbolic link, and checks: gjk-validate's stdout holds none of the
      plugin's lines and still ends with its summary and `report:` line; its stderr holds none
      either, and exactly one line naming the plugin, its log and the cap; the log
      W/report/plugin-<file>.log holds the plugin's stdout and stderr lines, exactly N bytes of
      them, and ends with the note that it was capped at N bytes; report.json's
      variants[].plugin.path and report.md name P's real absolute path; a second run into the
      same directory is accepted (the log is part of a report) and, without a printing plugin,
      leaves no log.
Exit 0 when every check holds; else a message and exit 1.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys


def fail(msg):
    print("plugin_output: FAIL: " + msg, file=sys.stderr)
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


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--work", required=True)
    a = ap.parse_args()
    a.exe, a.plugin, a.work = (os.path.abspath(x) for x in (a.exe, a.plugin, a.work))
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    out = os.path.join(a.work, "report")
    # Given through a symbolic link, relative to the working directory: the report names the file
    # itself, absolute.
    os.symlink(os.path.abspath(a.plugin), os.path.join(a.work, "printing.so"))
    # 6,000 cases: the accuracy calls alone print about 2.4 MB, over the 1 MiB cap whatever the timing
    # passes add (a sanitizer build's shorter timing printed 955,200 bytes with random:300).
    cmd = [
        a.exe,
        "run",
        "--family",
        "random:6000",
        "--variants",
        "double",
        "--no-default-plugins",
        "--plugin",
        "printing.so",
        "--passes",
        "3",
        "--out",
        out,
        "--no-progress",
    ]
    p = run(cmd, cwd=a.work)
    real = os.path.realpath(a.plugin)
    report = json.load(open(os.path.join(out, "report.json")))
    paths = {v["name"]: v["plugin"]["path"] for v in report["variants"] if "plugin" in v}
    if paths != {"printing-gjk": real, "printing-naive-f32": real}:
        fail("report.json's variants[].plugin.path: {}, expected {} for both".format(paths, real))
    if "`{}`".format(real) not in open(os.path.join(out, "report.md")).read():
        fail("report.md does not name " + real)
    if "printing plugin" in p.stdout:
        fail("the plugin's output reached gjk-validate's stdout:\n" + p.stdout[:2000])
    lines = p.stdout.strip().splitlines()
    if (
        not lines
        or not lines[-1].startswith("report: ")
        or not any(l.startswith("result: ") for l in lines)
    ):
        fail("stdout does not end with the summary and the report line:\n" + p.stdout[-2000:])
    log_name = "plugin-" + os.path.splitext(os.path.basename(real))[0] + ".log"
    log = os.path.join(out, log_name)
    err = p.stderr.strip().splitlines()
    if any("printing plugin:" in l for l in err):
        fail("the plugin's output reached gjk-validate's stderr:\n" + p.stderr[:2000])
    notice = [l for l in err if "printed" in l]
    if len(notice) != 1 or log not in notice[0] or real not in notice[0] or "cap" not in notice[0]:
        fail(
            "expected one line naming the plugin, its log {} and the cap, got:\n{}".format(
                log, p.stderr
            )
        )
    if not os.path.isfile(log):
        fail(log + " was not written")
    text = open(log, "rb").read()
    note = text[text.rfind(b"\n[gjk-validate:") :]
    cap = re.search(rb"capped at (\d+) bytes", note)
    if not cap:
        fail("the log does not end with the note that it was capped: ...{!r}".format(text[-300:]))
    cap = int(cap.group(1))
    # The plugin printed far more than the cap (about 200 bytes a call, 12,000 accuracy calls and the timed ones):
    # the log holds exactly the cap's worth, the rest dropped.
    if len(text) - len(note) != cap or "at least {} bytes".format(cap) not in notice[0]:
        fail(
            "the log holds {} bytes of the plugin's output, not its cap {}; notice: {}".format(
                len(text) - len(note), cap, notice[0]
            )
        )
    for want in [
        b"printing plugin: printing-gjk called with",
        b"printing plugin: printing-naive-f32 called",
        b"printing-gjk says this on stderr",
    ]:
        if want not in text:
            fail("the log lacks {!r}".format(want))
    # The same directory again, now without a printing plugin: accepted (a log is part of a
    # report), and replaced whole: no log left.
    p = run(
        [
            a.exe,
            "run",
            "--family",
            "random:20",
            "--variants",
            "double",
            "--no-default-plugins",
            "--no-timing",
            "--out",
            out,
            "--no-progress",
        ]
    )
    if os.path.exists(log) or "printed" in p.stderr:
        fail("a run without a printing plugin left or announced a log: {}".format(p.stderr))
    print(
        "plugin_output: stdout clean, one notice line, {} capped at {} bytes ({} with its note)".format(
            log_name, cap, len(text)
        )
    )


if __name__ == "__main__":
    main()
