#!/usr/bin/env python3
"""Writes the generated parts of docs/peers.md (the overview) and docs/peers/<peer>.md (one page per
plugin): how the shipped peers (and any plugin) did.

    python3 scripts/peers_doc.py                  # after scripts/run.sh: runs the peers' campaign
    python3 scripts/peers_doc.py --report DIR/report.json   # from a report of run --peers
    python3 scripts/peers_doc.py --doc OUT.md -- --family hard:20   # a campaign of one's own

It runs `build/release/validation/gjk-validate run --peers` on the default campaign (its options
as `gjk-validate list` prints them on its first line) into reports/peers/, reads
its report.json and rewrites only the part of each document between the markers
`<!-- peers_doc.py: begin -->` and `<!-- peers_doc.py: end -->` (created with the title when the
document does not exist; the hand-written sections around it are kept). The overview gives each
variant's contract and one row of its verdict; the page of a plugin (<doc's folder>/peers/<peer>.md,
<peer> its file's name without `gjk2d-`, `.so` and a `-float`/`-double` ending) gives its variants'
rows per family group, its timing, its penetration depths, its worst contract violation with a
standalone program from `gjk-validate repro` (kept in <doc's folder>/peers/repro/, emptied first)
and its largest error against gjk2d's bound, drawn to <doc's folder>/peers/<variant>.svg from
`gjk-validate explain --json` of that case (the folder's other .svg files are removed: it holds only
this script's drawings).
Only Python's standard library. Exit codes: 0 written, 1 a command failed, 2 bad usage.
"""
import argparse
import json
import math
import os
import pathlib
import re
import shlex
import subprocess
import sys
import tempfile

from check_doc_commands import OPTIONAL  # the optional parts a documented command may need

ROOT = pathlib.Path(__file__).resolve().parent.parent
TITLE = "# How accurate are the distance queries people use?"
BEGIN, END = "<!-- peers_doc.py: begin -->", "<!-- peers_doc.py: end -->"
DEFAULT_CAMPAIGN = "default campaign (run without --family and --cases): "  # `list`'s line
# gjk2d's reference variants, and its signed ones (a penetration contract, beside the peers' EPA),
# shown beside the peers
GJK2D_ROWS = ["double", "float", "double-signed", "float-signed"]


def fail(code, message):
    print(f"peers_doc.py: {message}", file=sys.stderr)
    sys.exit(code)


def run(cmd, must=True):
    """Runs a gjk-validate command; its exit code (1, a judged failure, still writes its output)."""
    print("+ " + shlex.join(cmd), file=sys.stderr)
    done = subprocess.run(cmd, stdout=subprocess.DEVNULL)
    if must and done.returncode not in (0, 1):
        fail(1, f"`{shlex.join(cmd)}` exited {done.returncode}")
    return done.returncode


def default_campaign(gjk):
    """run's options for the default campaign, from `gjk-validate list` (the program's one home)."""
    done = subprocess.run([gjk, "list", "--no-default-plugins"], capture_output=True, text=True)
    line = next((l for l in done.stdout.splitlines() if l.startswith(DEFAULT_CAMPAIGN)), None)
    if done.returncode != 0 or line is None:
        fail(1, f"`{gjk} list` exited {done.returncode} without its '{DEFAULT_CAMPAIGN}' line")
    return shlex.split(line[len(DEFAULT_CAMPAIGN) :])


def num(x):
    """A report number (non-finite ones are strings) as a float, None when absent."""
    if x is None:
        return None
    return float(x)  # also "inf", "-inf", "nan"


def group_of(family):
    if family.startswith("file:"):
        return "case files"
    return family.split("/")[0]


def merge_hist(hists):
    """max and p99 of the families' histograms joined (the rule of Hist::percentile in
    validation/src/statistics/stats.cpp: the upper edge of the bin holding the 99th percentile),
    the p99 no larger than the max (the max is exact, the bin edge only bounds the p99)."""
    top, p99 = merge_hist_edges(hists)
    return top, p99 if p99 is None or top is None else min(p99, top)


