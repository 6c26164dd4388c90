#!/usr/bin/env python3
"""Opens the HTML report in headless Chromium and checks that it really works (tests "report: browser*").

Drives Chromium over the DevTools protocol on --remote-debugging-pipe (Python standard library only):
  1. renders the page from a report.json with report_render (gjk_html::renderReport), or takes the
     index.html a campaign of gjk-validate wrote;
  2. loads it with #selftest: the page's own self-test counts the scatter points, steps the first
     iteration viewer and exercises every control, then writes a JSON verdict into <pre id=selftest>;
  3. independently of the page: every uncaught exception, console.error/assert, error log entry and
     any network request other than file:/data:/about: fails the test; the number of scatter points
     must equal the count computed here from report.json; "next" must change the drawn iteration;
  4. checks the first screen: at 1400 x 900 the verdict, the counts, the heat map and the speed plot
     lie within the first 1,200 px of the page; at 1280 px wide, with every folded block open, the
     page does not scroll sideways and no table is cut off (a wide table scrolls in its own box);
     and what the page says against report.json (check_data_views): counts in every heat-map
     cell's hover text, grey cells without a judged case, invalid answers, plugin files;
  5. checks the variants' colours and markers: one pair per variant, the same on the report page,
     the case page and the explain page, no two variants of the report with the same pair, and
     two with the same marker well apart in colour;
  6. takes screenshots (test artefacts): the first screen, the whole page, the first viewer;
  7. does the same for the single-case viewer page (gjk_html::renderCase) of the report's first worst
     case, as `gjk-validate explain --html` writes it.

usage: browser_check.py --chromium PATH --render report_render --report REPORT.json --out DIR
                        [--screenshot PNG] [--screenshot-1280 PNG] [--case-screenshot PNG]
                        [--expect-index HTML] [--campaign EXE ARG... -- | --generate CMD ARG... --]
Exit status: 0 pass, 1 fail, 77 Chromium missing (CTest SKIP_RETURN_CODE); with GJK2D_REQUIRE_ALL=1
(CI) a missing Chromium is a failure, 1.
"""
import argparse
import base64
import fcntl
import json
import math
import os
import queue
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

TIMEOUT = 60.0


def log(*a):
    print("browser_check:", *a, flush=True)


class Chromium:
    """A headless Chromium driven over the DevTools protocol on a pipe (fds 3 and 4)."""

    def __init__(self, exe, workdir):
        self.profile = tempfile.mkdtemp(prefix="gjk-chromium-", dir=workdir)
        self.stderr_path = Path(workdir) / "chromium-stderr.txt"
        to_chrome_r, to_chrome_w = os.pipe()
        from_chrome_r, from_chrome_w = os.pipe()
        # Keep our ends away from 3 and 4, which the child's dup2 below overwrites.
        fds = [
            fcntl.fcntl(fd, fcntl.F_DUPFD_CLOEXEC, 10)
            for fd in (to_chrome_r, to_chrome_w, from_chrome_r, from_chrome_w)
        ]
        for fd in (to_chrome_r, to_chrome_w, from_chrome_r, from_chrome_w):
            os.close(fd)
        child_in, self.wfd, self.rfd, child_out = fds

        def setup_child():
            os.dup2(child_in, 3)
            os.dup2(child_out, 4)

        args = [
            exe,
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--no-default-browser-check",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--disable-extensions",
            "--disable-dev-shm-usage",
            "--hide-scrollbars",
            "--mute-audio",
            "--enable-logging=stderr",
            "--v=0",
            "--user-data-dir=" + self.profile,
            "--remote-debugging-pipe",
            "--window-size=1400,1000",
            "about:blank",
        ]
        self.stderr = open(self.stderr_path, "wb")
        self.proc = subprocess.Popen(
            args,
            stdin=subprocess.DEVNULL,
            stdout=self.stderr,
            stderr=self.stderr,
            preexec_fn=setup_child,
            close_fds=False,
        )
        os.close(child_in)
        os.close(child_out)
        self.next_id = 0
        self.inbox = queue.Queue()
        self.events = []
        self.reader = threading.Thread(target=self._read, daemon=True)
        self.reader.start()

    def _read(self):
        buf = b""
        while True:
            try:
                chunk = os.read(self.rfd, 1 << 16)
            except OSError:
                chunk = b""
            if not chunk:
                self.inbox.put(None)
                return
            buf += chunk
            while b"\0" in buf:
                msg, buf = buf.split(b"\0", 1)
                self.inbox.put(json.loads(msg))

    def send(self, method, params=None, session=None, timeout=TIMEOUT):
        self.next_id += 1
        mid = self.next_id
        msg = {"id": mid, "method": method, "params": params or {}}
        if session:
            msg["sessionId"] = session
        os.write(self.wfd, json.dumps(msg).encode() + b"\0")
        deadline = time.monotonic() + timeout
        while True:
            m = self._get(deadline, method)
            if m.get("id") == mid:
                if "error" in m:
                    raise RuntimeError(f'{method}: {m["error"]}')
                return m.get("result", {})
            self.events.append(m)

    def _get(self, deadline, what):
        left = deadline - time.monotonic()
        if left <= 0:
            raise TimeoutError(f"no answer from Chromium for {what}")
        try:
            m = self.inbox.get(timeout=left)
        except queue.Empty:
            raise TimeoutError(f"no answer from Chromium for {what}")
        if m is None:
            raise RuntimeError("Chromium closed the DevTools pipe (crashed?)")
        return m

    def wait_event(self, method, session, timeout=TIMEOUT):
        for i, e in enumerate(self.events):
            if e.get("method") == method and e.get("sessionId") == session:
                del self.events[i]
                return e
        deadline = time.monotonic() + timeout
        while True:
            m = self._get(deadline, method)
            if m.get("method") == method and m.get("sessionId") == session:
                return m
            self.events.append(m)

    def drain(self):
        while True:
            try:
                m = self.inbox.get_nowait()
            except queue.Empty:
                return
            if m is not None:
                self.events.append(m)

    def close(self):
        try:
            self.send("Browser.close", timeout=5)
        except Exception:
            pass
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
        for fd in (self.wfd, self.rfd):
            try:
                os.close(fd)
            except OSError:
                pass
        self.stderr.close()
        shutil.rmtree(self.profile, ignore_errors=True)


