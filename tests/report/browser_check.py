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
     lie within the first 1,200 px of the page; at 1280 px wide, with every folded block open, no
     table is cut off and the page does not scroll sideways;
  5. checks the variants' colours: one per variant, the same on the report page, the case page and
     the explain page, and no two variants of the report (nearly) alike;
  6. takes screenshots (test artefacts): the first screen, the whole page, the first viewer;
  7. does the same for the single-case viewer page (gjk_html::renderCase) of the report's first worst
     case, as `gjk-validate explain --html` writes it.

usage: browser_check.py --chromium PATH --render report_render --report REPORT.json --out DIR
                        [--screenshot PNG] [--case-screenshot PNG] [--expect-index HTML]
                        [--campaign EXE ARG... --]
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
import shutil
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

TIMEOUT = 60.0


def log(*a):
    print('browser_check:', *a, flush=True)


class Chromium:
    """A headless Chromium driven over the DevTools protocol on a pipe (fds 3 and 4)."""

    def __init__(self, exe, workdir):
        self.profile = tempfile.mkdtemp(prefix='gjk-chromium-', dir=workdir)
        self.stderr_path = Path(workdir) / 'chromium-stderr.txt'
        to_chrome_r, to_chrome_w = os.pipe()
        from_chrome_r, from_chrome_w = os.pipe()
        # Keep our ends away from 3 and 4, which the child's dup2 below overwrites.
        fds = [fcntl.fcntl(fd, fcntl.F_DUPFD_CLOEXEC, 10) for fd in (to_chrome_r, to_chrome_w, from_chrome_r, from_chrome_w)]
        for fd in (to_chrome_r, to_chrome_w, from_chrome_r, from_chrome_w):
            os.close(fd)
        child_in, self.wfd, self.rfd, child_out = fds

        def setup_child():
            os.dup2(child_in, 3)
            os.dup2(child_out, 4)

        args = [exe, '--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
                '--no-default-browser-check', '--disable-background-networking', '--disable-component-update',
                '--disable-sync', '--disable-extensions', '--disable-dev-shm-usage', '--hide-scrollbars',
                '--mute-audio', '--enable-logging=stderr', '--v=0', '--user-data-dir=' + self.profile,
                '--remote-debugging-pipe', '--window-size=1400,1000', 'about:blank']
        self.stderr = open(self.stderr_path, 'wb')
        self.proc = subprocess.Popen(args, stdin=subprocess.DEVNULL, stdout=self.stderr, stderr=self.stderr,
                                     preexec_fn=setup_child, close_fds=False)
        os.close(child_in)
        os.close(child_out)
        self.next_id = 0
        self.inbox = queue.Queue()
        self.events = []
        self.reader = threading.Thread(target=self._read, daemon=True)
        self.reader.start()

    def _read(self):
        buf = b''
        while True:
            try:
                chunk = os.read(self.rfd, 1 << 16)
            except OSError:
                chunk = b''
            if not chunk:
                self.inbox.put(None)
                return
            buf += chunk
            while b'\0' in buf:
                msg, buf = buf.split(b'\0', 1)
                self.inbox.put(json.loads(msg))

    def send(self, method, params=None, session=None, timeout=TIMEOUT):
        self.next_id += 1
        mid = self.next_id
        msg = {'id': mid, 'method': method, 'params': params or {}}
        if session:
            msg['sessionId'] = session
        os.write(self.wfd, json.dumps(msg).encode() + b'\0')
        deadline = time.monotonic() + timeout
        while True:
            m = self._get(deadline, method)
            if m.get('id') == mid:
                if 'error' in m:
                    raise RuntimeError(f'{method}: {m["error"]}')
                return m.get('result', {})
            self.events.append(m)

    def _get(self, deadline, what):
        left = deadline - time.monotonic()
        if left <= 0:
            raise TimeoutError(f'no answer from Chromium for {what}')
        try:
            m = self.inbox.get(timeout=left)
        except queue.Empty:
            raise TimeoutError(f'no answer from Chromium for {what}')
        if m is None:
            raise RuntimeError('Chromium closed the DevTools pipe (crashed?)')
        return m

    def wait_event(self, method, session, timeout=TIMEOUT):
        for i, e in enumerate(self.events):
            if e.get('method') == method and e.get('sessionId') == session:
                del self.events[i]
                return e
        deadline = time.monotonic() + timeout
        while True:
            m = self._get(deadline, method)
            if m.get('method') == method and m.get('sessionId') == session:
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
            self.send('Browser.close', timeout=5)
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
        target = browser.send('Target.createTarget', {'url': 'about:blank'})['targetId']
        self.session = browser.send('Target.attachToTarget', {'targetId': target, 'flatten': True})['sessionId']
        for domain in ('Runtime', 'Log', 'Page', 'Network'):
            self.cmd(domain + '.enable')
        self.cmd('Emulation.setDeviceMetricsOverride', {'width': width, 'height': height, 'deviceScaleFactor': 1, 'mobile': False})
        self.mark = len(browser.events)

    def cmd(self, method, params=None):
        return self.b.send(method, params, self.session)

    def load(self, url):
        self.b.drain()
        self.mark = len(self.b.events)
        self.cmd('Page.navigate', {'url': url})
        self.b.wait_event('Page.loadEventFired', self.session)

    def eval(self, expr):
        r = self.cmd('Runtime.evaluate', {'expression': expr, 'returnByValue': True, 'awaitPromise': True})
        if 'exceptionDetails' in r:
            raise RuntimeError(f'evaluating {expr[:60]!r}: {r["exceptionDetails"]}')
        return r['result'].get('value')

    def wait_for(self, expr, timeout=TIMEOUT):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            v = self.eval(expr)
            if v:
                return v
            time.sleep(0.05)
        raise TimeoutError(f'waiting for {expr}')

    def problems(self):
        """Errors the browser saw since the last load: exceptions, console errors, error logs, network."""
        self.b.drain()
        out = []
        for e in self.b.events[self.mark:]:
            if e.get('sessionId') != self.session:
                continue
            m, p = e.get('method'), e.get('params', {})
            if m == 'Runtime.exceptionThrown':
                d = p.get('exceptionDetails', {})
                out.append('uncaught exception: ' + str(d.get('exception', {}).get('description') or d.get('text')))
            elif m == 'Runtime.consoleAPICalled' and p.get('type') in ('error', 'assert'):
                out.append('console.' + p['type'] + ': ' + ' '.join(str(a.get('value', a.get('description', ''))) for a in p.get('args', [])))
            elif m == 'Log.entryAdded' and p.get('entry', {}).get('level') == 'error':
                out.append('log error: ' + p['entry'].get('text', '') + ' ' + p['entry'].get('url', ''))
            elif m == 'Network.requestWillBeSent':
                url = p.get('request', {}).get('url', '')
                if not url.split(':', 1)[0] in ('file', 'data', 'about', 'blob'):
                    out.append('network request (the page must be self-contained): ' + url)
            elif m == 'Network.loadingFailed':
                out.append('failed to load: ' + str(p.get('errorText')))
        return out

    def screenshot(self, path, clip=None, full=False):
        params = {'format': 'png'}
        if full:
            m = self.cmd('Page.getLayoutMetrics')
            size = m.get('cssContentSize') or m.get('contentSize')
            clip = {'x': 0, 'y': 0, 'width': size['width'], 'height': min(size['height'], 16000)}
        if clip:
            params['clip'] = dict(clip, scale=1)
            params['captureBeyondViewport'] = True
        data = self.cmd('Page.captureScreenshot', params)['data']
        Path(path).parent.mkdir(parents=True, exist_ok=True)
        Path(path).write_bytes(base64.b64decode(data))
        log('screenshot', path)

    def element_clip(self, selector, pad=8):
        r = self.eval(f"""(function() {{ var e = document.querySelector({json.dumps(selector)}); if (!e) return null;
            var r = e.getBoundingClientRect(); return [r.left + scrollX, r.top + scrollY, r.width, r.height]; }})()""")
        if not r:
            return None
        return {'x': max(0, r[0] - pad), 'y': max(0, r[1] - pad), 'width': r[2] + 2 * pad, 'height': r[3] + 2 * pad}