def merge_hist_edges(hists):
    hists = [h for h in hists if h and h.get("count", 0) > 0]
    if not hists:
        return None, None
    top = max(num(h["max"]) for h in hists)
    shapes = {(h["log10_min"], h["bins_per_decade"], len(h.get("counts", []))) for h in hists}
    if len(shapes) != 1:  # bins that do not line up: the largest of the families' p99
        return top, max(num(h["p99"]) for h in hists)
    count = sum(h["count"] for h in hists)
    counts = [0] * max(len(h.get("counts", [])) for h in hists)
    for h in hists:
        for i, c in enumerate(h.get("counts", [])):
            counts[i] += c
    rank = max(1, (count * 990 + 999) // 1000)
    cum = sum(h["zeros"] for h in hists)
    if cum >= rank:
        return top, 0.0
    lo, per = hists[0]["log10_min"], hists[0]["bins_per_decade"]
    for i, c in enumerate(counts):
        cum += c
        if cum >= rank:
            return top, 10.0 ** (lo + (i + 1) / per)
    return top, top


def group_rows(report, variant):
    """One row per family group: summed counts, joined error histograms, ns/query weighted by
    cases."""
    groups = {}
    for fam in report["families"]:
        st = fam["variants"].get(variant)
        if st is not None:
            groups.setdefault(group_of(fam["name"]), []).append(st)
    rows = []
    for name, sts in groups.items():
        s = lambda k: sum(st.get(k, 0) or 0 for st in sts)
        reasons = {}
        for st in sts:
            for k, n in (st.get("contract_violations") or {}).get("reasons", {}).items():
                reasons[k] = reasons.get(k, 0) + n
        rel = merge_hist([st.get("errors", {}).get("rel") for st in sts])
        ratio = merge_hist([st.get("errors", {}).get("bound_ratio") for st in sts])
        timed = [
            (st["cases"], num(st["ns_per_query"]))
            for st in sts
            if st.get("ns_per_query") is not None
        ]
        weight = sum(c for c, _ in timed)
        ns = sum(c * t for c, t in timed) / weight if weight > 0 else None
        rows.append(
            {
                "group": name,
                "cases": s("cases"),
                "refused": s("refused"),
                "violations": sum(
                    (st.get("contract_violations") or {}).get("count", 0) for st in sts
                ),
                "reasons": reasons,
                "outside": s("beyond_bound_keeping_contract"),
                "penetration": penetration_rows(sts),
                "false_overlap": s("false_overlap"),
                "false_separation": s("false_separation"),
                "nonfinite": s("nonfinite"),
                "incidents": s("plugin_errors") + s("crashed") + s("hung"),
                "rel": rel,
                "ratio": ratio,
                "ns": ns,
            }
        )
    return rows


def penetration_rows(sts):
    """The families' penetration blocks (report.json Stats `penetration`, only a variant whose
    contract says penetration) joined: None when no family has one."""
    blocks = [st["penetration"] for st in sts if st.get("penetration")]
    if not blocks:
        return None
    s = lambda k: sum(b.get(k, 0) or 0 for b in blocks)
    return {
        "cases": s("cases"),
        "violations": s("contract_violations"),
        "beyond": s("beyond_bound"),
        "outside": s("beyond_bound_keeping_contract"),
        "nonfinite": s("nonfinite"),
        "abs": merge_hist([b.get("abs") for b in blocks]),
        "rel": merge_hist([b.get("rel") for b in blocks]),
        "ratio": merge_hist([b.get("bound_ratio") for b in blocks]),
    }


def g(x, spec=".3g"):
    return "-" if x is None else format(x, spec)


def reasons_text(reasons):
    return ", ".join(f"{k} {n}" for k, n in sorted(reasons.items(), key=lambda kv: -kv[1])) or "-"


def contract_table(report, peers):
    """Each variant's contract (report.json variants[].contract), clause by clause with its
    source."""
    out = [
        "### What each peer promises (its contract)",
        "",
        "Each implementation is judged by what it promises, each clause with where its library "
        "says so (declared by its adapter: gjk2d/plugin.h, `gjk2d_contract`). Where a library "
        "states no tolerance, its distance is held to gjk2d's own a-priori bound in its scalar "
        "type, and the table says so. *It is given*: the case as given, or, for a library "
        "that cannot take the case's transform exactly, the case's world points (in double, "
        "then rounded to its scalar type) with identity transforms, and it is judged on "
        "exactly those (its adapter's `input NAME world` line, docs/plugin-abi.md).",
        "",
        "| variant | type | it is given | on overlap | source | its distance is held to | "
        "margin | its depth is held to |",
        "|---|---|---|---|---|---|---|---|",
    ]
    info = {v["name"]: v for v in report["variants"]}
    for name in [v for v in GJK2D_ROWS if v in info] + peers:
        v = info[name]
        c = v.get("contract") or {}
        margin = c.get("margin", 0)
        msrc = c.get("margin_source") or ""
        given = (v.get("input") or {}).get("given", "the case as given")
        out.append(
            f"| {name} | {v.get('type', '?')} | {given} | {c.get('overlap', '?')} | "
            f"{c.get('overlap_source') or 'none stated'} | {c.get('judged_by', '?')} | "
            f"{g(margin, 'g')}{' (' + msrc + ')' if msrc else ''} | "
            f"{c.get('judged_by_depth', '?')} |"
        )
    return out


def timing_table(report, peers):
    """What each variant's ns/query includes (report.json variants[].timing), its ns/query and its
    preparation per shape, weighted by the timed families' cases."""
    out = [
        "### What ns/query includes",
        "",
        "Each implementation is timed as its users pay: where its adapter offers a preparation "
        "step (gjk2d/plugin.h, `gjk2d_plugin_prepared`; an adapter's `prepared` line), shapes "
        "are prepared once, outside the timed loop, and ns/query is the query alone; the "
        "preparation is timed apart, per shape. Variants are timed in alternated passes, family "
        'by family (docs/speed.md, "What a variant\'s ns/query includes").',
        "",
        "| variant | ns/query | ns to prepare a shape | what ns/query includes | timed by |",
        "|---|---|---|---|---|",
    ]
    info = {v["name"]: v for v in report["variants"]}
    for name in peers:
        t = info[name].get("timing") or {}
        sts = [f["variants"][name] for f in report["families"] if name in f["variants"]]
        timed = [
            (st["cases"], num(st["ns_per_query"]), st.get("prepare_ns_per_shape"))
            for st in sts
            if st.get("ns_per_query") is not None
        ]
        weight = sum(c for c, _, _ in timed)
        ns = sum(c * x for c, x, _ in timed) / weight if weight > 0 else None
        prep = [(c, num(p)) for c, _, p in timed if p is not None]
        pw = sum(c for c, _ in prep)
        pns = sum(c * x for c, x in prep) / pw if pw > 0 else None
        out.append(
            f"| {name} | {g(ns, '.0f')} | {g(pns, '.0f')} | {t.get('includes', '?')} | "
            f"{t.get('timed_by', '?')} |"
        )
    return out


def weighted_ns(report, name, key):
    """A variant's ns/query (key "ns_per_query") or ns to prepare a shape ("prepare_ns_per_shape"),
    the timed families' figures weighted by their cases; None when not timed."""
    timed = [
        (f["variants"][name]["cases"], num(f["variants"][name].get(key)))
        for f in report["families"]
        if name in f["variants"]
        and f["variants"][name].get("ns_per_query") is not None
        and f["variants"][name].get(key) is not None
    ]
    weight = sum(c for c, _ in timed)
    return sum(c * x for c, x in timed) / weight if weight > 0 else None


def summary_table(report, names, page_of_variant, command):
    """One row per variant over the whole campaign: its verdict, accuracy and speed, and its page."""
    out = [
        "### Verdict, accuracy and speed",
        "",
        f"One row per variant over the whole campaign, `{command}`; per family group, and why: "
        "each peer's page. Rows of gjk2d's reference and signed variants are there to compare "
        "with.",
        "",
        "| variant | page | cases | refused | breaks its contract | why | outside gjk2d's bound, "
        "keeps its contract | false overlaps | false separations | largest error / gjk2d's "
        "bound | ns/query | ns to prepare a shape |",
        "|---|---|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|",
    ]
    for v in names:
        rows = group_rows(report, v)
        s = lambda k: sum(r[k] for r in rows)
        reasons = {}
        for r in rows:
            for k, n in r["reasons"].items():
                reasons[k] = reasons.get(k, 0) + n
        ratios = [r["ratio"][0] for r in rows if r["ratio"][0] is not None]
        page = page_of_variant.get(v)
        link = f"[{os.path.basename(page)}]({page}.md)" if page else "-"
        out.append(
            f"| {v} | {link} | {s('cases')} | {s('refused')} | {s('violations')} | "
            f"{reasons_text(reasons)} | {s('outside')} | {s('false_overlap')} | "
            f"{s('false_separation')} | {g(max(ratios) if ratios else None)} | "
            f"{g(weighted_ns(report, v, 'ns_per_query'), '.0f')} | "
            f"{g(weighted_ns(report, v, 'prepare_ns_per_shape'), '.0f')} |"
        )
    out += [
        "",
        "Columns as on the peers' pages (docs/report-schema.md, Stats): *breaks its "
        "contract*: answers that break what the implementation promises (the table above), a "
        "bug of that implementation (for gjk2d's variants, a failure); *outside gjk2d's bound, "
        "keeps its contract*: a measured accuracy, not a failure; error / bound: |d - d_exact| "
        "over gjk2d's a-priori bound (docs/error-bound.md); ns/query: single-threaded, the "
        "timed families weighted by cases (- when not timed).",
    ]
    return out


def verdict_table(report, peers, command):
    out = [
        "### Contract violations and accuracy",
        "",
        f"Per variant and family group, from `{command}`.",
        "",
        "| variant | family group | cases | refused | breaks its contract | why | outside "
        "gjk2d's bound, keeps its contract | false overlaps | false "
        "separations | largest rel. error | p99 rel. error | largest error / gjk2d's bound | "
        "p99 error / bound | ns/query |",
        "|---|---|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for v in peers:
        for r in group_rows(report, v):
            out.append(
                f"| {v} | {r['group']} | {r['cases']} | {r['refused']} | "
                f"{r['violations']} | {reasons_text(r['reasons'])} | {r['outside']} | "
                f"{r['false_overlap']} | {r['false_separation']} | "
                f"{g(r['rel'][0])} | {g(r['rel'][1])} | "
                f"{g(r['ratio'][0])} | {g(r['ratio'][1])} | {g(r['ns'], '.0f')} |"
            )
    out += [
        "",
        "Columns (docs/report-schema.md, Stats): *cases* answered; *refused* by the "
        "implementation (not in cases); *breaks its contract*: answers that break what the "
        "implementation promises (the contract table of docs/peers.md): a bug of that "
        "implementation; *why*: the reasons, with their counts (docs/report-schema.md, "
        "`contract_violations`); *outside gjk2d's bound, keeps its contract*: answers further "
        "from the exact distance than gjk2d's a-priori bound in the variant's precision "
        "(docs/error-bound.md) that keep the implementation's own contract: a measured "
        "accuracy, not a failure; *false overlaps and separations* "
        "against the exact side, whatever the contract allows; rel. error = |d - d_exact| / "
        "d_exact (separated cases); error / bound = |d - d_exact| over gjk2d's bound (a "
        "negative distance of a zero or penetration contract counts as 0); p99 values are "
        "histogram bin upper edges, at most the largest; ns/query: the families' "
        "single-threaded timings, weighted by cases (- when not timed).",
    ]
    return out


def depth_table(report, peers):
    """The penetration depth beside the distance (report.json Stats `penetration`): each variant
    whose contract says penetration, per family group."""
    rows = [(v, r) for v in peers for r in group_rows(report, v) if r["penetration"]]
    if not rows:
        return []
    out = [
        "### Penetration depth (contracts that say `penetration`)",
        "",
        "The depth of each overlapping case against the exact penetration depth (docs/exact.md, "
        '"Penetration depth"), beside the distance above: what an engine resolving contacts '
        "consumes.",
        "",
        "| variant | family group | overlapping cases | breaks its contract | beyond gjk2d's "
        "depth bound | of them keeping its contract | largest depth error | largest rel. "
        "error | p99 rel. error | largest error / depth bound |",
        "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for v, r in rows:
        p = r["penetration"]
        out.append(
            f"| {v} | {r['group']} | {p['cases']} | {p['violations']} | {p['beyond']} | "
            f"{p['outside']} | {g(p['abs'][0])} | {g(p['rel'][0])} | {g(p['rel'][1])} | "
            f"{g(p['ratio'][0])} |"
        )
    out += [
        "",
        "Columns (docs/report-schema.md, `penetration`): *overlapping cases* judged (exact "
        "signed distance below 0); *breaks its contract*: the depth beyond its stated "
        "tolerance (or gjk2d's depth bound where none is stated: the contract table), "
        "or a point off its shape; *beyond gjk2d's depth bound*: |depth - exact depth| over "
        "gjk2d's a-priori depth bound (docs/error-bound.md), *of them keeping its contract*: "
        "a measured accuracy; rel. error = |depth - exact depth| / exact depth.",
    ]
    return out


def worst_violation(report, variant):
    """The variant's worst contract violation in the report (variants[].worst_contract_violation),
    or None."""
    for v in report["variants"]:
        if v["name"] == variant:
            return v.get("worst_contract_violation")
    return None


def worst_of(report, variant):
    """(family, case, error/bound) of the variant's largest error relative to gjk2d's bound."""
    best = None
    for fam in report["families"]:
        h = fam["variants"].get(variant, {}).get("errors", {}).get("bound_ratio")
        if h and h.get("count", 0) > 0 and h.get("max_case"):
            if best is None or num(h["max"]) > best[2]:
                best = (fam["name"], h["max_case"], num(h["max"]))
    return best


def explain_command(gjk, report, family, case, plugin_files, verb="explain", variant="double"):
    """`gjk-validate explain` (or `repro`) of one case of the report, its plugins loaded as
    --plugin."""
    cmd = [gjk, verb]
    inputs = report["context"]["inputs"]
    if family.startswith("file:"):
        rest = family[len("file:") :]
        files = [
            i["file"]
            for i in inputs
            if "file" in i and (i["file"] == rest or i["file"].endswith("/" + rest))
        ]
        cmd += [files[0] if files else rest, case]
    else:
        spec = next((i for i in inputs if i.get("family") == family), None)
        seed = spec.get("seed", report["context"]["seed"]) if spec else report["context"]["seed"]
        count = f":{spec['count']}" if spec and "count" in spec else ""
        cmd += ["--family", family + count, "--seed", str(seed), case]
    cmd += ["--variants", variant, "--no-default-plugins"]
    for f in plugin_files:
        cmd += ["--plugin", f]
    return cmd


def pts(xs):
    out = []
    for p in xs or []:
        try:
            x, y = num(p[0]), num(p[1])
        except (TypeError, ValueError, IndexError):
            continue
        if math.isfinite(x) and math.isfinite(y):
            out.append((x, y))
    return out


def exact_for(detail, variant):
    """The exact answer a variant is judged against: of the float-rounded input for a float one,
    of its world case for one given world points (docs/report-schema.md, CaseDetail: its
    "truth" key)."""
    ans = detail.get("variants", {}).get(variant, {})
    if ans.get("input") == "world":
        return detail.get("world_input", {}).get(ans.get("type"), {}).get("exact") or detail.get(
            "exact", {}
        )
    if ans.get("type") == "float" and detail.get("exact_float_input"):
        return detail["exact_float_input"]
    return detail.get("exact", {})


def svg_panel(detail, variant, box, ox, size, title):
    """One square panel: both shapes (radius drawn as a round stroke), the exact witness points
    (black) and the variant's (red), in the world window box = (cx, cy, half width)."""
    cx, cy, hw = box
    sc = size / (2 * hw)
    tx = lambda p: (ox + (p[0] - cx) * sc + size / 2, size / 2 - (p[1] - cy) * sc + 20)
    out = [
        f'<rect x="{ox}" y="20" width="{size}" height="{size}" fill="white" stroke="#999"/>',
        f'<text x="{ox + 4}" y="14" font-size="11">{title}</text>',
        f'<clipPath id="c{ox}"><rect x="{ox}" y="20" width="{size}" height="{size}"/></clipPath>',
        f'<g clip-path="url(#c{ox})">',
    ]
    for key, colour in (("a", "#4a90c2"), ("b", "#d98c2b")):
        shape = detail.get(key, {})
        w = [tx(p) for p in pts(shape.get("world"))]
        r = (num(shape.get("radius")) or 0) * sc
        if not w:
            continue
        d = "M" + " L".join(f"{x:.2f} {y:.2f}" for x, y in w) + " Z"
        width = max(2 * r, 1.2)
        out.append(
            f'<path d="{d}" fill="{colour}" fill-opacity="0.35" stroke="{colour}" '
            f'stroke-opacity="0.6" stroke-width="{width:.2f}" stroke-linejoin="round" '
            'stroke-linecap="round"/>'
        )
    ex = exact_for(detail, variant)
    ans = detail.get("variants", {}).get(variant, {})
    for a, b, colour in (
        (ex.get("witnessA"), ex.get("witnessB"), "black"),
        (ans.get("pointA"), ans.get("pointB"), "#d0021b"),
    ):
        p = [tx(q) for q in pts([a, b])]
        if len(p) == 2:
            out.append(
                f'<line x1="{p[0][0]:.2f}" y1="{p[0][1]:.2f}" x2="{p[1][0]:.2f}" '
                f'y2="{p[1][1]:.2f}" stroke="{colour}" stroke-width="1.2"/>'
            )
        for x, y in p:
            out.append(f'<circle cx="{x:.2f}" cy="{y:.2f}" r="3" fill="{colour}"/>')
    return out + ["</g>"]


def draw(detail, variant, path):
    """The case whole, and zoomed on the exact witness points so that the answer's error shows."""
    world = pts(detail.get("a", {}).get("world")) + pts(detail.get("b", {}).get("world"))
    if not world:
        return False
    xs, ys = [p[0] for p in world], [p[1] for p in world]
    radius = max(num(detail[k].get("radius")) or 0 for k in ("a", "b"))
    hw = max(max(xs) - min(xs), max(ys) - min(ys)) / 2 * 1.1 + radius or 1.0
    whole = ((max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2, hw)
    ex = exact_for(detail, variant)
    ans = detail.get("variants", {}).get(variant, {})
    wit = pts([ex.get("witnessA"), ex.get("witnessB")])
    got = pts([ans.get("pointA"), ans.get("pointB")])
    c = wit[0] if wit else whole[:2]
    spread = max([math.dist(c, p) for p in wit + got] + [0.0])
    zoom = (c[0], c[1], max(spread * 1.5, hw * 1e-12, 1e-300))
    size = 300
    body = svg_panel(detail, variant, whole, 0, size, "whole case") + svg_panel(
        detail, variant, zoom, size + 10, size, f"zoom: half width {zoom[2]:.3g}"
    )
    legend = (
        f'<text x="0" y="{size + 36}" font-size="11">blue: shape A, orange: shape B, black: '
        f"exact witness points, red: {variant}'s</text>"
    )
    path.write_text(
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{2 * size + 10}" '
        f'height="{size + 44}" font-family="sans-serif">\n'
        + "\n".join(body)
        + "\n"
        + legend
        + "\n</svg>\n"
    )
    return True


def rel(arg):
    """A path under the repository, relative to it (the commands shown run from its root)."""
    p = pathlib.Path(arg)
    if p.is_absolute():
        try:
            return str(p.resolve().relative_to(ROOT))
        except ValueError:
            pass
    return arg


def plugins_for(plugins, variant):
    """The plugin files of the command that explains `variant`'s worst case, and what the command
    needs that a user's clone lacks (" (needs ...)", or ""): every plugin the README's first command
    builds, and an optional one (check_doc_commands.OPTIONAL: the Box2D v3 adapter) only in its own
    variant's command, marked so that the docs test skips it where the part is not built."""
    files, needs = [], ""
    for p in plugins:
        optional = [o for o in OPTIONAL if re.search(o[1], "--plugin " + p["file"])]
        if not optional:
            files.append(p["file"])
        elif variant in p.get("variants", []):
            files.append(p["file"])
            needs = f" ({optional[0][2]})"
    return files, needs


def worst_section(report, peers, gjk, shown_gjk, svg_dir, doc, work):
    out = [
        "",
        "### Each peer's largest error against gjk2d's bound",
        "",
        "Each plugin variant's case with the largest error relative to gjk2d's bound, whether "
        "or not it keeps its contract (a non-finite answer is not here), drawn by this script "
        "from the command under it.",
    ]
    plugins = report["context"].get("plugins", [])
    for v in peers:
        w = worst_of(report, v)
        if w is None:
            out += ["", f"**{v}**: no case with an error to draw."]
            continue
        family, case, ratio = w
        files, needs = plugins_for(plugins, v)
        cmd = explain_command(gjk, report, family, case, files)
        js = work / f"explain-{v}.json"
        code = run(cmd + ["--json", str(js)], must=False)
        shown = [shown_gjk] + [rel(x) for x in cmd[1:]] + ["--json", "case.json"]
        if code not in (0, 1) or not js.is_file():
            print(
                f"peers_doc.py: {v}'s worst case not drawn: explain exited {code}", file=sys.stderr
            )
            out += [
                "",
                f"**{v}**{needs}: `{case}` ({family}), error / bound {ratio:.3g}; not drawn: "
                f"`{shlex.join(shown)}` exited {code}.",
            ]
            continue
        detail = json.loads(js.read_text())
        svg = svg_dir / f"{v}.svg"
        drawn = draw(detail, v, svg)
        ans = detail.get("variants", {}).get(v, {})
        out += [
            "",
            f"**{v}**{needs}: `{case}` ({family}), error / bound {ratio:.3g}: exact distance "
            f"{g(num(exact_for(detail, v).get('distance')), '.17g')}, {v} "
            f"{g(num(ans.get('distance')), '.17g')}. Command: `{shlex.join(shown)}`",
        ]
        if drawn:
            out += ["", f"![{v} on {case}]({os.path.relpath(svg, doc.parent)})"]
    return out


def violation_section(report, peers, gjk, shown_gjk, repro_dir, doc):
    """Each peer's worst contract violation, and the standalone program `gjk-validate repro` writes
    for it (in the peer's own language and API, no gjk2d in it), kept in repro_dir and linked."""
    out = [
        "",
        "### Each peer's worst contract violation, with a repro",
        "",
        "The case of each plugin variant whose answer breaks its own contract the most (the "
        "report's `variants[].worst_contract_violation`), and a program that shows it with the "
        "library alone: `gjk-validate repro` writes it, the command under each.",
    ]
    plugins = report["context"].get("plugins", [])
    for v in peers:
        w = worst_violation(report, v)
        if not w:
            out += ["", f"**{v}**: keeps its contract on every case."]
            continue
        files, needs = plugins_for(plugins, v)
        cmd = explain_command(gjk, report, w["family"], w["case"], files, "repro", v)
        shown = [shown_gjk] + [rel(x) for x in cmd[1:]] + ["--out", rel(str(repro_dir))]
        before = {f.name for f in repro_dir.iterdir()}
        code = run(cmd + ["--out", str(repro_dir)], must=False)
        made = sorted(f.name for f in repro_dir.iterdir() if f.name not in before)
        links = ", ".join(f"[{m}]({os.path.relpath(repro_dir / m, doc.parent)})" for m in made)
        what = f"repro: {links}" if code == 0 and made else f"no repro: `repro` exited {code}"
        out += [
            "",
            f"**{v}**{needs}: `{w['case']}` ({w['family']}), {w.get('reason', '?')}; "
            f"{what}. Command: `{shlex.join(shown)}`",
        ]
    return out


def page_name(plugin_file):
    """The page of a plugin: its file's name without `gjk2d-`, `.so` and a `-float`/`-double`
    ending (Bullet's two modules share one page)."""
    name = os.path.basename(plugin_file)
    name = name[len("gjk2d-") :] if name.startswith("gjk2d-") else name
    name = name[: -len(".so")] if name.endswith(".so") else name
    for end in ("-float", "-double"):
        if name.endswith(end):
            name = name[: -len(end)]
    return name


def pages_of(report):
    """{page: (title, [variants])} in the order of the report's plugins."""
    pages = {}
    for p in report["context"].get("plugins", []):
        title = p.get("library") or os.path.basename(p["file"])
        pages.setdefault(page_name(p["file"]), (title, []))[1].extend(p.get("variants", []))
    return pages


def stamp(command, ctx):
    return (
        f"Generated by `{command}`; edit nothing between these markers. The campaign: git "
        f"{ctx.get('git_revision', '?')}, {ctx.get('date', '?')}, "
        f"{ctx.get('cases_total', '?')} cases on {ctx.get('threads', '?')} threads of "
        f"{ctx.get('host', '?')}."
    )


def generated(report, shown_gjk, command, pages_dir):
    """The overview's generated part: the plugins, every variant's contract and its verdict."""
    ctx = report["context"]
    peers = [v["name"] for v in report["variants"] if "plugin" in v]
    pages = pages_of(report)
    page_of_variant = {v: page for page, (_, vs) in pages.items() for v in vs}
    out = [
        BEGIN,
        "",
        stamp(command, ctx),
        "",
        "Plugins loaded (the report's `context.plugins`), " "each with its page:",
        "",
    ]
    for p in ctx.get("plugins", []):
        lib = f", {p['library']}" if p.get("library") else ""
        page = page_name(p["file"])
        out.append(
            f"- [{page}]({pages_dir}/{page}.md): `{os.path.basename(p['file'])}` "
            f"({p.get('kind', '?')}{lib}): " + ", ".join(p.get("variants", []))
        )
    names = [v for v in GJK2D_ROWS if any(x["name"] == v for x in report["variants"])] + peers
    out += [""] + contract_table(report, peers) + [""]
    out += summary_table(
        report,
        names,
        {v: f"{pages_dir}/{p}" for v, p in page_of_variant.items()},
        f"{shown_gjk} {shlex.join(ctx_args(ctx))}",
    )
    return "\n".join(out + ["", END]) + "\n"


def generated_page(report, variants, gjk, shown_gjk, command, page, svg_dir, work):
    """A plugin's page's generated part: its variants per family group, timing, depths, worst
    contract violation with its repro, and largest error against gjk2d's bound, drawn."""
    ctx = report["context"]
    out = [BEGIN, "", stamp(command, ctx), ""]
    out += timing_table(report, variants) + [""]
    out += verdict_table(report, variants, f"{shown_gjk} {shlex.join(ctx_args(ctx))}")
    depth = depth_table(report, variants)
    out += [""] + depth if depth else []
    out += violation_section(report, variants, gjk, shown_gjk, svg_dir / "repro", page)
    out += worst_section(report, variants, gjk, shown_gjk, svg_dir, page, work)
    return "\n".join(out + ["", END]) + "\n"


def ctx_args(ctx):
    """The campaign's command line after `gjk-validate` (the report's context.command)."""
    words = shlex.split(ctx.get("command", "run"))
    return [rel(w) for w in (words[1:] if words and words[0].endswith("gjk-validate") else words)]


def splice(doc, block, title=TITLE):
    """The document with its generated part replaced by block (the title forced at its top for the
    overview; a page's first line is kept as written once it exists)."""
    text = doc.read_text() if doc.exists() else title + "\n"
    if title == TITLE and not text.startswith(TITLE):
        text = TITLE + "\n\n" + text
    if BEGIN in text and END in text:
        head, rest = text.split(BEGIN, 1)
        return head + block.rstrip("\n") + rest.split(END, 1)[1]
    first, _, rest = text.partition("\n")
    return first + "\n\n" + block + ("\n" + rest.lstrip("\n") if rest.strip() else "")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument(
        "--report",
        help="read this report.json of `gjk-validate run --peers` "
        "instead of running the campaign",
    )
    ap.add_argument("--gjk-validate", default=str(ROOT / "build/release/validation/gjk-validate"))
    ap.add_argument("--doc", default=str(ROOT / "docs/peers.md"))
    ap.add_argument("--svg-dir", help="default: <doc's folder>/peers")
    ap.add_argument(
        "--out",
        default=str(ROOT / "reports/peers"),
        help="the campaign's report directory (replaced)",
    )
    ap.add_argument(
        "run_args",
        nargs="*",
        help="after --: gjk-validate run's options instead of " "the default campaign's families",
    )
    a = ap.parse_args()
    doc = pathlib.Path(a.doc).resolve()
    svg_dir = pathlib.Path(a.svg_dir).resolve() if a.svg_dir else doc.parent / "peers"
    gjk = a.gjk_validate
    if not os.access(gjk, os.X_OK):
        fail(2, f"{gjk}: not found or not executable (build it: scripts/run.sh)")
    shown_gjk = (
        "build/release/validation/gjk-validate"
        if pathlib.Path(gjk).resolve() == (ROOT / "build/release/validation/gjk-validate").resolve()
        else "gjk-validate"
    )
    out = pathlib.Path(a.out).resolve()
    if a.report:
        report_path = pathlib.Path(a.report)
    else:
        args = a.run_args or default_campaign(gjk)
        run([gjk, "run", "--peers", *args, "--out", str(out), "--no-progress"])
        report_path = out / "report.json"
    try:
        report = json.loads(report_path.read_text())
    except (OSError, ValueError) as e:
        fail(2, f"{report_path}: cannot read the report: {e}")
    me = "python3 scripts/peers_doc.py" + (" " + shlex.join(sys.argv[1:]) if sys.argv[1:] else "")
    (svg_dir / "repro").mkdir(parents=True, exist_ok=True)
    # The drawings and programs of peers no longer in the report go too.
    for old in list(svg_dir.glob("*.svg")) + [
        f for f in (svg_dir / "repro").iterdir() if f.is_file()
    ]:
        old.unlink()
    written = {}
    with tempfile.TemporaryDirectory(prefix="peers_doc.") as work:
        for name, (title, variants) in pages_of(report).items():
            page = svg_dir / f"{name}.md"
            block = generated_page(
                report, variants, gjk, shown_gjk, me, page, svg_dir, pathlib.Path(work)
            )
            written[page] = splice(page, block, f"# {title}: how gjk-validate judges it")
    written[doc] = splice(
        doc, generated(report, shown_gjk, me, os.path.relpath(svg_dir, doc.parent))
    )
    doc.parent.mkdir(parents=True, exist_ok=True)
    for path, text in written.items():
        path.write_text(text)
    print(f"peers_doc.py: wrote {doc} and {svg_dir}/")
    return 0


if __name__ == "__main__":
    sys.exit(main())