class Page:
    def __init__(self, browser, width=1400, height=1000):
        self.b = browser
        target = browser.send("Target.createTarget", {"url": "about:blank"})["targetId"]
        self.session = browser.send("Target.attachToTarget", {"targetId": target, "flatten": True})[
            "sessionId"
        ]
        for domain in ("Runtime", "Log", "Page", "Network"):
            self.cmd(domain + ".enable")
        self.cmd(
            "Emulation.setDeviceMetricsOverride",
            {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False},
        )
        self.mark = len(browser.events)

    def cmd(self, method, params=None):
        return self.b.send(method, params, self.session)

    def load(self, url):
        self.b.drain()
        self.mark = len(self.b.events)
        self.cmd("Page.navigate", {"url": url})
        self.b.wait_event("Page.loadEventFired", self.session)

    def eval(self, expr):
        r = self.cmd(
            "Runtime.evaluate", {"expression": expr, "returnByValue": True, "awaitPromise": True}
        )
        if "exceptionDetails" in r:
            raise RuntimeError(f'evaluating {expr[:60]!r}: {r["exceptionDetails"]}')
        return r["result"].get("value")

    def wait_for(self, expr, timeout=TIMEOUT):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            v = self.eval(expr)
            if v:
                return v
            time.sleep(0.05)
        raise TimeoutError(f"waiting for {expr}")

    def problems(self):
        """Errors the browser saw since the last load: exceptions, console errors, error logs, network."""
        self.b.drain()
        out = []
        for e in self.b.events[self.mark :]:
            if e.get("sessionId") != self.session:
                continue
            m, p = e.get("method"), e.get("params", {})
            if m == "Runtime.exceptionThrown":
                d = p.get("exceptionDetails", {})
                out.append(
                    "uncaught exception: "
                    + str(d.get("exception", {}).get("description") or d.get("text"))
                )
            elif m == "Runtime.consoleAPICalled" and p.get("type") in ("error", "assert"):
                out.append(
                    "console."
                    + p["type"]
                    + ": "
                    + " ".join(
                        str(a.get("value", a.get("description", ""))) for a in p.get("args", [])
                    )
                )
            elif m == "Log.entryAdded" and p.get("entry", {}).get("level") == "error":
                out.append(
                    "log error: " + p["entry"].get("text", "") + " " + p["entry"].get("url", "")
                )
            elif m == "Network.requestWillBeSent":
                url = p.get("request", {}).get("url", "")
                if not url.split(":", 1)[0] in ("file", "data", "about", "blob"):
                    out.append("network request (the page must be self-contained): " + url)
            elif m == "Network.loadingFailed":
                out.append("failed to load: " + str(p.get("errorText")))
        return out

    def screenshot(self, path, clip=None, full=False):
        params = {"format": "png"}
        if full:
            m = self.cmd("Page.getLayoutMetrics")
            size = m.get("cssContentSize") or m.get("contentSize")
            clip = {"x": 0, "y": 0, "width": size["width"], "height": min(size["height"], 16000)}
        if clip:
            params["clip"] = dict(clip, scale=1)
            params["captureBeyondViewport"] = True
        data = self.cmd("Page.captureScreenshot", params)["data"]
        Path(path).parent.mkdir(parents=True, exist_ok=True)
        Path(path).write_bytes(base64.b64decode(data))
        log("screenshot", path)

    def element_clip(self, selector, pad=8):
        r = self.eval(
            f"""(function() {{ var e = document.querySelector({json.dumps(selector)}); if (!e) return null;
            var r = e.getBoundingClientRect(); return [r.left + scrollX, r.top + scrollY, r.width, r.height]; }})()"""
        )
        if not r:
            return None
        return {
            "x": max(0, r[0] - pad),
            "y": max(0, r[1] - pad),
            "width": r[2] + 2 * pad,
            "height": r[3] + 2 * pad,
        }


# --- What the page must show, computed here from the data ---------------------------------------


def num(v):
    if isinstance(v, bool):
        return math.nan
    if isinstance(v, (int, float)):
        return float(v)
    if isinstance(v, str):
        s = v.strip().lower()
        if s in ("inf", "+inf", "infinity"):
            return math.inf
        if s in ("-inf", "-infinity"):
            return -math.inf
        try:
            return float(s) if s not in ("nan", "") else math.nan
        except ValueError:
            return math.nan
    return math.nan


def _eligible(st):
    """A family x variant the speed plot can draw: a positive, finite ns_per_query and a normalised error."""
    if not isinstance(st, dict):
        return False
    ns = num(st.get("ns_per_query"))
    h = (st.get("errors") or {}).get("normalized") if isinstance(st.get("errors"), dict) else None
    return (
        math.isfinite(ns)
        and ns > 0
        and isinstance(h, dict)
        and (math.isfinite(num(h.get("p99"))) or math.isfinite(num(h.get("max"))))
    )


