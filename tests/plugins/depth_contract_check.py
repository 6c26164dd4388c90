#!/usr/bin/env python3
"""A declared depth clause in a campaign's report (issue 51; tests/plugins/CMakeLists.txt).

  depth_contract_check.py --exe E --adapter A --cases C --work W [--bridge B --so S --so-name N]

A is adapters/depth.py: protocol version 2, overlap `penetration`, and the depth clause `contract
toy-depth depth 1e-3 none tests/plugins/adapters/toy.py` (given before its overlap line, which the
handshake allows). C is adapters/contract_cases.json. Checked in report.json's variants[]:
  toy-depth  contract.overlap "penetration", contract.depth {"abs": 1e-3, "rel": null, "source":
             "tests/plugins/adapters/toy.py"}, judged_by_depth "its stated tolerance: abs 0.001,
             rel none (tests/plugins/adapters/toy.py)";
  double     contract.depth all unstated ({null, null, ""}), judged_by_depth "no depth answered
             (overlap common-point)";
  double-signed  its own contract's overlap penetration, judged_by_depth "gjk2d's own contract:
             gjk2d's depth bound for double".
With --bridge (the adapter bridge) and --so (a shipped plugin exporting gjk2d_plugin_depth, whose
implementation is N): the plugin loaded as a shared library and through the bridge gives the same
contract.depth, so the ABI's clause and the protocol's line carry the same facts.
Exit 0 when every check holds; else a message and exit 1.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys


def fail(msg):
    print("depth_contract_check: FAIL: " + msg, file=sys.stderr)
    sys.exit(1)


def check(cond, msg):
    if not cond:
        fail(msg)


def variants(a, out, variant_list, plugin):
    shutil.rmtree(out, ignore_errors=True)
    cmd = [
        a.exe,
        "run",
        "--cases",
        a.cases,
        "--variants",
        variant_list,
        "--no-default-plugins",
        "--plugin",
        plugin,
        "--no-timing",
        "--no-progress",
        "--out",
        out,
    ]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        fail(
            "{} exited {}\nstdout:\n{}\nstderr:\n{}".format(
                " ".join(cmd), p.returncode, p.stdout[-3000:], p.stderr[-3000:]
            )
        )
    with open(os.path.join(out, "report.json")) as f:
        return {v["name"]: v for v in json.load(f)["variants"]}


def main():
    ap = argparse.ArgumentParser()
    for k in ("--exe", "--adapter", "--cases", "--work"):
        ap.add_argument(k, required=True)
    for k in ("--bridge", "--so", "--so-name"):
        ap.add_argument(k)
    a = ap.parse_args()
    v = variants(a, os.path.join(a.work, "adapter"), "double,double-signed,toy-depth", a.adapter)
    c = v["toy-depth"]["contract"]
    source = "tests/plugins/adapters/toy.py"
    check(c["overlap"] == "penetration", "toy-depth overlap {}".format(c["overlap"]))
    check(
        c["depth"] == {"abs": 1e-3, "rel": None, "source": source},
        "toy-depth contract.depth {}".format(c["depth"]),
    )
    want = "its stated tolerance: abs 0.001, rel none ({}), plus gjk2d's depth bound for double".format(
        source
    )
    check(
        c["judged_by_depth"] == want,
        "toy-depth judged_by_depth {!r} != {!r}".format(c["judged_by_depth"], want),
    )
    d = v["double"]["contract"]
    check(
        d["depth"] == {"abs": None, "rel": None, "source": ""},
        "double contract.depth {}".format(d["depth"]),
    )
    check(
        d["judged_by_depth"] == "no depth answered (overlap common-point)",
        "double judged_by_depth {!r}".format(d["judged_by_depth"]),
    )
    ds = v["double-signed"]["contract"]
    check(
        ds["overlap"] == "penetration"
        and ds["judged_by_depth"] == "gjk2d's own contract: gjk2d's depth bound for double",
        "double-signed contract {}".format(ds),
    )
    if a.bridge:
        direct = variants(a, os.path.join(a.work, "so"), a.so_name, a.so)[a.so_name]["contract"]
        wrapper = os.path.join(a.work, "bridged.sh")
        with open(wrapper, "w") as f:
            f.write("#!/bin/sh\nexec '{}' '{}'\n".format(a.bridge, a.so))
        os.chmod(wrapper, 0o755)
        bridged = variants(a, os.path.join(a.work, "bridge"), a.so_name, wrapper)[a.so_name][
            "contract"
        ]
        check(
            direct["overlap"] == "penetration", "{} overlap {}".format(a.so_name, direct["overlap"])
        )
        check(direct["depth"]["source"] != "", "{} states no depth source".format(a.so_name))
        for k in ("depth", "judged_by_depth", "overlap"):
            check(
                direct[k] == bridged[k],
                "{}: {} {} as a shared library, {} through the bridge".format(
                    a.so_name, k, direct[k], bridged[k]
                ),
            )
    print("depth_contract_check: ok")


if __name__ == "__main__":
    main()