# --- What the page must show, computed here from the data ---------------------------------------

def num(v):
    if isinstance(v, bool):
        return math.nan
    if isinstance(v, (int, float)):
        return float(v)
    if isinstance(v, str):
        s = v.strip().lower()
        if s in ('inf', '+inf', 'infinity'):
            return math.inf
        if s in ('-inf', '-infinity'):
            return -math.inf
        try:
            return float(s) if s not in ('nan', '') else math.nan
        except ValueError:
            return math.nan
    return math.nan


def _eligible(st):
    """A family x variant the speed plot can draw: a positive, finite ns_per_query and a normalised error."""
    if not isinstance(st, dict):
        return False
    ns = num(st.get('ns_per_query'))
    h = (st.get('errors') or {}).get('normalized') if isinstance(st.get('errors'), dict) else None
    return math.isfinite(ns) and ns > 0 and isinstance(h, dict) and (math.isfinite(num(h.get('p99'))) or math.isfinite(num(h.get('max'))))


def expected_scatter_points(report):
    """The speed plot starts on `random` (else the family with most cases that has points): one point
    per variant of that family with a timing and a normalised error. Returns (family, points)."""
    fams = report.get('families') if isinstance(report, dict) else None
    fams = [f for f in (fams if isinstance(fams, list) else []) if isinstance(f, dict)]
    def points(f):
        vs = f.get('variants')
        return sum(1 for st in (vs.values() if isinstance(vs, dict) else []) if _eligible(st))
    with_points = [f for f in fams if points(f) > 0]
    if not with_points:
        return None, 0
    start = next((f for f in with_points if str(f.get('name')) == 'random'), None)
    if start is None:
        start = sorted(with_points, key=lambda f: -num(f.get('cases')) if math.isfinite(num(f.get('cases'))) else 0)[0]
    return str(start.get('name')), points(start)


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