def expected_scatter_points(report):
    """The speed plot starts on `random` (else the family with most cases that has points): one point
    per variant of that family with a timing and a normalised error. Returns (family, points)."""
    fams = report.get("families") if isinstance(report, dict) else None
    fams = [f for f in (fams if isinstance(fams, list) else []) if isinstance(f, dict)]

    def points(f):
        vs = f.get("variants")
        return sum(1 for st in (vs.values() if isinstance(vs, dict) else []) if _eligible(st))

    with_points = [f for f in fams if points(f) > 0]
    if not with_points:
        return None, 0
    start = next((f for f in with_points if str(f.get("name")) == "random"), None)
    if start is None:
        start = sorted(
            with_points,
            key=lambda f: -num(f.get("cases")) if math.isfinite(num(f.get("cases"))) else 0,
        )[0]
    return str(start.get("name")), points(start)


# Where the first screen's parts are (page coordinates, CSS px), at the current viewport.
FIRST_SCREEN_PROBE = """(function() {
  var out = {};
  [['verdict', '#verdict'], ['counts', '#counts'], ['heat map', '#heatmap'], ['speed plot', '#scatter']].forEach(function (x) {
    var e = document.querySelector(x[1]);
    if (!e) { out[x[0]] = null; return; }
    var r = e.getBoundingClientRect();
    out[x[0]] = {top: Math.round(r.top + scrollY), bottom: Math.round(r.bottom + scrollY), left: Math.round(r.left), right: Math.round(r.right)};
  });
  return out;
})()"""

# With every folded block open: the page must not scroll sideways, and a table wider than its place
# must sit in a box that scrolls (overflow-x auto or scroll) within the window: a table scrolls or
# wraps inside its own box, never the page, and is never cut off.
OVERFLOW_PROBE = """(function() {
  document.querySelectorAll('details').forEach(function (d) { d.open = true; });
  var width = document.documentElement.clientWidth, bad = [], scrolling = [];
  function scroller(e) {
    for (var p = e.parentElement; p && p !== document.body; p = p.parentElement) {
      var o = getComputedStyle(p).overflowX;
      if (o === 'auto' || o === 'scroll') return p;
    }
    return null;
  }
  document.querySelectorAll('table').forEach(function (t, i) {
    var r = t.getBoundingClientRect(), box = t.parentElement.getBoundingClientRect();
    if (r.width === 0) return;
    var name = (t.className || 'table') + ' #' + i, sc = scroller(t);
    if (sc) {
      var b = sc.getBoundingClientRect();
      if (b.right > width + 0.5) bad.push(name + ': its scroll box ends at ' + Math.round(b.right) + ' (page ' + width + ')');
      if (sc.scrollWidth > sc.clientWidth + 1) scrolling.push(name + ' (' + Math.round(r.width) + ' px in ' + Math.round(b.width) + ')');
    } else if (r.right > width + 0.5 || r.right > box.right + 0.5) {
      bad.push(name + ' right ' + Math.round(r.right) + ' in ' + Math.round(box.right) + ' (page ' + width + '), in no scroll box');
    }
  });
  var page = document.documentElement.scrollWidth;
  document.querySelectorAll('details').forEach(function (d) { d.open = false; });
  return {page: page, width: width, bad: bad, scrolling: scrolling};
})()"""

# Each variant as drawn: every element with data-marker (colour dots in tables and legends, the heat
# map's column heads, the speed plot's legend) gives its marker and its fill (or its shape's).
STYLE_PROBE = """(function() {
  var seen = {}, clash = [];
  document.querySelectorAll('[data-variant][data-marker]').forEach(function (e) {
    var shape = e.tagName.toLowerCase() === 'svg' ? e.querySelector('.vmark-shape') : e;
    var style = getComputedStyle(shape).fill + ' ' + e.getAttribute('data-marker'), name = e.getAttribute('data-variant');
    if (name in seen && seen[name] !== style) clash.push(name + ': ' + seen[name] + ' and ' + style);
    seen[name] = style;
  });
  return {styles: seen, clash: clash};
})()"""

# What the heat map, the family tables, the variants table and the viewers say, for check_data_views.
VIEWS_PROBE = """(function() {
  var out = {cells: [], invalid: [], rows: [], penetration: [], arrows: 0, variantsText: '', counts: ''};
  document.querySelectorAll('#heatmap .hm-cell').forEach(function (c) {
    out.cells.push({family: c.getAttribute('data-family'), variant: c.getAttribute('data-variant'), kind: c.getAttribute('data-kind'),
      fill: c.querySelector('rect').getAttribute('fill'), tip: c.querySelector('title').textContent});
  });
  document.querySelectorAll('details.family').forEach(function (d) {
    d.querySelectorAll('tr[data-variant] td.invalid-cell').forEach(function (td) {
      out.invalid.push({family: d.getAttribute('data-family'), variant: td.parentElement.getAttribute('data-variant'),
        count: td.getAttribute('data-invalid'), text: td.textContent, title: td.getAttribute('title') || ''});
    });
  });
  document.querySelectorAll('details.family').forEach(function (d) {
    d.querySelectorAll('tr.penetration-row').forEach(function (tr) {
      out.penetration.push({family: d.getAttribute('data-family'), variant: tr.getAttribute('data-variant'),
        cells: Array.prototype.map.call(tr.children, function (td) { return td.textContent; })});
    });
  });
  out.arrows = document.querySelectorAll('.translation-arrow').length;
  document.querySelectorAll('.viewer').forEach(function (v) {
    v.querySelectorAll('table.results tr[data-variant]').forEach(function (tr) {
      var wb = tr.querySelector('td.witness-bound');
      out.rows.push({case: v.getAttribute('data-case'), variant: tr.getAttribute('data-variant'),
        cls: tr.lastElementChild.textContent, witnessBound: wb ? wb.textContent : null});
    });
  });
  out.timing = {};
  document.querySelectorAll('#context li.timing-note').forEach(function (li) {
    li.getAttribute('data-timing-of').split('\\n').forEach(function (n) { out.timing[n] = li.textContent; });
  });
  var ctx = document.getElementById('context');
  out.variantsText = ctx ? ctx.textContent : '';
  var counts = document.getElementById('counts');
  out.counts = counts ? counts.textContent : '';
  return out;
})()"""