# Tables wider than their place, with every folded block opened: none may be cut off.
OVERFLOW_PROBE = """(function() {
  document.querySelectorAll('details').forEach(function (d) { d.open = true; });
  var width = document.documentElement.clientWidth, bad = [];
  document.querySelectorAll('table').forEach(function (t, i) {
    var r = t.getBoundingClientRect(), box = t.parentElement.getBoundingClientRect();
    if (r.width === 0) return;
    if (r.right > width + 0.5 || r.right > box.right + 0.5 || t.parentElement.scrollWidth > t.parentElement.clientWidth + 1)
      bad.push((t.className || 'table') + ' #' + i + ' right ' + Math.round(r.right) + ' in ' + Math.round(box.right) + ' (page ' + width + ')');
  });
  var page = document.documentElement.scrollWidth;
  document.querySelectorAll('details').forEach(function (d) { d.open = false; });
  return {page: page, width: width, bad: bad};
})()"""

# Each variant's colour as drawn: the colour dots (tables, legends) and the heat map's column heads.
COLOR_PROBE = """(function() {
  var seen = {}, clash = [];
  function add(name, color) {
    if (!name || !color) return;
    if (name in seen && seen[name] !== color) clash.push(name + ': ' + seen[name] + ' and ' + color);
    seen[name] = color;
  }
  document.querySelectorAll('.dot[data-variant]').forEach(function (e) { add(e.getAttribute('data-variant'), getComputedStyle(e).backgroundColor); });
  document.querySelectorAll('circle[data-variant]').forEach(function (e) { add(e.getAttribute('data-variant'), getComputedStyle(e).fill); });
  return {colors: seen, clash: clash};
})()"""


def rgb(text):
    """'rgb(31, 95, 168)' -> (31, 95, 168)."""
    inner = text[text.index('(') + 1:text.index(')')]
    return tuple(int(float(x)) for x in inner.split(',')[:3])


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