def rgb(text):
    """'rgb(31, 95, 168)' -> (31, 95, 168)."""
    inner = text[text.index("(") + 1 : text.index(")")]
    return tuple(int(float(x)) for x in inner.split(",")[:3])


STEP_PROBE = """(function() {
  var v = document.querySelector('.viewer');
  if (!v) return {none: true};
  var layer = function () { return v.querySelector('.minkowski-panel .layer'); };
  var r = {before: v.getAttribute('data-step'), drawnBefore: layer().getAttribute('data-step'),
           steps: Number(v.querySelector('.step-slider').max) + 1, svgBefore: v.querySelector('.minkowski-panel').innerHTML.length};
  var svg0 = v.querySelector('.minkowski-panel').innerHTML;
  v.querySelector('.step-next').click();
  r.after = v.getAttribute('data-step');
  r.drawnAfter = layer().getAttribute('data-step');
  r.svgChanged = v.querySelector('.minkowski-panel').innerHTML !== svg0;
  r.label = v.querySelector('.step-label').textContent;
  return r;
})()"""


def check_page(
    browser,
    html,
    out_dir,
    kind,
    report=None,
    screenshot=None,
    viewer_screenshot=None,
    label=None,
    screenshot_1280=None,
):
    """Loads html (kind 'report' or 'case' page); returns a list of failures."""
    fails = []
    label = label or kind
    url = Path(html).resolve().as_uri()
    page = Page(browser, 1400, 900)  # the first screen of a laptop
    # 1. The page's self-test.
    page.load(url + "#selftest")
    page.wait_for(
        "document.getElementById('selftest') && document.getElementById('selftest').getAttribute('data-done') === '1'"
    )
    verdict = json.loads(page.eval("document.getElementById('selftest').textContent"))
    (Path(out_dir) / f"{label}-selftest.json").write_text(json.dumps(verdict, indent=1))
    for name, c in verdict.get("checks", {}).items():
        if not c.get("ok"):
            fails.append(f'{label}: self-test check "{name}" failed: {c.get("detail")}')
    for e in verdict.get("errors", []):
        fails.append(f"{label}: page error: {e}")
    if not verdict.get("ok") and not fails:
        fails.append(f"{label}: self-test verdict not ok: {verdict}")
    fails += [f"{label} (#selftest): {p}" for p in page.problems()]
    log(
        f"{label}: self-test",
        "ok" if verdict.get("ok") else "FAILED",
        {k: verdict.get(k) for k in ("scatterPoints", "scatterExpected", "viewers")},
    )

    # 2. A clean load, checked from outside the page.
    page.load(url)
    page.wait_for(
        "document.querySelector('#app') && document.querySelector('#app').children.length > 0"
    )
    if kind == "report":
        drawn = page.eval("document.querySelectorAll('#scatter .pt').length")
        family, want = expected_scatter_points(report)
        log(
            f"report: speed plot on {family!r}: points drawn {drawn}, expected from report.json {want}"
        )
        if drawn != want:
            fails.append(
                f"report: the speed plot has {drawn} points, report.json has {want} variants to plot in family {family!r}"
            )
        if (
            family is not None
            and page.eval("document.querySelector('select.speed-family').value") != family
        ):
            fails.append(f"report: the speed plot does not start on family {family!r}")
        # The first screen answers the questions: verdict, heat map and speed plot within the first
        # 1,200 px at 1400 x 900.
        pos = page.eval(FIRST_SCREEN_PROBE)
        log("report: first screen at 1400 x 900 (page px):", json.dumps(pos))
        (Path(out_dir) / f"{label}-first-screen.json").write_text(json.dumps(pos, indent=1))
        for part in ("verdict", "counts", "heat map") + (("speed plot",) if want else ()):
            p = pos.get(part)
            if not p:
                fails.append(f"report: no {part} on the page")
            elif p["top"] < 0 or p["bottom"] > 1200:
                fails.append(f"report: the {part} is not within the first 1,200 px: {p}")
        # At 1280 px the page does not scroll sideways, and no table is cut off.
        page.cmd(
            "Emulation.setDeviceMetricsOverride",
            {"width": 1280, "height": 900, "deviceScaleFactor": 1, "mobile": False},
        )
        time.sleep(0.2)
        over = page.eval(OVERFLOW_PROBE)
        log(
            "report: at 1280 px: page width",
            over["page"],
            "tables cut off:",
            len(over["bad"]),
            "tables scrolling in their own box:",
            over["scrolling"],
        )
        if over["page"] > 1280 or over["page"] > over["width"] or over["bad"]:
            fails.append(
                f"report: at 1280 px the page scrolls sideways or a table is cut off: {over}"
            )
        if screenshot_1280:
            page.eval("window.scrollTo(0, 0)")
            page.screenshot(screenshot_1280)
        page.cmd(
            "Emulation.setDeviceMetricsOverride",
            {"width": 1400, "height": 900, "deviceScaleFactor": 1, "mobile": False},
        )
        time.sleep(0.2)
        fams = (
            [str(f.get("name")) for f in report.get("families", []) if isinstance(f, dict)]
            if isinstance(report, dict)
            else []
        )
        cards = (
            page.eval(
                "Array.prototype.map.call(document.querySelectorAll('.family h3'), function (e) { return e.textContent; })"
            )
            or []
        )
        for f in fams:
            if not any(c.startswith(f) for c in cards):
                fails.append(f"report: family {f!r} has no section on the page")
        if page.eval("document.querySelectorAll('.error-box').length"):
            fails.append(
                "report: the page shows an error box: "
                + str(page.eval("document.querySelector('.error-box').textContent"))
            )
        fails += check_data_views(page.eval(VIEWS_PROBE), report)
    styles = page.eval(STYLE_PROBE)
    for c in styles["clash"]:
        fails.append(f"{label}: a variant drawn in two colours or markers: {c}")
    if screenshot:
        # The first screen, as a reader opens the page (1400 x 900), and the whole page.
        page.cmd(
            "Emulation.setDeviceMetricsOverride",
            {"width": 1400, "height": 900, "deviceScaleFactor": 1, "mobile": False},
        )
        time.sleep(0.2)
        page.eval("window.scrollTo(0, 0)")
        page.screenshot(screenshot)
        full = Path(screenshot).with_name(Path(screenshot).stem + "-full.png")
        page.screenshot(full, full=True)
    want_viewer = kind == "case" or (
        isinstance(report, dict)
        and isinstance(report.get("worst"), list)
        and len(report["worst"]) > 0
    )
    if want_viewer:
        probe = page.eval(STEP_PROBE)
        log(f"{label}: step probe", probe)
        if probe.get("none"):
            fails.append(f"{label}: no iteration viewer on the page")
        elif probe["steps"] > 1:
            if not (
                probe["after"] == str(int(probe["before"]) + 1)
                and probe["drawnAfter"] == probe["after"]
                and probe["svgChanged"]
            ):
                fails.append(f'{label}: "next" did not change the drawn iteration: {probe}')
        if viewer_screenshot and not probe.get("none"):
            page.eval("document.querySelector('.viewer .step-next').click()")
            clip = page.element_clip(".viewer")
            if clip:
                page.screenshot(viewer_screenshot, clip=clip)
    fails += [f"{label}: {p}" for p in page.problems()]
    return fails, styles["styles"]


def check_styles(report, page_styles):
    """Every variant of the report drawn with one colour and marker, the same on every page; no two
    variants with the same colour and marker; two with the same marker well apart in colour (RGB
    distance at least 40)."""
    fails = []
    merged = {}
    for label, styles in page_styles.items():
        for name, st in styles.items():
            merged.setdefault(name, {})[label] = st
    for name, by_page in merged.items():
        if len(set(by_page.values())) > 1:
            fails.append(
                f"variant {name!r} has different colours or markers on different pages: {by_page}"
            )
    names = (
        [str(v.get("name")) for v in (report.get("variants") or []) if isinstance(v, dict)]
        if isinstance(report, dict)
        else []
    )
    report_styles = page_styles.get("report", {})
    missing = [n for n in names if n not in report_styles]
    if missing:
        fails.append(f"report: no colour and marker drawn for the variants {missing}")
    drawn = {}
    for n in names:
        if n in report_styles:
            color, marker = report_styles[n].rsplit(" ", 1)
            drawn[n] = (rgb(color), marker)
    order = sorted(drawn)
    for i, a in enumerate(order):
        for b in order[i + 1 :]:
            (ca, ma), (cb, mb) = drawn[a], drawn[b]
            if ma == mb and math.dist(ca, cb) < 40:
                fails.append(
                    f"variants {a!r} and {b!r} have the same marker ({ma}) and (nearly) the same colour: {ca} and {cb}"
                )
    log(
        f"variant styles: {len(drawn)} variants, {len(set(drawn.values()))} distinct colour and marker pairs,",
        f"{len(set(c for c, _ in drawn.values()))} colours, {len(set(m for _, m in drawn.values()))} markers on the report page;",
        "pages compared:",
        ", ".join(sorted(page_styles)),
    )
    return fails


def count_of(st, key):
    """A Stats count; a field an older report lacks counts 0 (as on the page)."""
    v = num(st.get(key)) if isinstance(st, dict) else math.nan
    return int(v) if math.isfinite(v) else 0


def plural(n, one):
    return f"{n:,} {one}" + ("" if n == 1 else "s")


NOT_RUN_GREY = "#ece9e3"