def check_page(browser, html, out_dir, kind, report=None, screenshot=None, viewer_screenshot=None, label=None):
    """Loads html (kind 'report' or 'case' page); returns a list of failures."""
    fails = []
    label = label or kind
    url = Path(html).resolve().as_uri()
    page = Page(browser, 1400, 900)  # the first screen of a laptop
    # 1. The page's self-test.
    page.load(url + '#selftest')
    page.wait_for("document.getElementById('selftest') && document.getElementById('selftest').getAttribute('data-done') === '1'")
    verdict = json.loads(page.eval("document.getElementById('selftest').textContent"))
    (Path(out_dir) / f'{label}-selftest.json').write_text(json.dumps(verdict, indent=1))
    for name, c in verdict.get('checks', {}).items():
        if not c.get('ok'):
            fails.append(f'{label}: self-test check "{name}" failed: {c.get("detail")}')
    for e in verdict.get('errors', []):
        fails.append(f'{label}: page error: {e}')
    if not verdict.get('ok') and not fails:
        fails.append(f'{label}: self-test verdict not ok: {verdict}')
    fails += [f'{label} (#selftest): {p}' for p in page.problems()]
    log(f'{label}: self-test', 'ok' if verdict.get('ok') else 'FAILED', {k: verdict.get(k) for k in ('scatterPoints', 'scatterExpected', 'viewers')})

    # 2. A clean load, checked from outside the page.
    page.load(url)
    page.wait_for("document.querySelector('#app') && document.querySelector('#app').children.length > 0")
    if kind == 'report':
        drawn = page.eval("document.querySelectorAll('#scatter .pt').length")
        family, want = expected_scatter_points(report)
        log(f'report: speed plot on {family!r}: points drawn {drawn}, expected from report.json {want}')
        if drawn != want:
            fails.append(f'report: the speed plot has {drawn} points, report.json has {want} variants to plot in family {family!r}')
        if family is not None and page.eval("document.querySelector('select.speed-family').value") != family:
            fails.append(f'report: the speed plot does not start on family {family!r}')
        # The first screen answers the questions: verdict, heat map and speed plot within the first
        # 1,200 px at 1400 x 900.
        pos = page.eval(FIRST_SCREEN_PROBE)
        log('report: first screen at 1400 x 900 (page px):', json.dumps(pos))
        (Path(out_dir) / f'{label}-first-screen.json').write_text(json.dumps(pos, indent=1))
        for part in ('verdict', 'counts', 'heat map') + (('speed plot',) if want else ()):
            p = pos.get(part)
            if not p:
                fails.append(f'report: no {part} on the page')
            elif p['top'] < 0 or p['bottom'] > 1200:
                fails.append(f'report: the {part} is not within the first 1,200 px: {p}')
        # No table is cut off at 1280 px.
        page.cmd('Emulation.setDeviceMetricsOverride', {'width': 1280, 'height': 900, 'deviceScaleFactor': 1, 'mobile': False})
        time.sleep(0.2)
        over = page.eval(OVERFLOW_PROBE)
        log('report: at 1280 px: page width', over['page'], 'tables cut off:', len(over['bad']))
        if over['page'] > over['width'] or over['bad']:
            fails.append(f'report: at 1280 px the page scrolls sideways or a table is cut off: {over}')
        page.cmd('Emulation.setDeviceMetricsOverride', {'width': 1400, 'height': 900, 'deviceScaleFactor': 1, 'mobile': False})
        time.sleep(0.2)
        fams = [str(f.get('name')) for f in report.get('families', []) if isinstance(f, dict)] if isinstance(report, dict) else []
        cards = page.eval("Array.prototype.map.call(document.querySelectorAll('.family h3'), function (e) { return e.textContent; })") or []
        for f in fams:
            if not any(c.startswith(f) for c in cards):
                fails.append(f'report: family {f!r} has no section on the page')
        if page.eval("document.querySelectorAll('.error-box').length"):
            fails.append('report: the page shows an error box: ' + str(page.eval("document.querySelector('.error-box').textContent")))
    colors = page.eval(COLOR_PROBE)
    for c in colors['clash']:
        fails.append(f'{label}: a variant drawn in two colours: {c}')
    if screenshot:
        # The first screen, as a reader opens the page (1400 x 900), and the whole page.
        page.cmd('Emulation.setDeviceMetricsOverride', {'width': 1400, 'height': 900, 'deviceScaleFactor': 1, 'mobile': False})
        time.sleep(0.2)
        page.eval('window.scrollTo(0, 0)')
        page.screenshot(screenshot)
        full = Path(screenshot).with_name(Path(screenshot).stem + '-full.png')
        page.screenshot(full, full=True)
    want_viewer = kind == 'case' or (isinstance(report, dict) and isinstance(report.get('worst'), list) and len(report['worst']) > 0)
    if want_viewer:
        probe = page.eval(STEP_PROBE)
        log(f'{label}: step probe', probe)
        if probe.get('none'):
            fails.append(f'{label}: no iteration viewer on the page')
        elif probe['steps'] > 1:
            if not (probe['after'] == str(int(probe['before']) + 1) and probe['drawnAfter'] == probe['after'] and probe['svgChanged']):
                fails.append(f'{label}: "next" did not change the drawn iteration: {probe}')
        if viewer_screenshot and not probe.get('none'):
            page.eval("document.querySelector('.viewer .step-next').click()")
            clip = page.element_clip('.viewer')
            if clip:
                page.screenshot(viewer_screenshot, clip=clip)
    fails += [f'{label}: {p}' for p in page.problems()]
    return fails, colors['colors']