def check_data_views(views, report):
    """What the page says about each family x variant, against report.json: a cell with no judged case
    is grey and says why; every cell's hover text gives cases, refused, skipped and invalid; the family
    tables show the invalid counts and reasons; the viewers show an invalid answer's reason and its
    witness bound; the variants table names each plugin's file; the header counts invalid answers.
    """
    fails = []
    fams = {str(f.get("name")): f for f in report.get("families", []) if isinstance(f, dict)}
    cells = {(c["family"], c["variant"]): c for c in views["cells"]}
    checked = {
        "grey": 0,
        "tips": 0,
        "invalid": 0,
        "viewer": 0,
        "plugin files": 0,
        "context plugins": 0,
    }
    for (fam, var), c in cells.items():
        st = (fams.get(fam, {}).get("variants") or {}).get(var)
        k = {key: count_of(st, key) for key in ("cases", "refused", "skipped", "invalid")}
        want = f"{plural(k['cases'], 'case')}, {k['refused']:,} refused, {k['skipped']:,} skipped, {k['invalid']:,} invalid"
        if want not in c["tip"]:
            fails.append(
                f'heat map {fam} / {var}: the hover text does not say {want!r}: {c["tip"]!r}'
            )
        checked["tips"] += 1
        if isinstance(st, dict) and k["cases"] == 0:
            checked["grey"] += 1
            if c["fill"] != NOT_RUN_GREY or c["kind"] != "notrun":
                fails.append(
                    f'heat map {fam} / {var}: no judged case, but the cell is {c["fill"]} ({c["kind"]}), not the grey of "not run"'
                )
            if (
                k["refused"] > 0
                and "refused by the implementation" not in c["tip"]
                and "refused or skipped" not in c["tip"]
            ):
                fails.append(
                    f'heat map {fam} / {var}: every case refused, but the hover text does not say so: {c["tip"]!r}'
                )
    for row in views["invalid"]:
        st = (fams.get(row["family"], {}).get("variants") or {}).get(row["variant"])
        n = count_of(st, "invalid")
        reasons = [
            f'{v:,} {r.replace("_", " ")}'
            for r, v in ((st or {}).get("invalid_reasons") or {}).items()
            if num(v) > 0
        ]
        checked["invalid"] += 1
        if row["count"] != str(n) or not row["text"].startswith(f"{n:,}"):
            fails.append(
                f'family {row["family"]} / {row["variant"]}: invalid shown as {row["text"]!r}, report.json has {n}'
            )
        for r in reasons:
            if r not in row["title"] or r not in row["text"]:
                fails.append(
                    f'family {row["family"]} / {row["variant"]}: invalid reason {r!r} not shown: {row}'
                )
    want_rows = sum(len(f.get("variants") or {}) for f in fams.values())
    if len(views["invalid"]) != want_rows:
        fails.append(
            f'the family tables have {len(views["invalid"])} invalid cells, report.json has {want_rows} family x variant statistics'
        )
    worst = {str(w.get("name")): w for w in report.get("worst") or [] if isinstance(w, dict)}
    for row in views["rows"]:
        r = ((worst.get(row["case"]) or {}).get("variants") or {}).get(row["variant"]) or {}
        if r.get("invalid") and f"invalid: {str(r['invalid']).replace('_', ' ')}" not in row["cls"]:
            fails.append(
                f'viewer {row["case"]} / {row["variant"]}: invalid answer ({r["invalid"]}) not shown: {row["cls"]!r}'
            )
        if r.get("witness_bound") is not None:
            checked["viewer"] += 1
            if row["witnessBound"] in (None, "—"):
                fails.append(
                    f'viewer {row["case"]} / {row["variant"]}: witness bound {r["witness_bound"]} not shown'
                )
    for v in report.get("variants") or []:
        path = (
            (v.get("plugin") or {}).get("path")
            if isinstance(v, dict) and isinstance(v.get("plugin"), dict)
            else None
        )
        if path:
            checked["plugin files"] += 1
            if path not in views["variantsText"]:
                fails.append(
                    f'the variants table does not name the plugin file {path!r} of {v.get("name")!r}'
                )
    for p in (report.get("context") or {}).get("plugins") or []:  # context.plugins (issue 32)
        checked["context plugins"] += 1
        for part in [p.get("file"), p.get("kind"), p.get("library")] + list(
            p.get("variants") or []
        ):
            if part and str(part) not in views["variantsText"]:
                fails.append(
                    f'the context section does not show {part!r} of the plugin {p.get("file")!r}'
                )
    # How the truths and witness distances were decided (issue 34), summed here from report.json.
    types = {}
    for v in report.get("variants") or []:
        if isinstance(v, dict) and v.get("type") and v.get("name") and v["type"] not in types:
            sts = [(f.get("variants") or {}).get(v["name"]) for f in fams.values()]
            sts = [st for st in sts if isinstance(st, dict) and isinstance(st.get("truth"), dict)]
            cases = sum(count_of(st, "cases") for st in sts)
            if cases:
                types[v["type"]] = (cases, sum(count_of(st["truth"], "gmp_route") for st in sts))
    for t, (cases, gmp) in types.items():
        checked["truth"] = checked.get("truth", 0) + 1
        want = f"Truth of the {t} input" + f"GMP route on {gmp:,} of {plural(cases, 'case')}"
        if want not in views["variantsText"]:
            fails.append(f"the context section does not say {want!r}")
    points = sum(
        count_of(st, "witness_points")
        for f in fams.values()
        for st in (f.get("variants") or {}).values()
    )
    wexact = sum(
        count_of(st, "witness_exact")
        for f in fams.values()
        for st in (f.get("variants") or {}).values()
    )
    if points:
        checked["witness"] = 1
        want = f"Witness checks{points:,} points measured, {wexact:,} by the exact route"
        if want not in views["variantsText"]:
            fails.append(f"the context section does not say {want!r}")
    for v in (
        report.get("variants") or []
    ):  # what ns/query includes, and the preparation figure (issue 50)
        t = v.get("timing") if isinstance(v, dict) else None
        if not isinstance(t, dict):
            continue
        checked["timing"] = checked.get("timing", 0) + 1
        text = views["timing"].get(str(v.get("name")))
        prepared = any(
            num((f.get("variants") or {}).get(v["name"], {}).get("prepare_ns_per_shape")) > 0
            for f in fams.values()
        )
        own = t.get("preparation") == "none" and "plugin" not in v
        form = t.get("prepared") if isinstance(t.get("prepared"), dict) else None
        if own and form is None:  # a report written before timing.prepared
            want = ["no preparation: the plain query takes the points as given"]
        elif own and not form.get("timed"):
            want = ["the plain query, the points as given; " + str(form.get("includes"))]
        elif own:  # both figures, weighted by the families' cases, and the preparation
            want = [
                "plain: ",
                " ns/query, the points as given; prepared: ",
                str(form.get("includes")),
            ]
            want += ["ns/shape to prepare"] if prepared else []
            fails += check_own_figures(v["name"], text or "", fams)
        else:
            want = (
                [t.get("includes")]
                + (["timed by the adapter"] if t.get("timed_by") == "adapter" else [])
                + (["ns/shape to prepare"] if prepared else [])
            )
        if text is None or any(w not in text for w in want):
            fails.append(
                f'the context does not say what ns/query of {v.get("name")!r} includes ({want}): {text!r}'
            )
        elif not prepared and "ns/shape to prepare" in text:
            fails.append(
                f'the context gives {v.get("name")!r} a preparation figure it does not have: {text!r}'
            )
    total_invalid = sum(
        count_of(st, "invalid") for f in fams.values() for st in (f.get("variants") or {}).values()
    )
    if total_invalid and f"{total_invalid:,} invalid answer" not in views["counts"]:
        fails.append(
            f'the header does not count the {total_invalid} invalid answers: {views["counts"]!r}'
        )
    fails += check_penetration(views, report, fams)
    log("data views checked:", checked, f"(invalid answers in all: {total_invalid})")
    return fails


def weighted(name, key, fams):
    "A figure of the variant's family stats weighted by the families' cases; None when none has it."
    pairs = [
        (num(st.get(key)), num(st.get("cases")))
        for f in fams.values()
        for st in [(f.get("variants") or {}).get(name) or {}]
        if num(st.get(key)) == num(st.get(key)) and num(st.get("cases")) > 0
    ]
    cases = sum(n for _, n in pairs)
    return sum(x * n for x, n in pairs) / cases if cases else None


def check_own_figures(name, text, fams):
    """gjk2d's own variant with a prepared form: the context gives its plain and prepared ns/query
    (ns_per_query and prepared_ns_per_query, weighted by the families' cases) to three digits, and
    the prepared figure is there only when the report has it."""
    fails = []
    for label, key in (("plain", "ns_per_query"), ("prepared", "prepared_ns_per_query")):
        m = re.search(label + r": ([0-9.,]+|—) ns/query", text)
        want = weighted(name, key, fams)
        shown = float(m.group(1).replace(",", "")) if m and m.group(1) != "—" else None
        if m is None or (want is None) != (shown is None):
            fails.append(f"the context gives {name!r} no {label} ns/query ({want}): {text!r}")
        elif want is not None and abs(shown - want) > 0.005 * want:
            fails.append(f"the context gives {name!r} {label} {shown} ns/query, not {want:.3g}")
    return fails


def check_penetration(views, report, fams):
    """Each family x variant with a penetration block in report.json (a contract whose overlap answer
    is penetration) has its row in the family's penetration table, with its overlapping cases, contract
    violations and verdict; no other variant has one. A viewer whose case overlaps (exact signed
    distance < 0) draws the minimal translation."""
    fails = []
    rows = {(r["family"], r["variant"]): r["cells"] for r in views["penetration"]}
    want = {}
    for fam, f in fams.items():
        for var, st in (f.get("variants") or {}).items():
            if isinstance(st, dict) and isinstance(st.get("penetration"), dict):
                want[(fam, var)] = st["penetration"]
    for key, p in want.items():
        cells = rows.get(key)
        if cells is None:
            fails.append(
                f"penetration {key[0]} / {key[1]}: no row in the family's penetration table"
            )
            continue
        shown = re.match(r"[\d,]*", cells[2]).group(0)  # the count, before the worst's reason
        if (
            cells[1] != f"{count_of(p, 'cases'):,}"
            or shown != f"{count_of(p, 'contract_violations'):,}"
        ):
            fails.append(
                f'penetration {key[0]} / {key[1]}: the row says {cells[1:3]!r}, report.json {p.get("cases")} cases, {p.get("contract_violations")} violations'
            )
        verdict = cells[-1]
        if count_of(p, "contract_violations") > 0 and verdict in ("pass", "keeps its contract"):
            fails.append(
                f'penetration {key[0]} / {key[1]}: {p.get("contract_violations")} violations but the verdict says {verdict!r}'
            )
    for key in rows:
        if key not in want:
            fails.append(
                f"penetration {key[0]} / {key[1]}: a row without a penetration block in report.json"
            )
    overlapping = [
        w
        for w in (report.get("worst") or [])
        if isinstance(w, dict)
        and isinstance((w.get("exact") or {}).get("signed_distance"), (int, float))
        and w["exact"]["signed_distance"] < 0
    ]
    if overlapping and views["arrows"] == 0:
        fails.append(
            f"{len(overlapping)} worst case(s) overlap (exact signed distance < 0) but no minimal translation is drawn"
        )
    log(
        f"penetration checked: {len(want)} family x variant blocks, {len(overlapping)} overlapping worst case(s), "
        f'{views["arrows"]} translation arrow(s)'
    )
    return fails