def check_colors(report, page_colors):
    """One colour per variant: the same on every page, and distinct variants distinct colours."""
    fails = []
    merged = {}
    for label, colors in page_colors.items():
        for name, c in colors.items():
            merged.setdefault(name, {})[label] = c
    for name, by_page in merged.items():
        if len(set(by_page.values())) > 1:
            fails.append(f'variant {name!r} has different colours on different pages: {by_page}')
    names = [str(v.get('name')) for v in (report.get('variants') or []) if isinstance(v, dict)] if isinstance(report, dict) else []
    report_colors = page_colors.get('report', {})
    missing = [n for n in names if n not in report_colors]
    if missing:
        fails.append(f'report: no colour dot for the variants {missing}')
    drawn = {n: rgb(report_colors[n]) for n in names if n in report_colors}
    for i, a in enumerate(sorted(drawn)):
        for b in sorted(drawn)[i + 1:]:
            d = math.dist(drawn[a], drawn[b])
            if d < 40:
                fails.append(f'variants {a!r} and {b!r} have (nearly) the same colour: {drawn[a]} and {drawn[b]}')
    log(f'colours: {len(drawn)} variants, {len(set(drawn.values()))} distinct colours on the report page;',
        'pages compared:', ', '.join(sorted(page_colors)))
    return fails


def explain_page(exe, report, out):
    """Runs `gjk-validate explain ... --html` for the report's first worst case from a generated family."""
    worst = [w for w in (report.get('worst') or []) if isinstance(w, dict) and w.get('name') and w.get('family')]
    worst = [w for w in worst if not str(w['family']).startswith('file:')]
    if not worst:
        raise RuntimeError('the report has no worst case from a generated family to explain')
    w = worst[0]
    ctx = report.get('context') or {}
    spec = str(w['family'])
    for inp in ctx.get('inputs') or []:
        if isinstance(inp, dict) and inp.get('family') == spec and inp.get('count'):
            spec += ':' + str(inp['count'])
    html = out / 'explain.html'
    cmd = [exe, 'explain', '--family', spec, '--seed', str(ctx.get('seed', 1)), '--name', str(w['name']), '--html', str(html)]
    log('explain:', ' '.join(cmd))
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=300)
    (out / 'explain-output.txt').write_bytes(r.stdout)
    if r.returncode not in (0, 1) or not html.is_file():
        raise RuntimeError(f'exit status {r.returncode}, no page written: ' + r.stdout.decode(errors='replace')[-1500:])
    return html


def main(argv):
    campaign = None
    if '--campaign' in argv:
        i = argv.index('--campaign')
        try:
            j = argv.index('--', i + 1)
        except ValueError:
            print('browser_check: --campaign needs a closing --', file=sys.stderr)
            return 2
        campaign, argv = argv[i + 1:j], argv[:i] + argv[j + 1:]
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--chromium', default='/usr/bin/chromium')
    ap.add_argument('--render', required=True, help='the report_render program')
    ap.add_argument('--report', required=True, help='report.json')
    ap.add_argument('--out', required=True, help='directory for pages, verdicts and logs')
    ap.add_argument('--expect-index', help='use this index.html (written by the runner) instead of rendering one')
    ap.add_argument('--screenshot')
    ap.add_argument('--case-screenshot')
    ap.add_argument('--explain', metavar='GJK_VALIDATE',
                    help='also run `GJK_VALIDATE explain --family F --name N --html` on the report\'s first worst case '
                         'and check that page')
    a = ap.parse_args(argv)

    chromium = a.chromium if os.path.isabs(a.chromium) else shutil.which(a.chromium)
    if not chromium or not os.access(chromium, os.X_OK):
        if os.environ.get('GJK2D_REQUIRE_ALL') == '1':  # CI (.ci/run): a skip is a failure
            log(f'FAIL: Chromium not found at {a.chromium}, and GJK2D_REQUIRE_ALL=1 makes a skip a failure '
                '(scripts/setup.sh --tests installs it)')
            return 1
        log(f'SKIP: Chromium not found at {a.chromium} (scripts/setup.sh --tests installs it)')
        return 77
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.monotonic()

    if campaign:
        log('campaign:', ' '.join(campaign))
        r = subprocess.run(campaign, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=840)
        (out / 'campaign-output.txt').write_bytes(r.stdout)
        log(f'campaign exit status {r.returncode} ({time.monotonic() - t0:.1f} s)')
        if r.returncode not in (0, 1):
            sys.stdout.write(r.stdout.decode(errors='replace')[-4000:])
            log('FAIL: the campaign did not finish (exit status 0: passed, 1: failures found; anything else is an error)')
            return 1

    if not Path(a.report).is_file():
        log(f'FAIL: no report at {a.report}')
        return 1
    report = json.loads(Path(a.report).read_text())

    if a.expect_index:
        html = Path(a.expect_index)
        if not html.is_file():
            log(f'FAIL: the runner wrote no {html} beside {a.report} (it should write index.html with gjk_html::renderReport)')
            return 1
    else:
        html = out / 'index.html'
        subprocess.run([a.render, 'report', a.report, str(html)], check=True)
    pages = [('report', 'report', html, a.screenshot)]
    if isinstance(report, dict) and isinstance(report.get('worst'), list) and report['worst']:
        case_html = out / 'case.html'
        subprocess.run([a.render, 'case', a.report, str(case_html), '0'], check=True)
        pages.append(('case', 'case', case_html, a.case_screenshot))

    fails = []
    if a.explain:
        try:
            pages.append(('explain', 'case', explain_page(a.explain, report, out), None))
        except Exception as e:
            fails.append(f'explain --html: {e}')

    browser = Chromium(chromium, str(out))
    page_colors = {}
    try:
        for label, kind, path, shot in pages:
            vshot = None
            if kind == 'report' and shot:
                vshot = str(Path(shot).with_name(Path(shot).stem + '-viewer.png'))
            try:
                if kind == 'case':
                    f, page_colors[label] = check_page(browser, path, out, kind, report=report, viewer_screenshot=shot, label=label)
                else:
                    f, page_colors[label] = check_page(browser, path, out, kind, report=report, screenshot=shot, viewer_screenshot=vshot, label=label)
                fails += f
            except Exception as e:  # a timeout or a crash is a failure, with the browser's log
                fails.append(f'{label}: {type(e).__name__}: {e}')
        if 'report' in page_colors:
            fails += check_colors(report, page_colors)
    finally:
        browser.close()
    log(f'done in {time.monotonic() - t0:.1f} s')
    if fails:
        for f in fails:
            log('FAIL:', f)
        tail = browser.stderr_path.read_text(errors='replace').splitlines()[-30:]
        log('last lines of Chromium\'s log:\n  ' + '\n  '.join(tail))
        return 1
    log('PASS')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