def explain_page(exe, report, out):
    """Runs `gjk-validate explain ... --html` for the report's first worst case from a generated family."""
    worst = [
        w
        for w in (report.get("worst") or [])
        if isinstance(w, dict) and w.get("name") and w.get("family")
    ]
    worst = [w for w in worst if not str(w["family"]).startswith("file:")]
    if not worst:
        raise RuntimeError("the report has no worst case from a generated family to explain")
    w = worst[0]
    ctx = report.get("context") or {}
    spec = str(w["family"])
    for inp in ctx.get("inputs") or []:
        if isinstance(inp, dict) and inp.get("family") == spec and inp.get("count"):
            spec += ":" + str(inp["count"])
    html = out / "explain.html"
    cmd = [
        exe,
        "explain",
        "--family",
        spec,
        "--seed",
        str(ctx.get("seed", 1)),
        "--name",
        str(w["name"]),
        "--html",
        str(html),
    ]
    log("explain:", " ".join(cmd))
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=300)
    (out / "explain-output.txt").write_bytes(r.stdout)
    if r.returncode not in (0, 1) or not html.is_file():
        raise RuntimeError(
            f"exit status {r.returncode}, no page written: "
            + r.stdout.decode(errors="replace")[-1500:]
        )
    return html


def main(argv):
    campaign = None
    if (
        "--campaign" in argv or "--generate" in argv
    ):  # --generate: a command that writes the report (a fixture)
        i = argv.index("--campaign") if "--campaign" in argv else argv.index("--generate")
        try:
            j = argv.index("--", i + 1)
        except ValueError:
            print("browser_check: --campaign needs a closing --", file=sys.stderr)
            return 2
        campaign, argv = argv[i + 1 : j], argv[:i] + argv[j + 1 :]
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("--chromium", default="/usr/bin/chromium")
    ap.add_argument("--render", required=True, help="the report_render program")
    ap.add_argument("--report", required=True, help="report.json")
    ap.add_argument("--out", required=True, help="directory for pages, verdicts and logs")
    ap.add_argument(
        "--expect-index",
        help="use this index.html (written by the runner) instead of rendering one",
    )
    ap.add_argument("--screenshot")
    ap.add_argument("--case-screenshot")
    ap.add_argument("--screenshot-1280", help="the first screen at 1280 x 900")
    ap.add_argument(
        "--explain",
        metavar="GJK_VALIDATE",
        help="also run `GJK_VALIDATE explain --family F --name N --html` on the report's first worst case "
        "and check that page",
    )
    a = ap.parse_args(argv)

    chromium = a.chromium if os.path.isabs(a.chromium) else shutil.which(a.chromium)
    if not chromium or not os.access(chromium, os.X_OK):
        if os.environ.get("GJK2D_REQUIRE_ALL") == "1":  # CI (.ci/run): a skip is a failure
            log(
                f"FAIL: Chromium not found at {a.chromium}, and GJK2D_REQUIRE_ALL=1 makes a skip a failure "
                "(scripts/setup.sh --tests installs it)"
            )
            return 1
        log(f"SKIP: Chromium not found at {a.chromium} (scripts/setup.sh --tests installs it)")
        return 77
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.monotonic()

    if campaign:
        log("campaign:", " ".join(campaign))
        r = subprocess.run(campaign, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=840)
        (out / "campaign-output.txt").write_bytes(r.stdout)
        log(f"campaign exit status {r.returncode} ({time.monotonic() - t0:.1f} s)")
        if r.returncode not in (0, 1):
            sys.stdout.write(r.stdout.decode(errors="replace")[-4000:])
            log(
                "FAIL: the campaign did not finish (exit status 0: passed, 1: failures found; anything else is an error)"
            )
            return 1

    if not Path(a.report).is_file():
        log(f"FAIL: no report at {a.report}")
        return 1
    report = json.loads(Path(a.report).read_text())

    if a.expect_index:
        html = Path(a.expect_index)
        if not html.is_file():
            log(
                f"FAIL: the runner wrote no {html} beside {a.report} (it should write index.html with gjk_html::renderReport)"
            )
            return 1
    else:
        html = out / "index.html"
        subprocess.run([a.render, "report", a.report, str(html)], check=True)
    pages = [("report", "report", html, a.screenshot)]
    if isinstance(report, dict) and isinstance(report.get("worst"), list) and report["worst"]:
        case_html = out / "case.html"
        subprocess.run([a.render, "case", a.report, str(case_html), "0"], check=True)
        pages.append(("case", "case", case_html, a.case_screenshot))

    fails = []
    if a.explain:
        try:
            pages.append(("explain", "case", explain_page(a.explain, report, out), None))
        except Exception as e:
            fails.append(f"explain --html: {e}")

    browser = Chromium(chromium, str(out))
    page_colors = {}
    try:
        for label, kind, path, shot in pages:
            vshot = None
            if kind == "report" and shot:
                vshot = str(Path(shot).with_name(Path(shot).stem + "-viewer.png"))
            try:
                if kind == "case":
                    f, page_colors[label] = check_page(
                        browser, path, out, kind, report=report, viewer_screenshot=shot, label=label
                    )
                else:
                    f, page_colors[label] = check_page(
                        browser,
                        path,
                        out,
                        kind,
                        report=report,
                        screenshot=shot,
                        viewer_screenshot=vshot,
                        label=label,
                        screenshot_1280=a.screenshot_1280,
                    )
                fails += f
            except Exception as e:  # a timeout or a crash is a failure, with the browser's log
                fails.append(f"{label}: {type(e).__name__}: {e}")
        if "report" in page_colors:
            fails += check_styles(report, page_colors)
    finally:
        browser.close()
    log(f"done in {time.monotonic() - t0:.1f} s")
    if fails:
        for f in fails:
            log("FAIL:", f)
        tail = browser.stderr_path.read_text(errors="replace").splitlines()[-30:]
        log("last lines of Chromium's log:\n  " + "\n  ".join(tail))
        return 1
    log("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
