// The report page: reads the JSON inlined in the page's "report-data" block (docs/report-schema.md) and
// draws everything with plain DOM and hand-written SVG. No libraries, no network.
// <html data-mode="report"> renders a whole report.json; data-mode="case" renders one CaseDetail.
// Every optional field may be missing: each section checks what it uses and degrades to a note.
(function () {
  'use strict';

  var SVGNS = 'http://www.w3.org/2000/svg'; // an XML namespace name, not a network address

  // --- Small DOM helpers --------------------------------------------------------------------------

  function append(node, kids) {
    for (var i = 0; i < kids.length; ++i) {
      var k = kids[i];
      if (k === null || k === undefined || k === false) continue;
      if (Array.isArray(k)) append(node, k);
      else if (typeof k === 'string' || typeof k === 'number')
        node.appendChild(document.createTextNode(String(k)));
      else node.appendChild(k);
    }
    return node;
  }

  function setAttrs(node, attrs) {
    if (!attrs) return node;
    Object.keys(attrs).forEach(function (key) {
      var v = attrs[key];
      if (v === null || v === undefined || v === false) return;
      if (key.slice(0, 2) === 'on' && typeof v === 'function')
        node.addEventListener(key.slice(2), v);
      else if (key === 'text') node.textContent = v;
      else node.setAttribute(key, v === true ? '' : String(v));
    });
    return node;
  }

  // h('div', {class: 'x'}, child, ...): an HTML element.
  function h(tag, attrs) {
    var node = setAttrs(document.createElement(tag), attrs);
    return append(node, Array.prototype.slice.call(arguments, 2));
  }

  // sv('line', {x1: ...}, child, ...): an SVG element.
  function sv(tag, attrs) {
    var node = setAttrs(document.createElementNS(SVGNS, tag), attrs);
    return append(node, Array.prototype.slice.call(arguments, 2));
  }

  function svgTitle(text) {
    return sv('title', {}, text);
  }

  // --- Numbers ------------------------------------------------------------------------------------

  function has(v) {
    return v !== undefined && v !== null;
  }

  // A JSON number, or the schema's "inf" / "-inf" / "nan" strings; NaN when missing.
  function num(v) {
    if (typeof v === 'number') return v;
    if (typeof v === 'string') {
      var s = v.trim().toLowerCase();
      if (s === 'inf' || s === '+inf' || s === 'infinity') return Infinity;
      if (s === '-inf' || s === '-infinity') return -Infinity;
      if (s === 'nan') return NaN;
      var x = Number(s);
      return s !== '' && isFinite(x) ? x : NaN;
    }
    return NaN;
  }

  function isNum(v) {
    return isFinite(num(v));
  }

  function trimMantissa(s) {
    // "1.20e-16" -> "1.2e-16", "1.00e+5" -> "1e5"
    var m = /^(-?\d+)(?:\.(\d*?))?0*e([+-])(\d+)$/.exec(s);
    if (!m) return s;
    return m[1] + (m[2] ? '.' + m[2] : '') + 'e' + (m[3] === '-' ? '-' : '') + m[4];
  }

  // 3 significant digits; exponent notation outside [1e-3, 1e6).
  function fmt(v, digits) {
    digits = digits || 3;
    if (!has(v)) return '—';
    var x = num(v);
    if (isNaN(x)) return typeof v === 'string' && v.toLowerCase() === 'nan' ? 'NaN' : '—';
    if (x === Infinity) return '∞';
    if (x === -Infinity) return '−∞';
    if (x === 0) return '0';
    var a = Math.abs(x);
    if (a < 1e-3 || a >= 1e6) return trimMantissa(x.toExponential(digits - 1)).replace('-', '−');
    var s = String(Number(x.toPrecision(digits)));
    if (a >= 1000) s = Number(s).toLocaleString('en-US');
    return s.replace('-', '−');
  }

  function fmtInt(v) {
    if (!has(v)) return '—';
    var x = num(v);
    if (!isFinite(x)) return fmt(v);
    return Math.round(x).toLocaleString('en-US');
  }

  // A coordinate shown in full (shortest round-trip form): detail tables, where digits matter.
  function fmtFull(v) {
    if (!has(v)) return '—';
    var x = num(v);
    if (!isFinite(x)) return fmt(v);
    var a = Math.abs(x);
    if (a !== 0 && (a < 1e-4 || a >= 1e15)) return x.toExponential().replace('e+', 'e');
    return String(x);
  }

  function fmtPt(p, f) {
    f = f || fmtFull;
    if (!Array.isArray(p)) return '—';
    return '(' + f(p[0]) + ', ' + f(p[1]) + ')';
  }

  function pct(x) {
    if (!isFinite(x)) return '—';
    if (x === 0) return '0 %';
    if (x < 0.001) return '<0.1 %';
    return fmt(100 * x) + ' %';
  }

  function finitePoint(p) {
    return Array.isArray(p) && p.length >= 2 && isNum(p[0]) && isNum(p[1]);
  }

  function pt(p) {
    return [num(p[0]), num(p[1])];
  }

  function pts(list) {
    if (!Array.isArray(list)) return [];
    return list.filter(finitePoint).map(pt);
  }

  // --- Variant colours and markers ------------------------------------------------------------------

  // Each variant of a page is drawn with a colour and a marker shape, and no two variants of the page
  // share both. This is the rule's one home (docs/report.md, "Variant colours and markers"):
  //  - gjk2d's built-in variants (validation/src/implementations/variants.cpp) keep their fixed colours,
  //    in hue pairs (the double variant dark, its float twin light), and the circle: the same on
  //    every page whatever else it lists;
  //  - every other name (a plugin, an external implementation) gets a slot of EXTRA_VARIANT_COLORS x
  //    EXTRA_MARKERS (10 colours, none a built-in's, x 4 markers). The names are taken in sorted
  //    order; each takes the first free slot starting from the colour its name hashes to (FNV-1a),
  //    trying every colour as a diamond before any square, then triangles, then triangles pointing
  //    down. So up to 10 such names all get different colours, the same set of names always gets
  //    the same slots, and a name keeps its colour on a page listing fewer names unless another
  //    name had taken it. Beyond 40 names: colours by the golden angle (distinct, less easy to tell).
  // tests/report/browser_check.py checks, on a 30-variant report, that no two variants of a page have
  // the same colour and marker, that two with the same marker have well-separated colours, and that a
  // variant looks the same on the report page and on its case pages; a Catch2 test of the runner
  // checks that every built-in variant has its fixed colour here.
  var BUILTIN_VARIANT_COLORS = {
    'double': '#1f5fa8',
    'float': '#64a6e8',
    'double-closest-point': '#c2570c',
    'float-closest-point': '#f7a35c',
    'double-world-frame': '#2e7d32',
    'float-world-frame': '#85c988',
    'double-duality-gap': '#6d4c41',
    'double-certified': '#5e35b1',
    'float-certified': '#b39ddb',
    'double-binary-support': '#00838f',
    'float-binary-support': '#5fd0dc',
    'double-warm': '#ad1457',
    'float-warm': '#f48fb1',
    'double-every-start': '#7a7a12',
    'float-every-start': '#cfd250',
    'double-batch': '#00695c',
    'float-batch': '#80cbc4',
    'double-correct': '#c62828',
    'double-signed': '#791571',
    'float-signed': '#ea86e1',
  };
  var BUILTIN_MARKER = 'circle';
  // RGB distances: at least 48 from every built-in colour, at least 72 from each other (docs/report.md).
  var EXTRA_VARIANT_COLORS = [
    '#212121',
    '#f2b600',
    '#8e24aa',
    '#546e7a',
    '#ff6f00',
    '#283593',
    '#9e9d24',
    '#a1887f',
    '#e040fb',
    '#2962ff',
  ];
  var EXTRA_MARKERS = ['diamond', 'square', 'triangle', 'triangle-down'];

  function isBuiltinVariant(name) {
    return Object.prototype.hasOwnProperty.call(BUILTIN_VARIANT_COLORS, name);
  }

  function nameHash(s) {
    var x = 0x811c9dc5;
    for (var i = 0; i < s.length; ++i) {
      x ^= s.charCodeAt(i);
      x = Math.imul(x, 0x01000193) >>> 0;
    }
    return x >>> 0;
  }

  function hslHex(hue, s, l) {
    var c = (1 - Math.abs(2 * l - 1)) * s,
      x = c * (1 - Math.abs(((hue / 60) % 2) - 1)),
      m = l - c / 2;
    var rgb =
      hue < 60
        ? [c, x, 0]
        : hue < 120
          ? [x, c, 0]
          : hue < 180
            ? [0, c, x]
            : hue < 240
              ? [0, x, c]
              : hue < 300
                ? [x, 0, c]
                : [c, 0, x];
    return (
      '#' +
      rgb
        .map(function (v) {
          var b = Math.round((v + m) * 255);
          return (b < 16 ? '0' : '') + b.toString(16);
        })
        .join('')
    );
  }

  // The page's styles: set once from every variant name the page draws (setVariantNames), before
  // anything is drawn. A name found later (not in the data's lists) takes a slot the same way.
  var variantStyles = {},
    slotTaken = {},
    overflowCount = 0;

  function takeExtraSlot(name) {
    var nc = EXTRA_VARIANT_COLORS.length,
      slots = nc * EXTRA_MARKERS.length,
      start = nameHash(name) % nc;
    for (var i = 0; i < slots; ++i) {
      var row = Math.floor(i / nc),
        col = (start + i) % nc,
        slot = row * nc + col;
      if (slotTaken[slot]) continue;
      slotTaken[slot] = true;
      return { color: EXTRA_VARIANT_COLORS[col], marker: EXTRA_MARKERS[row] };
    }
    var k = overflowCount++;
    return {
      color: hslHex(Math.round((k * 137.508) % 360), 0.65, 0.42),
      marker: EXTRA_MARKERS[k % EXTRA_MARKERS.length],
    };
  }

  function setVariantNames(names) {
    variantStyles = {};
    slotTaken = {};
    overflowCount = 0;
    var extras = [];
    names.forEach(function (n) {
      n = String(n);
      if (!isBuiltinVariant(n) && extras.indexOf(n) < 0) extras.push(n);
    });
    extras.sort(function (a, b) {
      return a < b ? -1 : a > b ? 1 : 0;
    }); // code-unit order: no locale
    extras.forEach(function (n) {
      variantStyles[n] = takeExtraSlot(n);
    });
  }

  function variantStyle(name) {
    name = String(name);
    if (isBuiltinVariant(name))
      return { color: BUILTIN_VARIANT_COLORS[name], marker: BUILTIN_MARKER };
    if (!Object.prototype.hasOwnProperty.call(variantStyles, name))
      variantStyles[name] = takeExtraSlot(name);
    return variantStyles[name];
  }

  function variantColor(name) {
    return variantStyle(name).color;
  }

  // A marker shape centred on (x, y), about 2r across; the caller sets fill and stroke.
  function markerShape(marker, x, y, r) {
    var d;
    if (marker === 'diamond') {
      var q = r * 1.25;
      d =
        'M' +
        x +
        ' ' +
        (y - q) +
        'l' +
        q +
        ' ' +
        q +
        'l' +
        -q +
        ' ' +
        q +
        'l' +
        -q +
        ' ' +
        -q +
        'Z';
    } else if (marker === 'square') {
      var s = r * 0.9;
      d = 'M' + (x - s) + ' ' + (y - s) + 'h' + 2 * s + 'v' + 2 * s + 'h' + -2 * s + 'Z';
    } else if (marker === 'triangle') {
      var t = r * 1.2;
      d = 'M' + x + ' ' + (y - t) + 'l' + t * 0.95 + ' ' + t * 1.6 + 'h' + -t * 1.9 + 'Z';
    } else if (marker === 'triangle-down') {
      var u = r * 1.2;
      d = 'M' + x + ' ' + (y + u) + 'l' + u * 0.95 + ' ' + -u * 1.6 + 'h' + -u * 1.9 + 'Z';
    } else return sv('circle', { cx: x, cy: y, r: r, class: 'vmark-shape' });
    return sv('path', { d: d, class: 'vmark-shape' });
  }

  // A variant's marker as a small inline picture (tables, legends); data-variant, data-color and
  // data-marker let the tests compare variants within and across pages.
  function variantDot(name) {
    var st = variantStyle(name);
    var m = markerShape(st.marker, 7, 7, 4.6);
    setAttrs(m, { fill: st.color, stroke: 'rgba(0,0,0,.45)', 'stroke-width': 0.8 });
    return sv(
      'svg',
      {
        class: 'dot',
        width: 14,
        height: 14,
        'aria-hidden': 'true',
        'data-variant': String(name),
        'data-color': st.color,
        'data-marker': st.marker,
      },
      m,
    );
  }

  // The talk's pastels, for geometry.
  var GEO = {
    aFill: '#b9d7f0',
    aStroke: '#5b8fc7',
    bFill: '#f6c6b8',
    bStroke: '#d67c66',
    zFill: '#cdeac0',
    zStroke: '#6aa35c',
    simplexFill: '#dccaf0',
    simplexStroke: '#8a5fc0',
    closest: '#f08a24',
    direction: '#d9487a',
    support: '#e8b923',
    exact: '#333333',
    origin: '#222222',
  };
  var STOP_COLORS = [
    '#a8d5e2',
    '#f9d8a7',
    '#c5e3bf',
    '#e6c3e0',
    '#f4b6b6',
    '#d5d0f0',
    '#f3e6a0',
    '#cfd8dc',
  ];

  // --- Scales and axes ----------------------------------------------------------------------------

  function linScale(d0, d1, r0, r1) {
    var f = function (v) {
      return d1 === d0 ? (r0 + r1) / 2 : r0 + ((v - d0) / (d1 - d0)) * (r1 - r0);
    };
    f.domain = [d0, d1];
    return f;
  }

  function logScale(d0, d1, r0, r1) {
    var l0 = Math.log10(d0),
      l1 = Math.log10(d1);
    var f = function (v) {
      return l1 === l0 ? (r0 + r1) / 2 : r0 + ((Math.log10(v) - l0) / (l1 - l0)) * (r1 - r0);
    };
    f.domain = [d0, d1];
    return f;
  }

  // Log-scale domain padded around [lo, hi] (both > 0).
  function logDomain(lo, hi, padDecades) {
    if (!(lo > 0) || !(hi > 0) || !isFinite(lo) || !isFinite(hi)) return [1, 10];
    var l0 = Math.log10(lo),
      l1 = Math.log10(hi);
    var pad = padDecades === undefined ? 0.15 : padDecades;
    if (l1 - l0 < 0.5) {
      var mid = (l0 + l1) / 2;
      l0 = mid - 0.25;
      l1 = mid + 0.25;
    }
    return [Math.pow(10, l0 - pad), Math.pow(10, l1 + pad)];
  }

  // Ticks of a log axis: decades, plus 2 and 5 when the domain spans little.
  function logTicks(d0, d1) {
    var l0 = Math.log10(d0),
      l1 = Math.log10(d1);
    var span = l1 - l0,
      ticks = [];
    var step = span > 12 ? Math.ceil(span / 8) : 1;
    for (var k = Math.ceil(l0); k <= Math.floor(l1); k += step)
      ticks.push({ v: Math.pow(10, k), exp: k, major: true });
    if (span < 2.5) {
      var mults = span < 0.6 ? [2, 3, 4, 5, 6, 7, 8, 9] : span < 1.2 ? [2, 3, 5, 7] : [2, 5];
      for (var e = Math.floor(l0); e <= Math.ceil(l1); ++e) {
        mults.forEach(function (m) {
          var v = m * Math.pow(10, e);
          if (v >= d0 && v <= d1) ticks.push({ v: v, exp: null, major: false });
        });
      }
    }
    return ticks;
  }

  function niceStep(span, count) {
    var raw = span / Math.max(1, count);
    if (!(raw > 0) || !isFinite(raw)) return 1;
    var p = Math.pow(10, Math.floor(Math.log10(raw)));
    var m = raw / p;
    return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * p;
  }

  function linTicks(d0, d1, count) {
    var step = niceStep(d1 - d0, count || 5),
      ticks = [];
    for (var v = Math.ceil(d0 / step) * step; v <= d1 + step * 1e-9; v += step)
      ticks.push({ v: Math.abs(v) < step * 1e-9 ? 0 : v });
    return ticks;
  }

  // Text for a tick: powers of ten as 10 with a superscript exponent.
  function tickText(t, attrs) {
    if (t.exp !== null && t.exp !== undefined && (t.exp < -2 || t.exp > 3)) {
      return sv(
        'text',
        attrs,
        '10',
        sv('tspan', { dy: -5, 'font-size': 9 }, String(t.exp).replace('-', '−')),
      );
    }
    return sv('text', attrs, fmt(t.v));
  }

  // Draws x and y axes, grid, tick labels and axis titles into g for the plot box.
  // opts.yLabelX0: x of the y tick labels' right edge (default box.x0); opts.xLabelY1: y below which
  // the x tick labels go (default box.y1), for plots with a band under or beside the axes.
  function drawAxes(g, box, xs, ys, xt, yt, xLabel, yLabel, opts) {
    opts = opts || {};
    var lx0 = opts.yLabelX0 === undefined ? box.x0 : opts.yLabelX0;
    var ly1 = opts.xLabelY1 === undefined ? box.y1 : opts.xLabelY1;
    g.appendChild(
      sv('rect', {
        x: box.x0,
        y: box.y0,
        width: box.x1 - box.x0,
        height: box.y1 - box.y0,
        class: 'plot-bg',
      }),
    );
    xt.forEach(function (t) {
      var x = xs(t.v);
      if (x < box.x0 - 0.5 || x > box.x1 + 0.5) return;
      g.appendChild(
        sv('line', {
          x1: x,
          x2: x,
          y1: box.y0,
          y2: box.y1,
          class: t.major === false ? 'grid minor' : 'grid',
        }),
      );
      g.appendChild(tickText(t, { x: x, y: ly1 + 16, class: 'tick', 'text-anchor': 'middle' }));
    });
    yt.forEach(function (t) {
      var y = ys(t.v);
      if (y < box.y0 - 0.5 || y > box.y1 + 0.5) return;
      g.appendChild(
        sv('line', {
          x1: box.x0,
          x2: box.x1,
          y1: y,
          y2: y,
          class: t.major === false ? 'grid minor' : 'grid',
        }),
      );
      g.appendChild(tickText(t, { x: lx0 - 6, y: y + 4, class: 'tick', 'text-anchor': 'end' }));
    });
    g.appendChild(
      sv('rect', {
        x: box.x0,
        y: box.y0,
        width: box.x1 - box.x0,
        height: box.y1 - box.y0,
        class: 'plot-frame',
      }),
    );
    if (xLabel)
      g.appendChild(
        sv(
          'text',
          { x: (box.x0 + box.x1) / 2, y: ly1 + 36, class: 'axis-label', 'text-anchor': 'middle' },
          xLabel,
        ),
      );
    if (yLabel) {
      var cy = (box.y0 + box.y1) / 2;
      g.appendChild(
        sv(
          'text',
          {
            x: 0,
            y: 0,
            transform: 'translate(' + (lx0 - 46) + ',' + cy + ') rotate(-90)',
            class: 'axis-label',
            'text-anchor': 'middle',
          },
          yLabel,
        ),
      );
    }
  }

  function legendItem(color, label, shape) {
    var sw = sv('svg', { width: 18, height: 14, class: 'legend-swatch' });
    if (shape === 'circle')
      sw.appendChild(
        sv('circle', { cx: 9, cy: 7, r: 5, fill: color, stroke: '#333', 'stroke-width': 0.7 }),
      );
    else if (shape === 'triangle')
      sw.appendChild(
        sv('path', {
          d: 'M9 1.5 L15 12 L3 12 Z',
          fill: 'white',
          stroke: color === 'none' ? '#333' : color,
          'stroke-width': 1.6,
        }),
      );
    else if (shape === 'ring')
      sw.appendChild(
        sv('circle', { cx: 9, cy: 7, r: 4.5, fill: 'white', stroke: color, 'stroke-width': 2.5 }),
      );
    else if (shape === 'ring-red')
      sw.appendChild(
        sv('circle', { cx: 9, cy: 7, r: 5, fill: color, stroke: '#c0392b', 'stroke-width': 2.5 }),
      );
    else if (shape === 'cross')
      sw.appendChild(sv('path', { d: 'M4 2L14 12M4 12L14 2', stroke: color, 'stroke-width': 2.2 }));
    else if (shape === 'diamond')
      sw.appendChild(
        sv('path', {
          d: 'M9 0.5L15.5 7L9 13.5L2.5 7Z',
          fill: color,
          stroke: '#6b5200',
          'stroke-width': 1,
        }),
      );
    else if (shape === 'cap')
      sw.appendChild(
        sv('path', {
          d: 'M9 12V4M3 4h12',
          stroke: color,
          'stroke-width': 2.2,
          'stroke-linecap': 'round',
          fill: 'none',
        }),
      );
    else if (shape === 'line')
      sw.appendChild(sv('line', { x1: 1, x2: 17, y1: 7, y2: 7, stroke: color, 'stroke-width': 2 }));
    else if (shape === 'dash')
      sw.appendChild(
        sv('line', {
          x1: 1,
          x2: 17,
          y1: 7,
          y2: 7,
          stroke: color,
          'stroke-width': 2,
          'stroke-dasharray': '4 3',
        }),
      );
    else
      sw.appendChild(
        sv('rect', {
          x: 1,
          y: 2,
          width: 16,
          height: 10,
          rx: 2,
          fill: color,
          stroke: 'rgba(0,0,0,.35)',
          'stroke-width': 0.7,
        }),
      );
    return h('span', { class: 'legend-item' }, sw, label);
  }

  // --- Data access ----------------------------------------------------------------------------------

  function families(report) {
    return Array.isArray(report.families)
      ? report.families.filter(function (f) {
          return f && typeof f === 'object';
        })
      : [];
  }

  function familyVariants(f) {
    return f && f.variants && typeof f.variants === 'object' ? f.variants : {};
  }

  // Variant names: the report's order first, then any others found in the families.
  function variantNames(report) {
    var names = [];
    (Array.isArray(report.variants) ? report.variants : []).forEach(function (v) {
      if (v && has(v.name) && names.indexOf(String(v.name)) < 0) names.push(String(v.name));
    });
    families(report).forEach(function (f) {
      Object.keys(familyVariants(f)).forEach(function (n) {
        if (names.indexOf(n) < 0) names.push(n);
      });
    });
    return names;
  }

  function hist(stats, metric) {
    var e = stats && stats.errors;
    var hh = e && e[metric];
    if (!hh && metric === 'width_ulps' && stats && stats.interval) hh = stats.interval.width_ulps;
    return hh && typeof hh === 'object' ? hh : null;
  }

  function misclassified(st) {
    return ['false_overlap', 'false_separation', 'undecidable'].reduce(function (s, k) {
      return s + (isNum(st[k]) ? num(st[k]) : 0);
    }, 0);
  }

  // Wrong answers about overlap (undecidable is not one: no answer at that precision can be wrong).
  function wrongClass(st) {
    return ['false_overlap', 'false_separation'].reduce(function (s, k) {
      return s + (isNum(st[k]) ? num(st[k]) : 0);
    }, 0);
  }

  // The rule for one scatter point (a family x variant pair): a positive time and a normalised error.
  function scatterEligible(st) {
    var ns = num(st && st.ns_per_query);
    var hh = hist(st, 'normalized');
    return isFinite(ns) && ns > 0 && !!hh && (isNum(hh.p99) || isNum(hh.max));
  }

  var METRICS = [
    {
      key: 'normalized',
      label: 'normalised error',
      axis: 'error / (u·R)  [u: unit roundoff, R: scale]',
    },
    { key: 'abs', label: 'absolute error', axis: '|d_gjk − d_exact|  [world units]' },
    { key: 'ulps', label: 'error in ulps', axis: 'error  [ulps of d_exact]' },
    { key: 'rel', label: 'relative error', axis: '|d_gjk − d_exact| / d_exact' },
    { key: 'bound_ratio', label: 'error / bound', axis: 'error / error bound  [≤ 1 passes]' },
    {
      key: 'witness',
      label: 'witness error',
      axis: 'witness point distance to its shape  [world units]',
    },
    { key: 'witness_gap', label: 'witness gap', axis: '| |pA − pB| − d_gjk |  [world units]' },
    {
      key: 'input_rounding',
      label: 'input rounding',
      axis: '|d_exact(rounded input) − d_exact|  [world units]',
    },
    { key: 'width_ulps', label: 'interval width', axis: 'certified interval width  [ulps]' },
  ];

  // --- Report page -------------------------------------------------------------------------------

  function section(id, title, intro) {
    return h(
      'section',
      { id: id, class: 'card' },
      h('h2', {}, title),
      intro ? h('p', { class: 'intro' }, intro) : null,
    );
  }

  function guarded(name, fn) {
    try {
      return fn();
    } catch (err) {
      console.error(
        'gjk report: section "' + name + '" failed: ' + (err && err.stack ? err.stack : err),
      );
      return h(
        'div',
        { class: 'error-box' },
        'This part of the page could not be drawn (' + name + '): ' + err,
      );
    }
  }

  function verdictBadge(passed) {
    if (passed === true) return h('span', { class: 'badge pass big' }, 'PASS');
    if (passed === false) return h('span', { class: 'badge fail big' }, 'FAIL');
    return h('span', { class: 'badge unknown big' }, 'no verdict');
  }

  // Comparison variants (report.variants[].judged === false) are reported, never judged.
  var judgedMap = {};
  function isJudged(name) {
    return judgedMap[name] !== false;
  }
  // Implementations with a contract of their own (report.variants[].contract.own === false): their
  // verdict is that contract's, said as "breaks its contract" and "outside gjk2d's bound", never
  // "fails" (gjk2d's own rules are a measure for them).
  var ownMap = {};
  function ownContract(name) {
    return ownMap[name] !== false;
  }
  function readJudged(report) {
    judgedMap = {};
    ownMap = {};
    (Array.isArray(report.variants) ? report.variants : []).forEach(function (v) {
      if (v && has(v.name) && v.judged === false) judgedMap[String(v.name)] = false;
      if (v && has(v.name) && v.contract && v.contract.own === false)
        ownMap[String(v.name)] = false;
    });
  }
  // A family x variant's contract violations (gjk2d's own contract: its failures; a report written
  // before contracts: its failures), the answers outside gjk2d's bound that keep it, and the
  // violations' reasons as "2 false overlap, ...".
  function violationsOf(st) {
    var c = st && st.contract_violations;
    return c && isNum(c.count) ? num(c.count) : st && isNum(st.failures) ? num(st.failures) : 0;
  }
  function outsideBoundOf(st) {
    return st && isNum(st.beyond_bound_keeping_contract)
      ? num(st.beyond_bound_keeping_contract)
      : 0;
  }
  function violationReasons(st) {
    var r = st && st.contract_violations && st.contract_violations.reasons;
    return r && typeof r === 'object'
      ? Object.keys(r).map(function (k) {
          return fmtInt(r[k]) + ' ' + k.replace(/_/g, ' ');
        })
      : [];
  }
  function comparisonTag(name) {
    return isJudged(name)
      ? null
      : h(
          'span',
          { class: 'tag comparison', title: 'comparison variant: reported, not judged' },
          'comparison',
        );
  }

  function passBadge(p, name, st) {
    if (has(name) && !ownContract(name)) {
      // its contract's verdict, not gjk2d's `pass`
      var broke = violationsOf(st) > 0,
        judged = isJudged(name);
      if (broke)
        return h(
          'span',
          { class: 'badge ' + (judged ? 'fail' : 'comparison') },
          'breaks its contract' + (judged ? '' : ' (not judged)'),
        );
      if (outsideBoundOf(st) > 0)
        return h('span', { class: 'badge comparison-ok' }, "outside gjk2d's bound");
      return h(
        'span',
        { class: 'badge ' + (judged ? 'pass' : 'comparison-ok') },
        'keeps its contract',
      );
    }
    if (has(name) && !isJudged(name)) {
      if (p === false) return h('span', { class: 'badge comparison' }, 'fails (not judged)');
      if (p === true) return h('span', { class: 'badge comparison-ok' }, 'passes (not judged)');
    }
    if (p === true) return h('span', { class: 'badge pass' }, 'pass');
    if (p === false) return h('span', { class: 'badge fail' }, 'fail');
    return h('span', { class: 'badge unknown' }, '—');
  }

  // Totals over the whole report: judged and comparison failures, misclassifications, undecidable.
  function totals(report) {
    var t = {
      judgedFailures: 0,
      comparisonFailures: 0,
      misclassified: 0,
      undecidable: 0,
      makeupFailed: 0,
      failingPairs: 0,
      invalid: 0,
      judgedInvalid: 0,
    };
    families(report).forEach(function (f) {
      if (Array.isArray(f.makeup))
        f.makeup.forEach(function (m) {
          if (m && m.ok === false) ++t.makeupFailed;
        });
      var fv = familyVariants(f);
      Object.keys(fv).forEach(function (n) {
        var st = fv[n] || {},
          fails = violationsOf(st);
        if (isJudged(n)) t.judgedFailures += fails;
        else t.comparisonFailures += fails;
        if (fails > 0 && isJudged(n)) ++t.failingPairs;
        t.misclassified += wrongClass(st);
        t.undecidable += isNum(st.undecidable) ? num(st.undecidable) : 0;
        t.invalid += caseCounts(st).invalid;
        if (isJudged(n)) t.judgedInvalid += caseCounts(st).invalid;
      });
    });
    return t;
  }

  function plural(n, one, many) {
    return fmtInt(n) + ' ' + (num(n) === 1 ? one : many || one + 's');
  }

  // The page head answers "did anything fail?": the verdict and one line of counts.
  function renderHeader(report) {
    var ctx = report.context || {};
    var names = variantNames(report);
    var nFam = families(report).length,
      nJudged = names.filter(isJudged).length;
    var t = totals(report);
    var rejected = has(ctx.cases_rejected)
      ? num(ctx.cases_rejected)
      : Array.isArray(report.rejected)
        ? report.rejected.length
        : 0;
    var counts = h(
      'div',
      { class: 'counts', id: 'counts' },
      h('span', {}, h('b', {}, fmtInt(ctx.cases_total)), ' cases'),
      h('span', {}, h('b', {}, String(nFam)), nFam === 1 ? ' family' : ' families'),
      h(
        'span',
        {},
        h('b', {}, String(names.length)),
        names.length === 1 ? ' variant' : ' variants',
        names.length !== nJudged
          ? ' (' + nJudged + ' judged, ' + (names.length - nJudged) + ' comparison)'
          : '',
      ),
      h(
        'span',
        { class: t.judgedFailures > 0 ? 'bad' : '' },
        h('b', {}, fmtInt(t.judgedFailures)),
        t.judgedFailures === 1 ? ' failure' : ' failures',
        t.comparisonFailures > 0
          ? h(
              'span',
              { class: 'muted' },
              ' (+ ' +
                fmtInt(t.comparisonFailures) +
                ' contract violations in comparison variants, not judged)',
            )
          : null,
      ),
      t.invalid
        ? h(
            'span',
            {
              class: t.judgedInvalid ? 'bad' : '',
              id: 'invalid-count',
              title:
                'answers that are no valid answer, counted in the failures (judged variants: ' +
                fmtInt(t.judgedInvalid) +
                ')',
            },
            h('b', {}, fmtInt(t.invalid)),
            t.invalid === 1 ? ' invalid answer' : ' invalid answers',
          )
        : null,
      t.makeupFailed
        ? h('span', { class: 'bad' }, h('b', {}, String(t.makeupFailed)), ' make-up checks failed')
        : null,
      h(
        'span',
        { class: rejected > 0 ? 'bad' : '' },
        h('a', { href: '#rejected' }, h('b', {}, fmtInt(rejected)), ' rejected'),
      ),
    );
    return h(
      'header',
      { class: 'page-head' },
      h(
        'div',
        { class: 'title-row' },
        h('div', { class: 'verdict', id: 'verdict' }, verdictBadge(report.passed)),
        h(
          'div',
          { class: 'head-text' },
          h('h1', {}, 'GJK 2D validation report'),
          counts,
          h(
            'div',
            { class: 'subtitle' },
            [
              has(ctx.date) ? String(ctx.date) : null,
              has(ctx.git_revision) ? 'rev ' + ctx.git_revision : null,
              has(ctx.host) ? String(ctx.host) : null,
              has(report.exit_code) ? 'exit code ' + report.exit_code : null,
            ]
              .filter(Boolean)
              .join('  ·  '),
          ),
        ),
      ),
      h(
        'nav',
        { class: 'toc' },
        h('a', { href: '#overview' }, 'Overview'),
        h('a', { href: '#families' }, 'Families'),
        h('a', { href: '#context' }, 'Context'),
        h('a', { href: '#worst' }, 'Worst cases'),
        h('a', { href: '#rejected' }, 'Rejected inputs'),
      ),
    );
  }

  // How the truths and the witness distances were decided: the exact side's GMP route
  // against its floating-point filter, summed over the families per input type (a float variant's
  // truth is that of the input rounded to float), as the terminal summary gives them
  // (validation/src/report/report.cpp, truthLines and witnessFallbackLine). Nothing for a report
  // written before the counts.
  function truthRows(report) {
    var rows = [],
      types = {},
      points = 0,
      exact = 0;
    (Array.isArray(report.variants) ? report.variants : []).forEach(function (v) {
      if (!v || !has(v.type) || !has(v.name) || types[v.type]) return;
      var cases = 0,
        gmp = 0;
      families(report).forEach(function (f) {
        var st = familyVariants(f)[v.name];
        if (!st || !st.truth || typeof st.truth !== 'object') return;
        cases += isNum(st.cases) ? num(st.cases) : 0;
        gmp += isNum(st.truth.gmp_route) ? num(st.truth.gmp_route) : 0;
      });
      if (cases > 0) types[v.type] = [cases, gmp];
    });
    Object.keys(types).forEach(function (t) {
      var c = types[t];
      rows.push([
        'Truth of the ' + t + ' input',
        'GMP route on ' +
          fmtInt(c[1]) +
          ' of ' +
          plural(c[0], 'case') +
          ' (' +
          fmt((100 * c[1]) / c[0]) +
          ' %), the rest decided by the floating-point filter',
      ]);
    });
    families(report).forEach(function (f) {
      var fv = familyVariants(f);
      Object.keys(fv).forEach(function (n) {
        points += isNum(fv[n].witness_points) ? num(fv[n].witness_points) : 0;
        exact += isNum(fv[n].witness_exact) ? num(fv[n].witness_exact) : 0;
      });
    });
    if (points > 0)
      rows.push([
        'Witness checks',
        fmtInt(points) +
          ' points measured, ' +
          fmtInt(exact) +
          ' by the exact route (' +
          fmt((100 * exact) / points) +
          ' %)',
      ]);
    return rows;
  }

  function renderContext(report) {
    var ctx = report.context || {};
    var sec = section('context', 'Context');
    var rows = [];
    function row(k, v) {
      if (has(v) && v !== '') rows.push(h('dt', {}, k), h('dd', {}, v));
    }
    row('Date', ctx.date);
    row('Host', ctx.host);
    row('Compiler', ctx.compiler);
    row('Flags', has(ctx.flags) ? h('code', {}, String(ctx.flags)) : null);
    row('Build type', ctx.build_type);
    row('Git revision', has(ctx.git_revision) ? h('code', {}, String(ctx.git_revision)) : null);
    row('Command', has(ctx.command) ? h('code', {}, String(ctx.command)) : null);
    row('Seed', has(ctx.seed) ? String(ctx.seed) : null);
    row('Threads', has(ctx.threads) ? String(ctx.threads) : null);
    if (Array.isArray(ctx.inputs) && ctx.inputs.length) {
      row(
        'Inputs',
        h(
          'ul',
          { class: 'plain' },
          ctx.inputs.map(function (inp) {
            if (!inp || typeof inp !== 'object') return h('li', {}, String(inp));
            var what = has(inp.family)
              ? 'family ' + inp.family
              : has(inp.file)
                ? 'file ' + inp.file
                : JSON.stringify(inp);
            return h(
              'li',
              {},
              what,
              has(inp.count) ? ': ' + fmtInt(inp.count) + ' cases' : '',
              has(inp.seed) ? ' (seed ' + inp.seed + ')' : '',
            );
          }),
        ),
      );
    }
    row(
      'Cases',
      has(ctx.cases_total) || has(ctx.cases_rejected)
        ? fmtInt(ctx.cases_total) +
            ' total' +
            (has(ctx.cases_rejected) ? ', ' + fmtInt(ctx.cases_rejected) + ' rejected' : '')
        : null,
    );
    row('Exact route', ctx.exact_route);
    // Every plugin whose variants ran: its file, kind, library (name and version) and variants.
    if (Array.isArray(ctx.plugins) && ctx.plugins.length) {
      row(
        'Plugins',
        h(
          'ul',
          { class: 'plain' },
          ctx.plugins.map(function (p) {
            p = p && typeof p === 'object' ? p : {};
            var names = Array.isArray(p.variants) ? p.variants.map(String) : [];
            return h(
              'li',
              { class: 'plugin-entry' },
              h('code', {}, String(p.file)),
              ' (' +
                [p.kind, p.library]
                  .filter(function (x) {
                    return has(x) && x !== '';
                  })
                  .join(', ') +
                '): ',
              names.map(function (n, i) {
                return h('span', {}, i ? ', ' : '', variantDot(n), n);
              }),
            );
          }),
        ),
      );
    }
    row(
      'Exit code',
      has(report.exit_code)
        ? String(report.exit_code) +
            (report.passed === true ? ' (passed)' : report.passed === false ? ' (failed)' : '')
        : null,
    );
    truthRows(report).forEach(function (r) {
      row(r[0], r[1]);
    });
    if (ctx.elapsed_s && typeof ctx.elapsed_s === 'object') {
      row(
        'Elapsed',
        Object.keys(ctx.elapsed_s)
          .map(function (k) {
            return k + ' ' + fmt(ctx.elapsed_s[k]) + ' s';
          })
          .join(', '),
      );
    }
    // Fields this page does not know yet are still shown.
    var known = [
      'date',
      'host',
      'compiler',
      'flags',
      'build_type',
      'git_revision',
      'command',
      'seed',
      'threads',
      'inputs',
      'cases_total',
      'cases_rejected',
      'exact_route',
      'elapsed_s',
      'plugins',
    ];
    Object.keys(ctx).forEach(function (k) {
      if (known.indexOf(k) >= 0) return;
      var v = ctx[k];
      if (v && typeof v === 'object' && !Array.isArray(v)) {
        // e.g. throughput: numbers as "key value" pairs, text apart.
        var parts = Object.keys(v)
          .filter(function (x) {
            return typeof v[x] === 'number';
          })
          .map(function (x) {
            return x.replace(/_/g, ' ') + ' ' + fmt(v[x]);
          });
        var notes = Object.keys(v)
          .filter(function (x) {
            return typeof v[x] === 'string';
          })
          .map(function (x) {
            return v[x];
          });
        row(
          k.replace(/_/g, ' '),
          h(
            'span',
            {},
            parts.join(', '),
            notes.length ? h('div', { class: 'small' }, notes.join(' ')) : null,
          ),
        );
      } else
        row(
          k.replace(/_/g, ' '),
          typeof v === 'object' ? h('code', {}, JSON.stringify(v)) : String(v),
        );
    });
    var grid = h('dl', { class: 'kv' }, rows);

    var vars = Array.isArray(report.variants) ? report.variants : [];
    var vt = null;
    var baseVar = vars.filter(function (v) {
      return v && v.name === report.baseline_variant;
    })[0];
    var baseOpts =
      baseVar && baseVar.options && typeof baseVar.options === 'object' ? baseVar.options : null;
    // The bound formula most variants share is printed once under the table.
    var formulas = {};
    vars.forEach(function (v) {
      if (v && v.bound && has(v.bound.formula))
        formulas[v.bound.formula] = (formulas[v.bound.formula] || 0) + 1;
    });
    var commonFormula =
      Object.keys(formulas).sort(function (a, b) {
        return formulas[b] - formulas[a];
      })[0] || null;
    // What ns/query includes, under the table: the variants with the same words on one line.
    var timing = [];
    vars.forEach(function (v) {
      var text = timingText(v, report),
        same = timing.filter(function (t) {
          return t.text === text;
        })[0];
      if (!text) return;
      if (same) same.names.push(String(v.name));
      else timing.push({ text: text, names: [String(v.name)] });
    });
    if (vars.length) {
      vt = h(
        'table',
        { class: 'data compact' },
        h(
          'thead',
          {},
          h(
            'tr',
            {},
            h('th', {}, 'Variant'),
            h('th', {}, 'Type'),
            h('th', {}, 'Options'),
            h('th', {}, 'Error bound'),
          ),
        ),
        h(
          'tbody',
          {},
          vars.map(function (v) {
            v = v || {};
            // Only what differs from the baseline variant's options: the table stays one line a row.
            var opts =
              v.options && typeof v.options === 'object'
                ? Object.keys(v.options)
                    .filter(function (k) {
                      return !baseOpts || baseOpts[k] !== v.options[k];
                    })
                    .map(function (k) {
                      return k + ': ' + v.options[k];
                    })
                    .join(', ')
                : '';
            if (!opts)
              opts =
                baseOpts && v.name !== report.baseline_variant
                  ? 'as baseline'
                  : 'reference options';
            var formula = v.bound && has(v.bound.formula) ? String(v.bound.formula) : null;
            var bound =
              v.bound && typeof v.bound === 'object'
                ? [
                    formula && formula !== commonFormula ? formula : null,
                    has(v.bound.unit_roundoff) ? 'u = ' + fmt(v.bound.unit_roundoff) : null,
                  ]
                    .filter(Boolean)
                    .join(', ')
                : '—';
            return h(
              'tr',
              {},
              h(
                'td',
                { class: 'variant-cell' },
                variantDot(String(v.name)),
                String(v.name),
                report.baseline_variant === v.name ? h('span', { class: 'tag' }, 'baseline') : null,
                comparisonTag(String(v.name)),
                v.warm === true ? h('span', { class: 'tag' }, 'warm start') : null,
              ),
              h('td', {}, has(v.type) ? String(v.type) : '—'),
              h('td', { class: 'small' }, pluginFile(v), opts),
              h('td', { class: 'small' }, bound),
            );
          }),
        ),
      );
    }
    append(sec, [
      h(
        'div',
        { class: 'context-grid' },
        grid,
        vt
          ? h(
              'div',
              {},
              h('h3', {}, 'Variants'),
              h('div', { class: 'table-wrap' }, vt),
              commonFormula
                ? h(
                    'p',
                    { class: 'small' },
                    'Error bound (unless stated in the row): ' + commonFormula,
                  )
                : null,
              timing.length
                ? h(
                    'div',
                    { class: 'small', id: 'timing-notes' },
                    'What ns / query includes:',
                    h(
                      'ul',
                      { class: 'plain' },
                      timing.map(function (t) {
                        return h(
                          'li',
                          { class: 'timing-note', 'data-timing-of': t.names.join('\n') },
                          h('b', {}, t.names.join(', ')),
                          ': ' + t.text,
                        );
                      }),
                    ),
                  )
                : null,
            )
          : null,
      ),
    ]);
    return sec;
  }

  // A figure of a variant's family stats (families[].variants[].KEY) weighted by the families'
  // cases; null when no family has it.
  function weightedFigure(v, report, key) {
    var sum = 0,
      cases = 0;
    families(report).forEach(function (f) {
      var st = familyVariants(f)[v.name];
      if (st && isNum(st[key]) && num(st.cases) > 0) {
        sum += num(st[key]) * num(st.cases);
        cases += num(st.cases);
      }
    });
    return cases > 0 ? sum / cases : null;
  }

  // What a variant's ns/query includes (report.variants[].timing) and, where it has a preparation
  // step, the ns to prepare one shape (families[].variants[].prepare_ns_per_shape); the figures
  // weighted by the families' cases; null for a report written before the field. gjk2d's own
  // variant: the plain query and, with a prepared form (timing.prepared.timed), both figures
  // (ns_per_query and prepared_ns_per_query), else why it has none. The same words as report.md's
  // timing table (validation/src/report/report.cpp, timingWords).
  function timingText(v, report) {
    var t = v && v.timing && typeof v.timing === 'object' ? v.timing : null;
    if (!t) return null;
    var prepare = weightedFigure(v, report, 'prepare_ns_per_shape');
    var perShape = prepare !== null ? fmt(prepare) + ' ns/shape to prepare' : null;
    if (t.preparation === 'none' && !v.plugin) {
      var p = t.prepared && typeof t.prepared === 'object' ? t.prepared : null;
      if (!p) return 'no preparation: the plain query takes the points as given';
      if (!p.timed) return 'the plain query, the points as given; ' + String(p.includes || '');
      var ns = function (key) {
        var x = weightedFigure(v, report, key);
        return x !== null ? fmt(x) : '—';
      };
      return [
        'plain: ' + ns('ns_per_query') + ' ns/query, the points as given',
        'prepared: ' + ns('prepared_ns_per_query') + ' ns/query, ' + String(p.includes || ''),
        perShape,
      ]
        .filter(Boolean)
        .join('; ');
    }
    return [
      has(t.includes) ? String(t.includes) : null,
      t.timed_by === 'adapter' ? 'timed by the adapter' : null,
      perShape,
    ]
      .filter(Boolean)
      .join('; ');
  }

  // The file a plugin's variant came from (report.variants[].plugin.path), for the variants table.
  function pluginFile(v) {
    if (!v.plugin || typeof v.plugin !== 'object' || !has(v.plugin.path)) return null;
    return h('div', { class: 'plugin-file' }, 'plugin file ', h('code', {}, String(v.plugin.path)));
  }

  // Judged variants first (they decide the verdict), then comparison variants; each group in the
  // report's order.
  function orderedVariants(report) {
    var names = variantNames(report);
    return names.filter(isJudged).concat(
      names.filter(function (n) {
        return !isJudged(n);
      }),
    );
  }

  function slug(s) {
    return String(s)
      .toLowerCase()
      .replace(/[^a-z0-9]+/g, '-')
      .replace(/^-|-$/g, '');
  }

  // Opens a family's detail and scrolls to it (heat map cells, family names, #family-... links).
  function openFamily(name, variant) {
    var d = document.getElementById('family-' + slug(name));
    if (!d) return;
    d.open = true;
    d.scrollIntoView({ block: 'start' });
    if (has(variant)) {
      var rows = d.querySelectorAll('tr[data-variant]');
      for (var i = 0; i < rows.length; ++i) {
        if (rows[i].getAttribute('data-variant') !== String(variant)) continue;
        var row = rows[i];
        row.classList.add('flash');
        setTimeout(function () {
          row.classList.remove('flash');
        }, 2500);
      }
    }
  }

  function openFromHash() {
    var id = decodeURIComponent(location.hash.slice(1));
    var el = id ? document.getElementById(id) : null;
    if (el && el.tagName === 'DETAILS') {
      el.open = true;
      el.scrollIntoView({ block: 'start' });
    }
  }

  // --- Heat map: families x variants ---------------------------------------------------------------

  // The counts every heat-map cell's hover text gives (Stats "cases", "refused", "skipped", "invalid"):
  // `cases` are the judged ones; refused (plugins) and skipped cases are not in it. A field an older
  // report lacks counts 0.
  function caseCounts(st) {
    st = st && typeof st === 'object' ? st : {};
    function c(k) {
      return isNum(st[k]) ? num(st[k]) : 0;
    }
    return {
      cases: c('cases'),
      refused: c('refused'),
      skipped: c('skipped'),
      invalid: c('invalid'),
    };
  }

  function countsText(k) {
    return (
      plural(k.cases, 'case') +
      ', ' +
      fmtInt(k.refused) +
      ' refused, ' +
      fmtInt(k.skipped) +
      ' skipped, ' +
      fmtInt(k.invalid) +
      ' invalid'
    );
  }

  // Why an answer was invalid (Stats "invalid_reasons", docs/report-schema.md), as "2 witness gap, ...".
  function invalidReasons(st) {
    var r =
      st && st.invalid_reasons && typeof st.invalid_reasons === 'object' ? st.invalid_reasons : {};
    return Object.keys(r)
      .filter(function (k) {
        return num(r[k]) > 0;
      })
      .map(function (k) {
        return fmtInt(r[k]) + ' ' + k.replace(/_/g, ' ');
      });
  }

  // What a heat-map cell shows for one family x variant: the worst error relative to the error
  // bound, or (a variant without a bound) the largest normalised error.
  // A family x variant with no judged case (cases 0: all refused, all skipped, or none) is "not run",
  // grey, never the colour of an error of 0.
  function cellValue(st) {
    if (!st || typeof st !== 'object') return { kind: 'missing' };
    if (!(caseCounts(st).cases > 0)) return { kind: 'notrun' };
    var hb = hist(st, 'bound_ratio');
    if (hb && has(hb.max) && !isNaN(num(hb.max))) return { kind: 'bound', v: num(hb.max) };
    var hn = hist(st, 'normalized');
    if (hn && has(hn.max) && !isNaN(num(hn.max))) return { kind: 'norm', v: num(hn.max) };
    return { kind: 'none' };
  }

  function mix(c0, c1, t) {
    var a = parseInt(c0.slice(1), 16),
      b = parseInt(c1.slice(1), 16);
    var r = [16, 8, 0].map(function (sh) {
      var x = (a >> sh) & 255,
        y = (b >> sh) & 255;
      return Math.round(x + (y - x) * t);
    });
    return (
      '#' +
      r
        .map(function (x) {
          return (x < 16 ? '0' : '') + x.toString(16);
        })
        .join('')
    );
  }

  function ramp(stops, t) {
    t = Math.max(0, Math.min(1, t));
    var k = Math.min(stops.length - 2, Math.floor(t * (stops.length - 1)));
    return mix(stops[k], stops[k + 1], t * (stops.length - 1) - k);
  }

  // Within the bound: pale (far below) to deep blue (at the bound), over 1e-4 .. 1. Beyond it: red.
  var BOUND_RAMP = ['#ffffd9', '#c7e9b4', '#7fcdbb', '#41b6c4', '#1d91c0', '#225ea8', '#0c2c84'];
  var BEYOND_RAMP = ['#f26b4f', '#c0392b', '#67000d'];
  // Normalised error (variants without a bound): 0.1 .. 1e3 u·R, pale to deep purple.
  var NORM_RAMP = ['#f6f3f9', '#d3cae6', '#9e8cc4', '#6a51a3', '#3f007d'];
  var BOUND_DECADES = [-4, 0],
    BEYOND_DECADES = [0, 3],
    NORM_DECADES = [-1, 3];

  function cellColor(c) {
    if (c.kind === 'bound') {
      if (!(c.v > 0)) return BOUND_RAMP[0];
      if (!isFinite(c.v)) return BEYOND_RAMP[2];
      var l = Math.log10(c.v);
      if (c.v > 1)
        return ramp(BEYOND_RAMP, (l - BEYOND_DECADES[0]) / (BEYOND_DECADES[1] - BEYOND_DECADES[0]));
      return ramp(BOUND_RAMP, (l - BOUND_DECADES[0]) / (BOUND_DECADES[1] - BOUND_DECADES[0]));
    }
    if (c.kind === 'norm') {
      if (!(c.v > 0)) return NORM_RAMP[0];
      if (!isFinite(c.v)) return NORM_RAMP[4];
      return ramp(
        NORM_RAMP,
        (Math.log10(c.v) - NORM_DECADES[0]) / (NORM_DECADES[1] - NORM_DECADES[0]),
      );
    }
    return '#ece9e3';
  }

  function darkColor(hex) {
    var x = parseInt(hex.slice(1), 16);
    return 0.299 * ((x >> 16) & 255) + 0.587 * ((x >> 8) & 255) + 0.114 * (x & 255) < 140;
  }

  // The width of a label in the page's font (a canvas measures it; an estimate without one).
  var measureCtx = null;
  function textWidth(s, px) {
    if (measureCtx === null) {
      var c = document.createElement('canvas');
      measureCtx = c.getContext ? c.getContext('2d') || false : false;
    }
    if (!measureCtx) return String(s).length * px * 0.58;
    measureCtx.font = px + 'px ' + getComputedStyle(document.body).fontFamily;
    return measureCtx.measureText(String(s)).width;
  }

  // A cell's hover text: what its colour shows, then its cases, refused, skipped and invalid answers
  // (every cell, 0 when the family has no statistics for the variant), failures and misclassified.
  function cellTip(f, n, st, c) {
    var k = caseCounts(st),
      fails = violationsOf(st);
    var und = st && isNum(st.undecidable) ? num(st.undecidable) : 0,
      reasons = invalidReasons(st);
    var verdict = ownContract(n)
      ? plural(fails, 'failure')
      : plural(fails, 'contract violation') +
        ' (breaks its contract), ' +
        fmtInt(outsideBoundOf(st)) +
        " outside gjk2d's bound";
    var why =
      k.refused > 0 && k.skipped > 0
        ? 'every case refused or skipped'
        : k.refused > 0
          ? 'every case refused by the implementation'
          : k.skipped > 0
            ? 'every case skipped'
            : 'no case';
    return (
      f.name +
      ' / ' +
      n +
      (isJudged(n) ? '' : ' (comparison, not judged)') +
      '\n' +
      (c.kind === 'bound'
        ? 'worst error / bound ' + fmt(c.v)
        : c.kind === 'norm'
          ? 'largest error ' + fmt(c.v) + ' u·R (no bound)'
          : c.kind === 'notrun'
            ? 'not run: ' + why
            : c.kind === 'missing'
              ? 'not run in this family'
              : 'no error recorded') +
      '\n' +
      countsText(k) +
      (reasons.length ? ' (' + reasons.join(', ') + ')' : '') +
      (st
        ? '\n' +
          verdict +
          ', ' +
          fmtInt(st ? wrongClass(st) : 0) +
          ' misclassified' +
          (und ? ', ' + fmtInt(und) + ' undecidable' : '')
        : '') +
      "\nclick: the family's detail"
    );
  }

  function renderHeatmap(report) {
    var fams = families(report),
      names = orderedVariants(report);
    var wrap = h('figure', { class: 'overview-part heatmap-part' });
    wrap.appendChild(
      h(
        'figcaption',
        { class: 'part-title' },
        'Where is each variant weakest? ',
        h(
          'span',
          { class: 'muted small' },
          "worst error / bound per family; click a cell for the family's detail",
        ),
      ),
    );
    if (!fams.length || !names.length) {
      wrap.appendChild(h('p', { class: 'note' }, 'No families or variants: nothing to map.'));
      return wrap;
    }
    var nJudged = names.filter(isJudged).length,
      gap = nJudged && nJudged < names.length ? 8 : 0;
    // Columns 24 px wide up to 18 variants; narrower beyond (to 16 px), so that the grid of the
    // default campaign's variants, the default peers' included, keeps the speed plot beside it.
    var cw = Math.max(16, Math.min(24, Math.floor(432 / names.length))),
      ch = 16,
      labelW =
        12 +
        Math.max.apply(
          null,
          fams
            .map(function (f) {
              return textWidth(f.name, 12);
            })
            .concat([60]),
        );
    var headH =
      14 +
      Math.max.apply(
        null,
        names.map(function (n) {
          return textWidth(n, 11.5);
        }),
      ) *
        Math.sin(Math.PI / 3);
    var x0 = labelW,
      y0 = headH,
      gridW = names.length * cw + gap,
      gridH = fams.length * ch;
    // The rotated names lean right: room for the last ones beyond the grid.
    var right = Math.max.apply(
      null,
      [12].concat(
        names.map(function (n, i) {
          return (
            i * cw +
            (i >= nJudged ? gap : 0) +
            cw / 2 +
            4 +
            textWidth(n, 11.5) * Math.cos(Math.PI / 3) -
            gridW
          );
        }),
      ),
    );
    // A bracket's label wider than its columns starts at the bracket's left end (room for it too).
    var COMP_LABEL = 'comparison, not judged';
    if (gap) right = Math.max(right, nJudged * cw + gap + textWidth(COMP_LABEL, 11) + 4 - gridW);
    var W = Math.ceil(x0 + gridW + right),
      H = Math.ceil(y0 + gridH + 30);
    var svg = sv('svg', {
      id: 'heatmap',
      class: 'plot heatmap',
      viewBox: '0 0 ' + W + ' ' + H,
      width: W,
      height: H,
      role: 'img',
      'aria-label': 'families by variants, coloured by the worst error relative to the bound',
    });
    function colX(i) {
      return x0 + i * cw + (i >= nJudged ? gap : 0);
    }
    // Column heads: variant names, rotated, in the variant's colour dot.
    names.forEach(function (n, i) {
      var cx = colX(i) + cw / 2;
      svg.appendChild(
        sv(
          'g',
          { class: 'hm-head' },
          setAttrs(markerShape(variantStyle(n).marker, cx, y0 - 6, 4), {
            fill: variantColor(n),
            stroke: 'rgba(0,0,0,.45)',
            'stroke-width': 0.7,
            'data-variant': n,
            'data-color': variantColor(n),
            'data-marker': variantStyle(n).marker,
          }),
          sv(
            'text',
            {
              x: cx + 2,
              y: y0 - 13,
              class: 'hm-col' + (isJudged(n) ? '' : ' comparison'),
              transform: 'rotate(-60 ' + (cx + 2) + ' ' + (y0 - 13) + ')',
            },
            n,
          ),
        ),
      );
    });
    // Rows: one per family.
    fams.forEach(function (f, r) {
      var y = y0 + r * ch,
        fv = familyVariants(f);
      var label = sv(
        'text',
        {
          x: x0 - 8,
          y: y + ch / 2 + 4,
          class: 'hm-row' + (f.pass === false ? ' bad' : ''),
          'text-anchor': 'end',
        },
        String(f.name),
      );
      label.addEventListener('click', function () {
        openFamily(f.name);
      });
      svg.appendChild(label);
      names.forEach(function (n, i) {
        var st = fv[n],
          c = cellValue(st),
          x = colX(i),
          fill = cellColor(c);
        var fails = violationsOf(st),
          wrong = st ? wrongClass(st) : 0;
        var tip = cellTip(f, n, st, c);
        var cell = sv(
          'g',
          {
            class: 'hm-cell',
            'data-family': String(f.name),
            'data-variant': n,
            'data-kind': c.kind,
            'data-fail': fails > 0 ? '1' : null,
            'data-wrong': wrong > 0 ? '1' : null,
          },
          svgTitle(tip),
        );
        cell.appendChild(
          sv('rect', {
            x: x + 0.5,
            y: y + 0.5,
            width: cw - 1,
            height: ch - 1,
            rx: 2,
            fill: fill,
            stroke: fails > 0 && isJudged(n) ? '#c0392b' : 'none',
            'stroke-width': fails > 0 && isJudged(n) ? 2 : 0,
          }),
        );
        if (c.kind === 'missing' || c.kind === 'notrun' || c.kind === 'none') {
          cell.appendChild(
            sv(
              'text',
              {
                x: x + cw / 2,
                y: y + ch / 2 + 4,
                class: 'hm-glyph muted-glyph',
                'text-anchor': 'middle',
              },
              '–',
            ),
          );
        }
        if (fails > 0) {
          cell.appendChild(
            sv('path', {
              d:
                'M' +
                (x + 7) +
                ' ' +
                (y + 4.5) +
                'l' +
                (cw - 14) +
                ' ' +
                (ch - 9) +
                'm0 ' +
                -(ch - 9) +
                'l' +
                -(cw - 14) +
                ' ' +
                (ch - 9),
              stroke: darkColor(fill) ? '#ffffff' : '#1a1a1a',
              'stroke-width': 2,
              'stroke-linecap': 'round',
            }),
          );
        }
        if (wrong > 0)
          cell.appendChild(
            sv('path', { d: 'M' + (x + cw - 8.5) + ' ' + (y + 1) + 'h7.5v7.5Z', fill: '#111' }),
          );
        cell.addEventListener('click', function () {
          openFamily(f.name, n);
        });
        svg.appendChild(cell);
      });
    });
    // Under the grid: which columns are judged and which are comparison variants.
    function bracket(i0, i1, text) {
      if (i1 < i0) return;
      var a = colX(i0) + 1,
        b = colX(i1) + cw - 1,
        y = y0 + gridH + 6;
      svg.appendChild(
        sv('path', { d: 'M' + a + ' ' + y + 'v4H' + b + 'v-4', fill: 'none', stroke: '#a39b8e' }),
      );
      // Too wide for its columns: the judged label ends at its bracket's right end, the other starts at its left end.
      var wide = textWidth(text, 11) > b - a,
        anchor = !wide ? 'middle' : i0 === 0 ? 'end' : 'start';
      svg.appendChild(
        sv(
          'text',
          {
            x: !wide ? (a + b) / 2 : i0 === 0 ? b : a,
            y: y + 17,
            class: 'legend-text small',
            'text-anchor': anchor,
          },
          text,
        ),
      );
    }
    if (gap) {
      bracket(0, nJudged - 1, 'judged');
      bracket(nJudged, names.length - 1, COMP_LABEL);
    }
    wrap.appendChild(h('div', { class: 'plot-wrap' }, svg));
    wrap.appendChild(heatLegend(fams, names));
    return wrap;
  }

  // Colour bars of the heat map's scales (the normalised one only when some cell uses it).
  function heatLegend(fams, names) {
    var kinds = {};
    fams.forEach(function (f) {
      var fv = familyVariants(f);
      names.forEach(function (n) {
        kinds[cellValue(fv[n]).kind] = true;
      });
    });
    function bar(stops, decades, label, extra) {
      var W = 150,
        x0 = 14,
        svg = sv('svg', { width: x0 + W + (extra ? 66 : 16), height: 30, class: 'legend-swatch' });
      var n = 24;
      for (var i = 0; i < n; ++i)
        svg.appendChild(
          sv('rect', {
            x: x0 + (i * W) / n,
            y: 2,
            width: W / n + 0.5,
            height: 10,
            fill: ramp(stops, (i + 0.5) / n),
          }),
        );
      if (extra)
        svg.appendChild(
          sv('rect', { x: x0 + W + 6, y: 2, width: 40, height: 10, fill: ramp(BEYOND_RAMP, 0.4) }),
        );
      for (var d = decades[0]; d <= decades[1]; ++d) {
        var x = x0 + ((d - decades[0]) / (decades[1] - decades[0])) * W;
        svg.appendChild(
          sv(
            'text',
            { x: x, y: 25, class: 'tick', 'text-anchor': 'middle', 'font-size': 10 },
            d === 0 ? '1' : '1e' + d,
          ),
        );
      }
      if (extra)
        svg.appendChild(
          sv(
            'text',
            { x: x0 + W + 26, y: 25, class: 'tick', 'text-anchor': 'middle', 'font-size': 10 },
            '> 1',
          ),
        );
      return h('span', { class: 'legend-item' }, label, svg);
    }
    var glyph = function (d, fill, stroke) {
      var s = sv(
        'svg',
        { width: 22, height: 16, class: 'legend-swatch' },
        sv('rect', {
          x: 1,
          y: 1,
          width: 20,
          height: 14,
          rx: 2,
          fill: fill || '#7fcdbb',
          stroke: stroke || 'none',
          'stroke-width': 2,
        }),
      );
      if (d) s.appendChild(sv('path', d));
      return s;
    };
    return h(
      'div',
      { class: 'legend heat-legend' },
      kinds.bound ? bar(BOUND_RAMP, BOUND_DECADES, 'error / bound', true) : null,
      kinds.norm ? bar(NORM_RAMP, NORM_DECADES, 'error / (u·R), no bound', false) : null,
      h(
        'span',
        { class: 'legend-item' },
        glyph(
          {
            d: 'M7 4.5l8 7m0 -7l-8 7',
            stroke: '#1a1a1a',
            'stroke-width': 2,
            'stroke-linecap': 'round',
          },
          null,
          '#c0392b',
        ),
        'failures or contract violations (red frame: judged)',
      ),
      h(
        'span',
        { class: 'legend-item' },
        glyph({ d: 'M13.5 1h7.5v7.5Z', fill: '#111' }),
        'false overlap or separation',
      ),
      h(
        'span',
        { class: 'legend-item' },
        glyph(null, '#ece9e3'),
        'not run (no judged case: refused, skipped or absent)',
      ),
    );
  }

  // --- Speed against error --------------------------------------------------------------------------

  var ALL_FAMILIES = '*';

  // The plot's items: one per variant, on one family or (ALL_FAMILIES) as a range over every family.
  function speedItems(report, family) {
    var names = orderedVariants(report),
      fams = families(report),
      items = [];
    names.forEach(function (n) {
      var rows = [];
      fams.forEach(function (f) {
        if (family !== ALL_FAMILIES && String(f.name) !== family) return;
        var st = familyVariants(f)[n];
        if (!scatterEligible(st)) return;
        var hn = hist(st, 'normalized');
        rows.push({
          family: String(f.name),
          ns: num(st.ns_per_query),
          p99: num(hn.p99),
          max: num(hn.max),
          st: st,
        });
      });
      if (!rows.length) return;
      if (family !== ALL_FAMILIES) {
        rows[0].variant = n;
        items.push(rows[0]);
        return;
      }
      // A family where the variant fails (gjk2d's own contract) or breaks its declared contract.
      var broke = function (r) {
        return ownContract(n) ? r.st.pass === false : violationsOf(r.st) > 0;
      };
      var med = function (xs) {
        xs = xs.filter(isFinite).sort(function (a, b) {
          return a - b;
        });
        return xs.length ? xs[(xs.length - 1) >> 1] : NaN;
      };
      var worst = rows.reduce(function (w, r) {
        return !w || (isFinite(r.max) && !(r.max <= w.max)) ? r : w;
      }, null);
      var nss = rows.map(function (r) {
        return r.ns;
      });
      items.push({
        variant: n,
        family: rows.length + ' families',
        ns: med(nss),
        nsLo: Math.min.apply(null, nss),
        nsHi: Math.max.apply(null, nss),
        p99: med(
          rows.map(function (r) {
            return r.p99;
          }),
        ),
        max: worst.max,
        worstFamily: worst.family,
        fails: rows.filter(broke).length,
        st: {
          pass: !rows.some(broke),
          failures: rows.reduce(function (a, r) {
            return a + (isNum(r.st.failures) ? num(r.st.failures) : 0);
          }, 0),
          contract_violations: {
            count: rows.reduce(function (a, r) {
              return a + violationsOf(r.st);
            }, 0),
          },
        },
      });
    });
    return items;
  }

  // The family the plot starts on: `random` when it has points, else the family with most cases.
  function defaultSpeedFamily(report) {
    var fams = families(report).filter(function (f) {
      return speedItems(report, String(f.name)).length > 0;
    });
    if (!fams.length) return null;
    var r = fams.filter(function (f) {
      return String(f.name) === 'random';
    })[0];
    if (r) return 'random';
    return String(
      fams.slice().sort(function (a, b) {
        return (num(b.cases) || 0) - (num(a.cases) || 0);
      })[0].name,
    );
  }

  function renderSpeed(report) {
    var wrap = h('figure', { class: 'overview-part speed-part', id: 'speed' });
    var fams = families(report)
      .map(function (f) {
        return String(f.name);
      })
      .filter(function (n) {
        return speedItems(report, n).length > 0;
      });
    var holder = h('div', { class: 'plot-wrap' });
    var first = defaultSpeedFamily(report);
    var select = h(
      'select',
      {
        class: 'speed-family',
        'aria-label': 'family',
        onchange: function (e) {
          draw(e.target.value);
        },
      },
      h('option', { value: ALL_FAMILIES }, 'all families: median and range per variant'),
      fams.map(function (n) {
        return h('option', { value: n, selected: n === first }, n);
      }),
    );
    wrap.appendChild(
      h(
        'figcaption',
        { class: 'part-title' },
        'What does accuracy cost in time? ',
        fams.length ? select : null,
      ),
    );
    wrap.appendChild(holder);
    function draw(family) {
      holder.textContent = '';
      holder.appendChild(
        guarded('speed plot', function () {
          return speedPlot(report, family);
        }),
      );
      holder.setAttribute('data-family', family);
    }
    if (first === null) {
      holder.appendChild(
        sv('svg', { id: 'scatter', class: 'plot', width: 10, height: 10, 'data-points': '0' }),
      );
      holder.appendChild(
        h(
          'p',
          { class: 'note' },
          'No family × variant has both a timing and a normalised error: nothing to plot' +
            (has(report.context && report.context.elapsed_s) &&
            !(num(report.context.elapsed_s.timing) > 0)
              ? ' (the run was not timed).'
              : '.'),
        ),
      );
    } else draw(first);
    wrap.appendChild(speedLegend(report));
    return wrap;
  }

  function speedLegend(report) {
    var names = orderedVariants(report);
    function item(n) {
      var s = sv('svg', { width: 16, height: 14, class: 'legend-swatch' });
      var m = markerShape(variantStyle(n).marker, 8, 7, 5);
      setAttrs(m, {
        fill: variantColor(n),
        stroke: '#333',
        'stroke-width': 0.8,
        'data-variant': n,
        'data-color': variantColor(n),
        'data-marker': variantStyle(n).marker,
      });
      s.appendChild(m);
      return h('span', { class: 'legend-item', 'data-variant': n }, s, n);
    }
    var judged = names.filter(isJudged),
      comp = names.filter(function (n) {
        return !isJudged(n);
      });
    return h(
      'div',
      { class: 'speed-legend' },
      judged.length
        ? h(
            'div',
            { class: 'legend' },
            h('span', { class: 'legend-group' }, 'judged'),
            judged.map(item),
          )
        : null,
      comp.length
        ? h(
            'div',
            { class: 'legend' },
            h('span', { class: 'legend-group' }, 'comparison'),
            comp.map(item),
          )
        : null,
      h(
        'div',
        { class: 'legend small' },
        legendItem('#bbb', "p99 error (the variant's marker)", 'circle'),
        legendItem('#888', 'max error', 'cap'),
        legendItem('#bbb', 'fails or breaks its contract (red outline)', 'ring-red'),
        h(
          'span',
          { class: 'legend-item muted' },
          'lower left is better; hover a marker for its numbers',
        ),
      ),
    );
  }

  function speedPlot(report, family) {
    var items = speedItems(report, family),
      all = family === ALL_FAMILIES;
    var W = 600,
      H = 430,
      box = { x0: 74, y0: 12, x1: W - 14, y1: H - 52 };
    var svg = sv('svg', {
      id: 'scatter',
      class: 'plot',
      viewBox: '0 0 ' + W + ' ' + H,
      width: W,
      height: H,
      role: 'img',
      'aria-label': 'time per query against normalised error',
      'data-points': String(items.length),
      'data-family': family,
    });
    if (!items.length) {
      svg.appendChild(
        sv(
          'text',
          { x: W / 2, y: H / 2, class: 'note-text', 'text-anchor': 'middle' },
          'nothing to plot for this family',
        ),
      );
      return svg;
    }
    var xsVals = [],
      ysVals = [];
    items.forEach(function (it) {
      xsVals.push(it.ns);
      if (all) xsVals.push(it.nsLo, it.nsHi);
      [it.p99, it.max].forEach(function (v) {
        if (isFinite(v) && v > 0) ysVals.push(v);
      });
    });
    var xd = logDomain(Math.min.apply(null, xsVals), Math.max.apply(null, xsVals), 0.06);
    var yd = ysVals.length
      ? logDomain(Math.min.apply(null, ysVals), Math.max.apply(null, ysVals), 0.3)
      : [0.1, 10];
    var zeroBand = items.some(function (it) {
      return !(it.p99 > 0) || !(it.max > 0);
    });
    var plotBox = { x0: box.x0, y0: box.y0, x1: box.x1, y1: zeroBand ? box.y1 - 26 : box.y1 };
    if (zeroBand) {
      svg.appendChild(
        sv('rect', {
          x: plotBox.x0,
          y: plotBox.y1 + 2,
          width: plotBox.x1 - plotBox.x0,
          height: 22,
          class: 'zero-band',
        }),
      );
      svg.appendChild(
        sv(
          'text',
          { x: plotBox.x0 - 6, y: plotBox.y1 + 17, class: 'tick', 'text-anchor': 'end' },
          '0',
        ),
      );
    }
    var xs = logScale(xd[0], xd[1], plotBox.x0 + 14, plotBox.x1 - 14);
    var ys = logScale(yd[0], yd[1], plotBox.y1 - 8, plotBox.y0 + 8);
    var g = sv('g', {});
    svg.appendChild(g);
    drawAxes(
      g,
      plotBox,
      xs,
      ys,
      logTicks(xd[0], xd[1]),
      logTicks(yd[0], yd[1]),
      'time per query  [ns, log scale]' + (all ? ': median over families, bar: range' : ''),
      'normalised error  [u·R, log]',
      { xLabelY1: box.y1 },
    );
    function yOf(v) {
      return v > 0 && isFinite(v) ? ys(v) : plotBox.y1 + 13;
    }
    var taken = [],
      labels = sv('g', { class: 'pt-labels' });
    items.forEach(function (it) {
      var x = xs(it.ns);
      [it.p99, it.max].forEach(function (v) {
        if (isFinite(v)) {
          var y = yOf(v);
          taken.push({ x0: x - 8, x1: x + 8, y0: y - 8, y1: y + 8 });
        }
      });
    });
    function free(b) {
      return (
        b.x0 >= plotBox.x0 &&
        b.x1 <= plotBox.x1 &&
        b.y0 >= plotBox.y0 &&
        b.y1 <= plotBox.y1 &&
        !taken.some(function (t) {
          return b.x0 < t.x1 && b.x1 > t.x0 && b.y0 < t.y1 && b.y1 > t.y0;
        })
      );
    }
    // A variant label at the first free spot beside its p99 marker; none when every spot is taken
    // (the legend and the marker's hover text name it then).
    function placeLabel(name, x, y) {
      var w = textWidth(name, 11) + 2,
        hgt = 12;
      var spots = [
        [x + 10, y + 4],
        [x - 10 - w, y + 4],
        [x + 9, y - 8],
        [x - 9 - w, y - 8],
        [x + 9, y + 16],
        [x - 9 - w, y + 16],
        [x - w / 2, y - 12],
        [x - w / 2, y + 22],
      ];
      for (var i = 0; i < spots.length; ++i) {
        var b = {
          x0: spots[i][0],
          x1: spots[i][0] + w,
          y0: spots[i][1] - hgt + 2,
          y1: spots[i][1] + 2,
        };
        if (!free(b)) continue;
        taken.push(b);
        labels.appendChild(
          sv('text', { x: spots[i][0], y: spots[i][1], class: 'pt-label', fill: '#3d3932' }, name),
        );
        return;
      }
    }
    var pointsG = sv('g', {});
    // Comparison variants under the judged ones.
    items
      .slice()
      .reverse()
      .forEach(function (it) {
        var c = variantColor(it.variant),
          x = xs(it.ns),
          judged = isJudged(it.variant);
        var own = ownContract(it.variant),
          failing = own ? it.st.pass === false : violationsOf(it.st) > 0;
        var tip =
          (all ? 'all families' : it.family) +
          ' / ' +
          it.variant +
          (judged ? '' : ' (comparison, not judged)') +
          '\n' +
          (all
            ? fmt(it.ns) +
              ' ns per query (median over ' +
              it.family +
              '; ' +
              fmt(it.nsLo) +
              ' – ' +
              fmt(it.nsHi) +
              ')\nnormalised error: median p99 ' +
              fmt(it.p99) +
              ', worst max ' +
              fmt(it.max) +
              ' (' +
              it.worstFamily +
              ')' +
              (it.fails
                ? (own ? '\nfails in ' : '\nbreaks its contract in ') +
                  plural(it.fails, 'family', 'families')
                : '')
            : fmt(it.ns) +
              ' ns per query' +
              (has(it.st.ratio_to_baseline)
                ? ' (' + fmt(it.st.ratio_to_baseline) + '× baseline)'
                : '') +
              '\nnormalised error p99 ' +
              fmt(it.p99) +
              ', max ' +
              fmt(it.max) +
              (failing
                ? !own
                  ? '\nbreaks its contract' +
                    (judged ? ' (' : ', not judged (') +
                    plural(violationsOf(it.st), 'contract violation') +
                    ')'
                  : (judged ? '\nFAIL (' : '\nfails, not judged (') +
                    plural(it.st.failures, 'failure') +
                    ')'
                : ''));
        var pg = sv(
          'g',
          {
            class: 'pt' + (judged ? ' judged' : ' comparison'),
            'data-variant': it.variant,
            'data-family': all ? ALL_FAMILIES : it.family,
          },
          svgTitle(tip),
        );
        var yp = isFinite(it.p99) ? yOf(it.p99) : null,
          ym = isFinite(it.max) ? yOf(it.max) : null;
        if (all)
          pg.appendChild(
            sv('line', {
              x1: xs(it.nsLo),
              x2: xs(it.nsHi),
              y1: yp === null ? ym : yp,
              y2: yp === null ? ym : yp,
              stroke: c,
              'stroke-width': 2.5,
              opacity: 0.55,
            }),
          );
        if (yp !== null && ym !== null)
          pg.appendChild(
            sv('line', {
              x1: x,
              x2: x,
              y1: yp,
              y2: ym,
              stroke: c,
              'stroke-width': 1.5,
              opacity: 0.7,
            }),
          );
        // The maximum: a cap at the end of the line from the p99 marker (not a marker shape: those are the variants').
        if (ym !== null)
          pg.appendChild(
            sv('path', {
              d: 'M' + (x - 6) + ' ' + ym + 'h12',
              stroke: c,
              'stroke-width': 3,
              'stroke-linecap': 'round',
              class: 'mk-max',
            }),
          );
        if (yp !== null) {
          var m = markerShape(variantStyle(it.variant).marker, x, yp, 6);
          setAttrs(m, {
            fill: c,
            stroke: failing ? '#c0392b' : '#333',
            'stroke-width': failing ? 2.5 : 0.8,
            class: 'mk-p99',
          });
          pg.appendChild(m);
        }
        pointsG.appendChild(pg);
      });
    g.appendChild(pointsG);
    items.forEach(function (it) {
      if (isFinite(it.p99)) placeLabel(it.variant, xs(it.ns), yOf(it.p99));
    });
    g.appendChild(labels);
    return svg;
  }

  function renderOverview(report) {
    var sec = section('overview', 'Overview');
    append(sec, [
      h(
        'div',
        { class: 'overview-grid' },
        guarded('heat map', function () {
          return renderHeatmap(report);
        }),
        guarded('speed against error', function () {
          return renderSpeed(report);
        }),
      ),
    ]);
    return sec;
  }

  // --- Families: the detail, one folded block each ----------------------------------------------------

  // One row per variant of the family, judged first; the table fits the page width (no family column,
  // breakdowns in the cell's hover text).
  function familyTable(f, report) {
    var names = orderedVariants(report),
      fv = familyVariants(f);
    var hasBound = names.some(function (n) {
      return hist(fv[n], 'bound_ratio');
    });
    var head1 = h(
      'tr',
      {},
      h('th', { rowspan: 2 }, 'Variant'),
      h('th', { rowspan: 2, class: 'num' }, 'Cases'),
      h(
        'th',
        { rowspan: 2, class: 'num', title: 'false overlap + false separation + undecidable' },
        'Mis\u00adclass.',
      ),
      h(
        'th',
        {
          rowspan: 2,
          class: 'num',
          title:
            "answers that break their implementation's own contract (gjk2d's variants: their failures), by reason below the count; below them, for an implementation with a contract of its own, the answers that keep it but are outside gjk2d's bound (a measured accuracy, not a failure)",
        },
        'Breaks contract',
      ),
      h(
        'th',
        {
          rowspan: 2,
          class: 'num',
          title:
            'answers that are no valid answer (a negative distance, a witness point off its shape, witness points further apart than the distance allows), each also a failure; by reason below the count',
        },
        'In\u00advalid',
      ),
      h('th', { colspan: 2, class: 'grp' }, 'Absolute error'),
      h('th', { colspan: 2, class: 'grp' }, 'Error [ulps]'),
      h('th', { colspan: 2, class: 'grp' }, 'Error / (u·R)'),
      hasBound ? h('th', { class: 'grp' }, 'Error / bound') : null,
      h('th', { colspan: 2, class: 'grp' }, 'Iterations'),
      h(
        'th',
        {
          rowspan: 2,
          class: 'num',
          title: 'median time per query; below it, the ratio to the baseline variant',
        },
        'ns / query',
      ),
      h('th', { rowspan: 2 }, 'Result'),
    );
    var head2 = h(
      'tr',
      {},
      ['max', 'p99', 'max', 'p99', 'max', 'p99']
        .concat(hasBound ? ['max'] : [], ['mean', 'max'])
        .map(function (t) {
          return h('th', { class: 'num sub' }, t);
        }),
    );
    var ncol = hasBound ? 16 : 15;
    var body = h('tbody', {});
    var present = names.filter(function (n) {
        return n in fv;
      }),
      missing = names.filter(function (n) {
        return !(n in fv);
      });
    var startedComparison = false;
    present.forEach(function (vn) {
      var st = fv[vn] || {};
      if (!isJudged(vn) && !startedComparison) {
        startedComparison = true;
        body.appendChild(
          h(
            'tr',
            { class: 'group-row' },
            h('td', { colspan: ncol }, 'Comparison variants: reported, not judged'),
          ),
        );
      }
      function detail(keys) {
        return keys
          .filter(function (k) {
            return num(st[k]) > 0;
          })
          .map(function (k) {
            return fmtInt(st[k]) + ' ' + k.replace(/_/g, ' ');
          });
      }
      var mis = misclassified(st);
      var misDetail = detail(['false_overlap', 'false_separation', 'undecidable']);
      var failDetail = detail([
        'nonfinite',
        'out_of_range',
        'iteration_limit',
        'crashed',
        'hung',
        'plugin_errors',
      ]);
      var rate =
        has(st.failure_rate_upper95) && isNum(st.failure_rate_upper95)
          ? 'failure rate < ' + fmt(st.failure_rate_upper95) + ' (upper 95 % bound)'
          : null;
      var ha = hist(st, 'abs'),
        hu = hist(st, 'ulps'),
        hn = hist(st, 'normalized'),
        hb = hist(st, 'bound_ratio');
      var it = st.iterations || {};
      var spread = Array.isArray(st.ns_spread)
        ? 'spread ' + fmt(st.ns_spread[0]) + ' – ' + fmt(st.ns_spread[1]) + ' ns'
        : null;
      var skipped =
        num(st.skipped) > 0
          ? fmtInt(st.skipped) +
            ' skipped' +
            (num(st.not_applicable) > 0
              ? ' (' + fmtInt(st.not_applicable) + ' not applicable)'
              : '')
          : null;
      body.appendChild(
        h(
          'tr',
          { 'data-variant': vn, class: isJudged(vn) ? 'judged-row' : 'comparison-row' },
          h('td', { class: 'variant-cell' }, variantDot(vn), vn),
          h(
            'td',
            { class: 'num', title: skipped },
            fmtInt(st.cases),
            skipped ? h('div', { class: 'small muted' }, fmtInt(st.skipped) + ' skipped') : null,
            num(st.refused) > 0
              ? h('div', { class: 'small muted' }, fmtInt(st.refused) + ' refused')
              : null,
          ), // plugins
          // Undecidable (within the error bound of the truth) is not a failure: red only for the rest.
          h(
            'td',
            {
              class: 'num' + (wrongClass(st) > 0 ? ' bad' : ''),
              title: misDetail.join(', ') || null,
            },
            fmtInt(mis),
            wrongClass(st) > 0 || num(st.undecidable) > 0
              ? h('div', { class: 'small' }, misDetail.join(', '))
              : null,
          ),
          violationCell(st, vn, [rate].concat(failDetail).filter(Boolean), failDetail),
          invalidCell(st, vn),
          h('td', { class: 'num' }, fmt(ha && ha.max)),
          h('td', { class: 'num' }, fmt(ha && ha.p99)),
          h('td', { class: 'num' }, fmt(hu && hu.max)),
          h('td', { class: 'num' }, fmt(hu && hu.p99)),
          h('td', { class: 'num' }, fmt(hn && hn.max)),
          h('td', { class: 'num' }, fmt(hn && hn.p99)),
          hasBound
            ? h('td', { class: 'num' + (hb && num(hb.max) > 1 ? ' bad' : '') }, fmt(hb && hb.max))
            : null,
          h('td', { class: 'num' }, fmt(it.mean)),
          h('td', { class: 'num' }, fmtInt(it.max)),
          h(
            'td',
            { class: 'num', title: spread },
            has(st.ns_per_query) ? fmt(st.ns_per_query) : '—',
            has(st.ratio_to_baseline) && vn !== report.baseline_variant
              ? h('div', { class: 'small muted' }, fmt(st.ratio_to_baseline) + '×')
              : null,
          ),
          h('td', {}, passBadge(st.pass, vn, st)),
        ),
      );
    });
    if (missing.length) {
      body.appendChild(
        h(
          'tr',
          { class: 'missing-row' },
          h(
            'td',
            { colspan: ncol, class: 'muted small' },
            'not run in this family: ' + missing.join(', '),
          ),
        ),
      );
    }
    return h(
      'div',
      { class: 'table-wrap' },
      h('table', { class: 'data summary' }, h('thead', {}, head1, head2), body),
    );
  }

  // --- Families: penetration -------------------------------------------------------------------------

  // A family x variant's penetration block (report.json families[].variants[].penetration: a
  // contract whose overlap answer is penetration, its depths on overlapping shapes), or null.
  function penetrationOf(st) {
    return st && st.penetration && typeof st.penetration === 'object' ? st.penetration : null;
  }

  // "x (case)" for a penetration histogram's largest value.
  function largestCell(hh, bad) {
    var has1 = hh && num(hh.count) > 0;
    return h(
      'td',
      {
        class: 'num' + (bad ? ' bad' : ''),
        title: has1 && has(hh.max_case) ? String(hh.max_case) : null,
      },
      has1 ? fmt(hh.max) : '—',
      has1 && has(hh.max_case)
        ? h('div', { class: 'small muted case-name' }, String(hh.max_case))
        : null,
    );
  }

  // The penetration verdict in words: gjk2d's own contract pass / FAIL; a declared one breaks it,
  // keeps it outside gjk2d's depth bound, or keeps it.
  function penetrationVerdict(p, vn) {
    var broken = num(p.contract_violations) > 0,
      outside = num(p.beyond_bound_keeping_contract) > 0;
    if (ownContract(vn)) return broken ? (isJudged(vn) ? 'FAIL' : 'fails (not judged)') : 'pass';
    return broken
      ? 'breaks its contract'
      : outside
        ? "outside gjk2d's depth bound"
        : 'keeps its contract';
  }

  // Beside the distance's table and histogram: the depth of each variant whose contract says
  // penetration, on the family's overlapping cases (exact signed distance < 0), against the exact
  // signed distance; a table and the histogram of error / gjk2d's depth bound. Null when no
  // variant of the family has the block.
  function penetrationBlock(f, present) {
    var fv = familyVariants(f);
    var names = present.filter(function (n) {
      return penetrationOf(fv[n]);
    });
    if (!names.length) return null;
    var head = h(
      'tr',
      {},
      [
        'Variant',
        'Overlapping cases',
        'Breaks contract',
        'Outside depth bound',
        'Max |d − s|',
        'Max rel. error',
        'Max error / depth bound',
        'p99 error / depth bound',
        'Result',
      ].map(function (t, i) {
        return h('th', { class: i > 0 && i < 8 ? 'num' : null }, t);
      }),
    );
    var body = h('tbody', {});
    var pseudo = { variants: {} }; // the histogram reads errors[metric], as the distance's does
    names.forEach(function (vn) {
      var p = penetrationOf(fv[vn]),
        verdict = penetrationVerdict(p, vn);
      var bad = verdict === 'FAIL' || verdict === 'breaks its contract';
      pseudo.variants[vn] = { errors: { bound_ratio: p.bound_ratio, abs: p.abs, rel: p.rel } };
      var w = p.worst_contract_violation;
      body.appendChild(
        h(
          'tr',
          { 'data-variant': vn, class: 'penetration-row' },
          h('td', { class: 'variant-cell' }, variantDot(vn), vn),
          h('td', { class: 'num' }, fmtInt(p.cases)),
          h(
            'td',
            {
              class: 'num' + (num(p.contract_violations) > 0 && isJudged(vn) ? ' bad' : ''),
              title: w ? w.reason + ' on ' + w.case : null,
            },
            fmtInt(p.contract_violations),
            w ? h('div', { class: 'small' }, w.reason + ' (' + w.case + ')') : null,
          ),
          h('td', { class: 'num' }, fmtInt(p.beyond_bound_keeping_contract)),
          largestCell(p.abs),
          largestCell(p.rel),
          largestCell(p.bound_ratio, p.bound_ratio && num(p.bound_ratio.max) > 1),
          h('td', { class: 'num' }, fmt(p.bound_ratio && p.bound_ratio.p99)),
          h('td', { class: 'penetration-verdict' + (bad ? ' bad' : '') }, verdict),
        ),
      );
    });
    var metric = {
      key: 'bound_ratio',
      label: 'depth error / depth bound',
      axis: "|d − s| / gjk2d's depth bound  [s: exact signed distance; ≤ 1 within]",
    };
    return h(
      'div',
      { class: 'penetration-block' },
      h(
        'div',
        { class: 'plot-title' },
        'Penetration: the depth on overlapping cases, against the exact signed distance',
      ),
      h(
        'div',
        { class: 'table-wrap' },
        h('table', { class: 'data summary penetration' }, h('thead', {}, head), body),
      ),
      h(
        'div',
        { class: 'plot-box' },
        errorHistogram(pseudo, metric, names),
        h(
          'div',
          { class: 'legend' },
          names.map(function (n) {
            return h('span', { class: 'legend-item' }, variantDot(n), n);
          }),
          legendItem('#555', 'p99', 'dash'),
        ),
      ),
    );
  }

  // The answers that break their implementation's contract (gjk2d's own: failures, with their kinds
  // below); for an implementation with a contract of its own, the reasons and the answers outside
  // gjk2d's bound that keep it.
  function violationCell(st, vn, tip, failDetail) {
    var n = violationsOf(st),
      own = ownContract(vn);
    var below = own
      ? failDetail
      : violationReasons(st).concat(
          outsideBoundOf(st) > 0 ? [fmtInt(outsideBoundOf(st)) + " outside gjk2d's bound"] : [],
        );
    return h(
      'td',
      {
        class: 'num' + (n > 0 && isJudged(vn) ? ' bad' : ''),
        title: (own ? tip : below).join(', ') || null,
      },
      fmtInt(n),
      below.length ? h('div', { class: 'small' }, below.join(', ')) : null,
    );
  }

  // The invalid answers of a family x variant (0 when an older report has no "invalid"), with their
  // reasons under the count and as hover text.
  function invalidCell(st, vn) {
    var n = caseCounts(st).invalid,
      reasons = invalidReasons(st);
    return h(
      'td',
      {
        class: 'num invalid-cell' + (n > 0 && isJudged(vn) ? ' bad' : ''),
        'data-invalid': String(n),
        title: reasons.join(', ') || null,
      },
      fmtInt(n),
      reasons.map(function (r) {
        return h('div', { class: 'reasons' }, r);
      }),
    );
  }

  // --- Families: histograms -------------------------------------------------------------------------

  function histRange(hists) {
    var lo = Infinity,
      hi = -Infinity;
    hists.forEach(function (hh) {
      var c = Array.isArray(hh.counts) ? hh.counts : [];
      for (var i = 0; i < c.length; ++i)
        if (num(c[i]) > 0) {
          lo = Math.min(lo, i);
          hi = Math.max(hi, i);
        }
    });
    return lo <= hi ? [lo, hi] : null;
  }

  function errorHistogram(fam, metric, names) {
    var fv = familyVariants(fam);
    var series = names
      .filter(function (n) {
        return hist(fv[n], metric.key);
      })
      .map(function (n) {
        return { name: n, h: hist(fv[n], metric.key) };
      });
    var W = 600,
      H = 290,
      box = { x0: 72, y0: 14, x1: W - 14, y1: H - 48 };
    var svg = sv('svg', { class: 'plot', viewBox: '0 0 ' + W + ' ' + H, width: W, height: H });
    if (!series.length) {
      svg.appendChild(
        sv(
          'text',
          { x: W / 2, y: H / 2, class: 'note-text', 'text-anchor': 'middle' },
          'no ' + metric.label + ' histogram in this family',
        ),
      );
      return svg;
    }
    // Bins in log10 units, per series (they may differ); common display range.
    var lmin = Infinity,
      lmax = -Infinity,
      ymax = 1,
      anyZeros = false;
    series.forEach(function (s) {
      var hh = s.h,
        l0 = isNum(hh.log10_min) ? num(hh.log10_min) : -40,
        bpd = num(hh.bins_per_decade) > 0 ? num(hh.bins_per_decade) : 10;
      var r = histRange([hh]);
      s.l0 = l0;
      s.bpd = bpd;
      if (r) {
        lmin = Math.min(lmin, l0 + r[0] / bpd);
        lmax = Math.max(lmax, l0 + (r[1] + 1) / bpd);
      }
      (hh.counts || []).forEach(function (c) {
        ymax = Math.max(ymax, num(c) || 0);
      });
      if (num(hh.zeros) > 0) {
        anyZeros = true;
        ymax = Math.max(ymax, num(hh.zeros));
      }
      [hh.p99, hh.max].forEach(function (v) {
        v = num(v);
        if (v > 0 && isFinite(v)) {
          lmin = Math.min(lmin, Math.log10(v));
          lmax = Math.max(lmax, Math.log10(v));
        }
      });
    });
    if (!(lmin <= lmax)) {
      lmin = -1;
      lmax = 1;
    }
    lmin = Math.floor(lmin - 0.3);
    lmax = Math.ceil(lmax + 0.3);
    var zeroW = anyZeros ? 34 : 0;
    var pbox = { x0: box.x0 + zeroW, y0: box.y0, x1: box.x1, y1: box.y1 };
    var xs = logScale(Math.pow(10, lmin), Math.pow(10, lmax), pbox.x0, pbox.x1);
    var ys = logScale(0.7, ymax * 1.6, pbox.y1, pbox.y0);
    var g = sv('g', {});
    svg.appendChild(g);
    var xticks = logTicks(Math.pow(10, lmin), Math.pow(10, lmax)).filter(function (t) {
      return !anyZeros || xs(t.v) > pbox.x0 + 12;
    });
    drawAxes(
      g,
      pbox,
      xs,
      ys,
      xticks,
      logTicks(0.7, ymax * 1.6).filter(function (t) {
        return t.major !== false;
      }),
      metric.axis,
      'cases  [log scale]',
      { yLabelX0: box.x0 },
    );
    if (anyZeros) {
      g.appendChild(
        sv('rect', {
          x: box.x0,
          y: pbox.y0,
          width: zeroW - 4,
          height: pbox.y1 - pbox.y0,
          class: 'zero-band',
        }),
      );
      g.appendChild(
        sv(
          'text',
          { x: box.x0 + (zeroW - 4) / 2, y: pbox.y1 + 16, class: 'tick', 'text-anchor': 'middle' },
          '0',
        ),
      );
    }
    var bw = series.length > 1 ? (zeroW - 8) / series.length : zeroW - 8;
    series.forEach(function (s, si) {
      var c = variantColor(s.name),
        hh = s.h,
        counts = hh.counts || [];
      var d = '',
        started = false,
        lastX = null;
      for (var i = 0; i < counts.length; ++i) {
        var cnt = num(counts[i]);
        var a = s.l0 + i / s.bpd,
          b = s.l0 + (i + 1) / s.bpd;
        if (b <= lmin || a >= lmax) continue;
        var xa = xs(Math.pow(10, Math.max(a, lmin))),
          xb = xs(Math.pow(10, Math.min(b, lmax)));
        var y = cnt > 0 ? ys(cnt) : pbox.y1;
        if (!started) {
          d += 'M' + xa.toFixed(2) + ' ' + pbox.y1;
          started = true;
        }
        d += 'L' + xa.toFixed(2) + ' ' + y.toFixed(2) + 'L' + xb.toFixed(2) + ' ' + y.toFixed(2);
        lastX = xb;
      }
      if (started) {
        d += 'L' + lastX.toFixed(2) + ' ' + pbox.y1 + 'Z';
        g.appendChild(
          sv(
            'path',
            { d: d, fill: c, 'fill-opacity': 0.18, stroke: c, 'stroke-width': 1.6 },
            svgTitle(s.name + ': ' + fmtInt(hh.count) + ' values'),
          ),
        );
      }
      if (num(hh.zeros) > 0) {
        var y0 = ys(num(hh.zeros));
        g.appendChild(
          sv(
            'rect',
            {
              x: box.x0 + 2 + si * bw,
              y: y0,
              width: Math.max(2, bw - 1),
              height: pbox.y1 - y0,
              fill: c,
              'fill-opacity': 0.55,
              stroke: c,
            },
            svgTitle(s.name + ': ' + fmtInt(hh.zeros) + ' exact zeros'),
          ),
        );
      }
      var p99 = num(hh.p99),
        mx = num(hh.max);
      if (p99 > 0 && isFinite(p99)) {
        var xp = xs(p99);
        g.appendChild(
          sv(
            'line',
            {
              x1: xp,
              x2: xp,
              y1: pbox.y0,
              y2: pbox.y1,
              stroke: c,
              'stroke-width': 1.4,
              'stroke-dasharray': '5 3',
            },
            svgTitle(s.name + ' p99 = ' + fmt(p99)),
          ),
        );
      }
      if (mx > 0 && isFinite(mx)) {
        var xm = xs(mx);
        g.appendChild(
          sv(
            'path',
            {
              d: 'M' + xm + ' ' + (pbox.y0 + 12) + ' l-5 -9 l10 0 Z',
              fill: c,
              stroke: '#333',
              'stroke-width': 0.6,
            },
            svgTitle(
              s.name + ' max = ' + fmt(mx) + (has(hh.max_case) ? ' (' + hh.max_case + ')' : ''),
            ),
          ),
        );
      }
    });
    return svg;
  }

  function iterationHistogram(fam, names) {
    var fv = familyVariants(fam);
    var series = names
      .filter(function (n) {
        return fv[n] && fv[n].iterations && Array.isArray(fv[n].iterations.counts);
      })
      .map(function (n) {
        return {
          name: n,
          counts: fv[n].iterations.counts.map(function (c) {
            return num(c) || 0;
          }),
        };
      });
    var W = 420,
      H = 260,
      box = { x0: 64, y0: 14, x1: W - 12, y1: H - 48 };
    var svg = sv('svg', { class: 'plot', viewBox: '0 0 ' + W + ' ' + H, width: W, height: H });
    if (!series.length) {
      svg.appendChild(
        sv(
          'text',
          { x: W / 2, y: H / 2, class: 'note-text', 'text-anchor': 'middle' },
          'no iteration counts',
        ),
      );
      return svg;
    }
    var last = 0,
      ymax = 1;
    series.forEach(function (s) {
      s.counts.forEach(function (c, i) {
        if (c > 0) last = Math.max(last, i);
        ymax = Math.max(ymax, c);
      });
    });
    var n = last + 1;
    var xs = linScale(-0.5, n - 0.5, box.x0, box.x1);
    var ys = linScale(0, ymax * 1.08, box.y1, box.y0);
    var g = sv('g', {});
    svg.appendChild(g);
    var xt = [];
    var stepT = Math.max(1, Math.ceil(n / 16));
    for (var i = 0; i < n; i += stepT) xt.push({ v: i });
    drawAxes(
      g,
      box,
      xs,
      ys,
      xt,
      linTicks(0, ymax * 1.08, 5),
      'GJK iterations  [support points found]',
      'cases',
    );
    var slot = (box.x1 - box.x0) / n,
      bw = (slot * 0.8) / series.length;
    series.forEach(function (s, si) {
      s.counts.forEach(function (c, i) {
        if (i >= n || !(c > 0)) return;
        var x = box.x0 + i * slot + slot * 0.1 + si * bw,
          y = ys(c);
        g.appendChild(
          sv(
            'rect',
            {
              x: x,
              y: y,
              width: Math.max(1, bw - 1),
              height: box.y1 - y,
              fill: variantColor(s.name),
              'fill-opacity': 0.8,
            },
            svgTitle(s.name + ': ' + fmtInt(c) + ' cases with ' + i + ' iterations'),
          ),
        );
      });
    });
    return svg;
  }

  function stopReasons(fam, names) {
    var fv = familyVariants(fam);
    var reasons = [];
    names.forEach(function (n) {
      var st = fv[n] && fv[n].stops;
      if (st && typeof st === 'object')
        Object.keys(st).forEach(function (k) {
          if (num(st[k]) > 0 && reasons.indexOf(k) < 0) reasons.push(k);
        });
    });
    var wrap = h('div', { class: 'stops' });
    if (!reasons.length) {
      wrap.appendChild(h('p', { class: 'note' }, 'no stop reasons recorded'));
      return wrap;
    }
    names.forEach(function (n) {
      var st = fv[n] && fv[n].stops;
      if (!st) return;
      var total = reasons.reduce(function (s, k) {
        return s + (num(st[k]) || 0);
      }, 0);
      var bar = h('div', { class: 'stop-bar' });
      reasons.forEach(function (k, i) {
        var c = num(st[k]) || 0;
        if (!(c > 0) || !(total > 0)) return;
        var frac = c / total;
        bar.appendChild(
          h(
            'span',
            {
              class: 'stop-seg',
              style: 'width:' + 100 * frac + '%;background:' + STOP_COLORS[i % STOP_COLORS.length],
              title: n + ': ' + k + ' ' + fmtInt(c) + ' (' + pct(frac) + ')',
            },
            frac > 0.12 ? pct(frac) : '',
          ),
        );
      });
      wrap.appendChild(
        h('div', { class: 'stop-row' }, h('span', { class: 'stop-name' }, variantDot(n), n), bar),
      );
    });
    wrap.appendChild(
      h(
        'div',
        { class: 'legend' },
        reasons.map(function (k, i) {
          return legendItem(STOP_COLORS[i % STOP_COLORS.length], k);
        }),
      ),
    );
    return wrap;
  }

  function renderFamilies(report) {
    var sec = section(
      'families',
      'Families',
      "One folded block per family: click a family (or a heat-map cell) to open it. Inside: the make-up checks, a row per variant (judged variants first; errors are |d_gjk − d_exact|, absolute, in ulps of the exact distance and normalised by u·R, u the type's unit roundoff and R the largest coordinate of A − B in the compute frame; p99 is read from the histogram bins, upper edge; misclassified: false overlap, false separation or undecidable, the last not a failure), the error histogram (choose the measure; exact zeros in the grey band on the left, dashed lines at p99, triangles at the maximum), iterations and stop reasons.",
    );
    var fams = families(report);
    if (!fams.length) {
      sec.appendChild(h('p', { class: 'note' }, 'This report has no families.'));
      return sec;
    }
    var blocks = [];
    function openAll(open) {
      blocks.forEach(function (d) {
        d.open = open;
      });
    }
    sec.appendChild(
      h(
        'p',
        { class: 'small family-tools' },
        h(
          'button',
          {
            type: 'button',
            class: 'open-all',
            onclick: function () {
              openAll(true);
            },
          },
          'open all',
        ),
        ' ',
        h(
          'button',
          {
            type: 'button',
            class: 'close-all',
            onclick: function () {
              openAll(false);
            },
          },
          'close all',
        ),
      ),
    );
    fams.forEach(function (f) {
      var block = guarded('family ' + f.name, function () {
        return renderFamily(f, report);
      });
      if (block.tagName === 'DETAILS') blocks.push(block);
      sec.appendChild(block);
    });
    return sec;
  }

  function renderFamily(f, report) {
    var names = orderedVariants(report);
    var fv = familyVariants(f);
    var present = names.filter(function (n) {
      return n in fv;
    });
    var judgedFails = 0,
      compFails = 0,
      wrong = 0;
    present.forEach(function (n) {
      var x = violationsOf(fv[n]);
      if (isJudged(n)) judgedFails += x;
      else compFails += x;
      wrong += wrongClass(fv[n] || {});
    });
    var makeupBad =
      Array.isArray(f.makeup) &&
      f.makeup.some(function (m) {
        return m && m.ok === false;
      });
    var card = h('details', {
      class: 'family',
      id: 'family-' + slug(f.name),
      'data-family': String(f.name),
    });
    card.appendChild(
      h(
        'summary',
        {},
        h(
          'h3',
          {},
          String(f.name),
          h('span', { class: 'muted small' }, fmtInt(f.cases) + ' cases'),
          passBadge(f.pass),
          judgedFails ? h('span', { class: 'bad small' }, plural(judgedFails, 'failure')) : null,
          compFails
            ? h(
                'span',
                { class: 'small muted' },
                plural(compFails, 'contract violation') + ' in comparison variants (not judged)',
              )
            : null,
          wrong ? h('span', { class: 'small muted' }, fmtInt(wrong) + ' misclassified') : null,
          makeupBad ? h('span', { class: 'bad small' }, 'make-up check failed') : null,
        ),
      ),
    );
    if (Array.isArray(f.makeup) && f.makeup.length) {
      card.appendChild(
        h(
          'div',
          { class: 'makeup' },
          h('span', { class: 'muted small' }, 'Makeup: '),
          f.makeup.map(function (m) {
            m = m || {};
            return h(
              'span',
              { class: 'makeup-item ' + (m.ok === false ? 'bad' : 'ok') },
              (m.ok === false ? '✗ ' : '✓ ') +
                m.check +
                ' ' +
                fmt(m.value) +
                (has(m.min) || has(m.max) ? ' (in [' + fmt(m.min) + ', ' + fmt(m.max) + '])' : ''),
            );
          }),
        ),
      );
    }
    card.appendChild(familyTable(f, report));
    var pen = penetrationBlock(f, present);
    if (pen) card.appendChild(pen);
    var metrics = METRICS.filter(function (m) {
      return present.some(function (n) {
        return hist(fv[n], m.key);
      });
    });
    var histHolder = h('div', { class: 'hist-holder' });
    var current = metrics.length ? metrics[0] : METRICS[0];
    function draw() {
      histHolder.textContent = '';
      histHolder.appendChild(errorHistogram(f, current, present));
    }
    var select = h(
      'select',
      {
        class: 'metric-select',
        onchange: function (e) {
          current =
            metrics.filter(function (m) {
              return m.key === e.target.value;
            })[0] || current;
          draw();
        },
      },
      metrics.map(function (m) {
        return h('option', { value: m.key }, m.label);
      }),
    );
    draw();
    var legend = h(
      'div',
      { class: 'legend' },
      present.map(function (n) {
        return h('span', { class: 'legend-item' }, variantDot(n), n);
      }),
      legendItem('#555', 'p99', 'dash'),
    );
    card.appendChild(
      h(
        'div',
        { class: 'family-plots' },
        h(
          'div',
          { class: 'plot-box' },
          h('div', { class: 'plot-title' }, 'Error distribution ', metrics.length ? select : null),
          histHolder,
          legend,
        ),
        h(
          'div',
          { class: 'plot-box' },
          h('div', { class: 'plot-title' }, 'Iterations'),
          iterationHistogram(f, present),
          h('div', { class: 'plot-title' }, 'Stop reasons'),
          stopReasons(f, present),
        ),
      ),
    );
    var worst = Array.isArray(report.worst)
      ? report.worst.filter(function (w) {
          return w && String(w.family) === String(f.name);
        })[0]
      : null;
    if (worst)
      card.appendChild(
        h(
          'p',
          { class: 'small' },
          "The family's worst case, ",
          h('code', {}, String(worst.name)),
          ', is drawn under ',
          h('a', { href: '#' + viewerAnchor(worst) }, 'Worst cases'),
          '.',
        ),
      );
    return card;
  }

  function viewerAnchor(w) {
    return 'worst-' + slug(w.name || '');
  }

  function renderWorst(report) {
    var sec = section(
      'worst',
      'Worst cases',
      "The worst case of each family (over all variants), drawn. Left: the shapes in world coordinates with the exact closest points (black) and GJK's (variant colour). Right: the Minkowski difference Z = A − B with the origin, GJK's simplex, its closest point to the origin and the search direction at the chosen iteration. Step with the buttons, the slider or the arrow keys.",
    );
    var worst = Array.isArray(report.worst)
      ? report.worst.filter(function (w) {
          return w && typeof w === 'object';
        })
      : [];
    if (!worst.length) {
      sec.appendChild(h('p', { class: 'note' }, 'This report has no worst cases.'));
      return sec;
    }
    worst.forEach(function (w, i) {
      sec.appendChild(
        h(
          'div',
          { id: viewerAnchor(w) },
          guarded('worst case ' + (w.name || i), function () {
            return new Viewer(w, report).root;
          }),
        ),
      );
    });
    return sec;
  }

  function renderRejected(report) {
    var sec = section('rejected', 'Rejected inputs');
    var rej = Array.isArray(report.rejected) ? report.rejected : [];
    if (!rej.length) {
      sec.appendChild(h('p', { class: 'note' }, 'No input was rejected.'));
    } else {
      sec.appendChild(
        h(
          'div',
          { class: 'table-wrap' },
          h(
            'table',
            { class: 'data compact' },
            h('thead', {}, h('tr', {}, h('th', {}, 'Input'), h('th', {}, 'Reason'))),
            h(
              'tbody',
              {},
              rej.map(function (r) {
                r = r || {};
                return h(
                  'tr',
                  {},
                  h('td', {}, h('code', {}, String(r.name))),
                  h('td', {}, String(r.reason)),
                );
              }),
            ),
          ),
        ),
      );
    }
    if (has(report.worst_cases_file))
      sec.appendChild(
        h(
          'p',
          { class: 'small muted' },
          'The worst cases are also in ',
          h('code', {}, String(report.worst_cases_file)),
          ' (replay them with gjk-validate explain).',
        ),
      );
    return sec;
  }

  // --- Geometry for the viewer ------------------------------------------------------------------------

  function cross3(o, a, b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  }

  // Convex hull (Andrew's monotone chain), positive orientation in the points' own coordinates.
  function hull(points) {
    var p = points.slice().sort(function (a, b) {
      return a[0] - b[0] || a[1] - b[1];
    });
    var u = [];
    for (var i = 0; i < p.length; ++i)
      if (!u.length || u[u.length - 1][0] !== p[i][0] || u[u.length - 1][1] !== p[i][1])
        u.push(p[i]);
    p = u;
    if (p.length <= 2) return p;
    var lower = [],
      upper = [];
    p.forEach(function (q) {
      while (lower.length >= 2 && cross3(lower[lower.length - 2], lower[lower.length - 1], q) <= 0)
        lower.pop();
      lower.push(q);
    });
    for (var j = p.length - 1; j >= 0; --j) {
      var q = p[j];
      while (upper.length >= 2 && cross3(upper[upper.length - 2], upper[upper.length - 1], q) <= 0)
        upper.pop();
      upper.push(q);
    }
    var out = lower.slice(0, -1).concat(upper.slice(0, -1));
    return out.length ? out : [p[0], p[p.length - 1]];
  }

  // The polygon grown by r (pixel units), as a polygon: arcs sampled finely where they can be seen.
  function rounded(poly, r, view) {
    if (!(r > 0.3) || !poly.length) return poly;
    var n = poly.length,
      out = [];
    var cx = view.W / 2,
      cy = view.H / 2,
      diag = Math.hypot(view.W, view.H);
    // Orientation: positive area turns left; outward normal of edge e is (e.y, -e.x) then.
    var area = 0;
    for (var i = 0; i < n; ++i) area += cross3([0, 0], poly[i], poly[(i + 1) % n]);
    var sgn = area < 0 ? -1 : 1;
    for (var k = 0; k < n; ++k) {
      var v = poly[k],
        prev = poly[(k - 1 + n) % n],
        next = poly[(k + 1) % n];
      var t0, t1;
      if (n === 1) {
        t0 = 0;
        t1 = 2 * Math.PI;
      } else {
        var ein = [v[0] - prev[0], v[1] - prev[1]],
          eout = [next[0] - v[0], next[1] - v[1]];
        t0 = Math.atan2(-sgn * ein[0], sgn * ein[1]);
        t1 = Math.atan2(-sgn * eout[0], sgn * eout[1]);
        var dlt = (t1 - t0) * sgn;
        while (dlt < 0) dlt += 2 * Math.PI;
        while (dlt > 2 * Math.PI) dlt -= 2 * Math.PI;
        if (n === 2 && dlt < 1e-12) dlt = Math.PI;
        t1 = t0 + sgn * dlt;
      }
      var angles = arcAngles(t0, t1, r, v, cx, cy, diag);
      angles.forEach(function (a) {
        out.push([v[0] + r * Math.cos(a), v[1] + r * Math.sin(a)]);
      });
    }
    return out;
  }

  // Angles from t0 to t1 for an arc of radius r around v: chords within a quarter pixel of the arc
  // where it is near the view, a few samples elsewhere (off view).
  function arcAngles(t0, t1, r, v, cx, cy, diag) {
    var span = t1 - t0,
      step = Math.min(0.25, Math.sqrt(2 / r));
    var count = Math.ceil(Math.abs(span) / step);
    var out = [],
      i;
    if (count <= 720) {
      for (i = 0; i <= count; ++i) out.push(t0 + (span * i) / Math.max(1, count));
      return out;
    }
    var phi = Math.atan2(cy - v[1], cx - v[0]),
      alpha = (3 * diag) / r;
    var lo = Math.min(t0, t1),
      hi = Math.max(t0, t1);
    // Bring phi into [lo, hi] if some turn of it is.
    while (phi < lo - alpha) phi += 2 * Math.PI;
    while (phi > hi + alpha) phi -= 2 * Math.PI;
    var d0 = Math.max(lo, phi - alpha),
      d1 = Math.min(hi, phi + alpha);
    var list = [];
    for (i = 0; i <= 48; ++i) list.push(lo + ((hi - lo) * i) / 48);
    if (d0 < d1) {
      var m = Math.min(2000, Math.ceil((d1 - d0) / step));
      for (i = 0; i <= m; ++i) list.push(d0 + ((d1 - d0) * i) / Math.max(1, m));
    }
    list.sort(function (a, b) {
      return a - b;
    });
    if (t1 < t0) list.reverse();
    return list;
  }

  // Sutherland-Hodgman clip of a convex polygon to a rectangle.
  function clipPoly(poly, rc) {
    var edges = [
      function (p) {
        return p[0] >= rc.x0;
      },
      function (p) {
        return p[0] <= rc.x1;
      },
      function (p) {
        return p[1] >= rc.y0;
      },
      function (p) {
        return p[1] <= rc.y1;
      },
    ];
    var cuts = [
      function (a, b) {
        var t = (rc.x0 - a[0]) / (b[0] - a[0]);
        return [rc.x0, a[1] + t * (b[1] - a[1])];
      },
      function (a, b) {
        var t = (rc.x1 - a[0]) / (b[0] - a[0]);
        return [rc.x1, a[1] + t * (b[1] - a[1])];
      },
      function (a, b) {
        var t = (rc.y0 - a[1]) / (b[1] - a[1]);
        return [a[0] + t * (b[0] - a[0]), rc.y0];
      },
      function (a, b) {
        var t = (rc.y1 - a[1]) / (b[1] - a[1]);
        return [a[0] + t * (b[0] - a[0]), rc.y1];
      },
    ];
    var out = poly;
    for (var e = 0; e < 4 && out.length; ++e) {
      var inp = out,
        inside = edges[e];
      out = [];
      for (var i = 0; i < inp.length; ++i) {
        var a = inp[i],
          b = inp[(i + 1) % inp.length];
        var ia = inside(a),
          ib = inside(b);
        if (ia) out.push(a);
        if (ia !== ib) out.push(cuts[e](a, b));
      }
    }
    return out;
  }

  // Liang-Barsky clip of a segment; null when outside.
  function clipSeg(a, b, rc) {
    var t0 = 0,
      t1 = 1,
      dx = b[0] - a[0],
      dy = b[1] - a[1];
    var p = [-dx, dx, -dy, dy],
      q = [a[0] - rc.x0, rc.x1 - a[0], a[1] - rc.y0, rc.y1 - a[1]];
    for (var i = 0; i < 4; ++i) {
      if (p[i] === 0) {
        if (q[i] < 0) return null;
        continue;
      }
      var t = q[i] / p[i];
      if (p[i] < 0) {
        if (t > t1) return null;
        if (t > t0) t0 = t;
      } else {
        if (t < t0) return null;
        if (t < t1) t1 = t;
      }
    }
    return [
      [a[0] + t0 * dx, a[1] + t0 * dy],
      [a[0] + t1 * dx, a[1] + t1 * dy],
    ];
  }

  function pathOf(poly, close) {
    if (!poly.length) return '';
    var d = 'M' + poly[0][0].toFixed(2) + ' ' + poly[0][1].toFixed(2);
    for (var i = 1; i < poly.length; ++i)
      d += 'L' + poly[i][0].toFixed(2) + ' ' + poly[i][1].toFixed(2);
    return d + (close ? 'Z' : '');
  }

  function bbox(points) {
    var b = { x0: Infinity, y0: Infinity, x1: -Infinity, y1: -Infinity };
    points.forEach(function (p) {
      growBox(b, p, 0);
    });
    return b;
  }

  function growBox(b, p, r) {
    if (!finitePoint(p)) return;
    r = r || 0;
    b.x0 = Math.min(b.x0, p[0] - r);
    b.x1 = Math.max(b.x1, p[0] + r);
    b.y0 = Math.min(b.y0, p[1] - r);
    b.y1 = Math.max(b.y1, p[1] + r);
  }

  function boxOk(b) {
    return isFinite(b.x0) && isFinite(b.x1) && isFinite(b.y0) && isFinite(b.y1);
  }

  // A world-to-pixel map fitting box b into W x H with a margin. Differences to the centre are taken
  // in double before scaling, so shapes 1e9 from the origin keep their small features.
  function makeView(b, W, H, margin, minSpan) {
    if (!boxOk(b)) b = { x0: -1, y0: -1, x1: 1, y1: 1 };
    var cx = b.x0 / 2 + b.x1 / 2,
      cy = b.y0 / 2 + b.y1 / 2;
    var w = b.x1 - b.x0,
      hgt = b.y1 - b.y0;
    var span = Math.max(w, hgt);
    var floor = minSpan > 0 ? minSpan : 0;
    if (!(span > floor))
      span = floor > 0 ? floor : Math.max(Math.abs(cx), Math.abs(cy)) * 1e-3 || 1;
    w = Math.max(w, span * 1e-3);
    hgt = Math.max(hgt, span * 1e-3);
    if (w < floor) w = floor;
    if (hgt < floor) hgt = floor;
    var scale = Math.min((W - 2 * margin) / w, (H - 2 * margin) / hgt);
    if (!(scale > 0) || !isFinite(scale)) scale = 1;
    var v = { W: W, H: H, cx: cx, cy: cy, s: scale };
    v.x = function (x) {
      return W / 2 + (x - cx) * scale;
    };
    v.y = function (y) {
      return H / 2 - (y - cy) * scale;
    };
    v.p = function (p) {
      return [v.x(p[0]), v.y(p[1])];
    };
    v.rect = { x0: -40, y0: -40, x1: W + 40, y1: H + 40 };
    v.inside = function (q) {
      return q[0] >= -20 && q[0] <= W + 20 && q[1] >= -20 && q[1] <= H + 20;
    };
    return v;
  }

  // Light grid with tick labels in world units. Far from the origin (the ticks' values would need
  // more digits than fit), labels are offsets from a reference shown in the corner.
  function drawGrid(g, v, labelsG) {
    var spanX = v.W / v.s,
      spanY = v.H / v.s;
    var step = niceStep(Math.max(spanX, spanY), 7);
    var big = Math.max(Math.abs(v.cx), Math.abs(v.cy)) / step > 1e5;
    var refX = big ? Math.round(v.cx / step) * step : 0,
      refY = big ? Math.round(v.cy / step) * step : 0;
    var gx = sv('g', { class: 'grid-g' }),
      gl = sv('g', { class: 'grid-labels' });
    // Tick k sits at world refX + k*step, drawn at pixel x(refX) + k*step*s (no large sums formed).
    var px0 = v.W / 2 + (refX - v.cx) * v.s,
      py0 = v.H / 2 - (refY - v.cy) * v.s;
    var kx0 = Math.ceil((0 - px0) / (step * v.s)),
      kx1 = Math.floor((v.W - px0) / (step * v.s));
    var ky0 = Math.ceil((py0 - v.H) / (step * v.s)),
      ky1 = Math.floor(py0 / (step * v.s));
    var axisX = !big && v.x(0) > 0 && v.x(0) < v.W,
      axisY = !big && v.y(0) > 0 && v.y(0) < v.H;
    function label(k) {
      var val = k * step;
      var s = Math.abs(val) < step * 1e-6 ? '0' : fmt(val, 3);
      return big ? (val >= 0 ? '+' : '') + s.replace('−', '−') : s;
    }
    var k;
    for (k = kx0; k <= kx1 && k - kx0 < 60; ++k) {
      var x = px0 + k * step * v.s;
      gx.appendChild(
        sv('line', {
          x1: x,
          x2: x,
          y1: 0,
          y2: v.H,
          class: k === 0 && !big ? 'grid-axis' : 'grid-line',
        }),
      );
      gl.appendChild(
        sv(
          'text',
          { x: x + 2, y: v.H - 4, class: 'grid-label' },
          label(k + (big ? 0 : refX / step)),
        ),
      );
    }
    for (k = ky0; k <= ky1 && k - ky0 < 60; ++k) {
      var y = py0 - k * step * v.s;
      gx.appendChild(
        sv('line', {
          x1: 0,
          x2: v.W,
          y1: y,
          y2: y,
          class: k === 0 && !big ? 'grid-axis' : 'grid-line',
        }),
      );
      gl.appendChild(
        sv('text', { x: 3, y: y - 3, class: 'grid-label' }, label(k + (big ? 0 : refY / step))),
      );
    }
    if (big) {
      gl.appendChild(
        sv(
          'text',
          { x: v.W - 6, y: 14, class: 'grid-ref', 'text-anchor': 'end' },
          'tick labels relative to (' + fmtFull(refX) + ', ' + fmtFull(refY) + ')',
        ),
      );
    }
    gl.appendChild(
      sv(
        'text',
        { x: v.W - 6, y: v.H - 18, class: 'grid-ref', 'text-anchor': 'end' },
        'grid step ' + fmt(step) + ' world units',
      ),
    );
    void axisX;
    void axisY;
    g.appendChild(gx);
    labelsG.appendChild(gl);
  }

  // --- The iteration viewer ----------------------------------------------------------------------------

  var viewerCount = 0;

  function Viewer(detail, report) {
    this.d = detail;
    this.id = 'viewer-' + ++viewerCount;
    var vmap = detail.variants && typeof detail.variants === 'object' ? detail.variants : {};
    this.variants = Object.keys(vmap);
    // Order: the report's variant order first.
    if (report && Array.isArray(report.variants)) {
      var order = report.variants.map(function (v) {
        return v && String(v.name);
      });
      this.variants.sort(function (a, b) {
        var ia = order.indexOf(a),
          ib = order.indexOf(b);
        return (ia < 0 ? 1e9 : ia) - (ib < 0 ? 1e9 : ib);
      });
    }
    // Start on the variant this case is worst for, among those with an iteration trace (a
    // plugin's variant has none: docs/validate-your-gjk.md).
    var by = detail.worst_by || 'normalized',
      best = null,
      bestErr = -Infinity,
      traced = null;
    this.variants.forEach(function (n) {
      if (!vmap[n] || !Array.isArray(vmap[n].trace)) return;
      traced = traced || n;
      var e = vmap[n].errors ? num(vmap[n].errors[by]) : NaN;
      if (isFinite(e) && e > bestErr) {
        bestErr = e;
        best = n;
      }
    });
    this.variant = best || traced || this.variants[0] || null;
    this.step = 0;
    this.zoom = false;
    this.build();
    this.draw();
  }

  Viewer.prototype.vdata = function () {
    var vmap = this.d.variants || {};
    return (this.variant && vmap[this.variant]) || {};
  };

  Viewer.prototype.trace = function () {
    var t = this.vdata().trace;
    return Array.isArray(t)
      ? t.filter(function (s) {
          return s && typeof s === 'object';
        })
      : [];
  };

  Viewer.prototype.build = function () {
    var self = this,
      d = this.d;
    var ex = d.exact || {};
    this.root = h('div', {
      class: 'viewer',
      id: this.id,
      tabindex: 0,
      'data-case': has(d.name) ? String(d.name) : '',
    });
    this.root.addEventListener('keydown', function (e) {
      if (e.target && e.target.tagName === 'SELECT') return;
      if (e.key === 'ArrowRight') {
        self.go(self.step + 1);
        e.preventDefault();
      } else if (e.key === 'ArrowLeft') {
        self.go(self.step - 1);
        e.preventDefault();
      }
    });
    var chips = [
      has(d.family) ? h('span', { class: 'chip' }, 'family ', h('b', {}, String(d.family))) : null,
      has(d.worst_by)
        ? h('span', { class: 'chip' }, 'worst by ', h('b', {}, String(d.worst_by)))
        : null,
      h('span', { class: 'chip' }, 'exact distance ', h('b', {}, fmtFull(ex.distance))),
      ex.overlap === true ? h('span', { class: 'chip warn' }, 'shapes overlap') : null,
    ];
    this.root.appendChild(
      h('div', { class: 'viewer-head' }, h('h3', {}, has(d.name) ? String(d.name) : 'case'), chips),
    );
    // A case file's provenance (optional `source` and `comment`), as text: never a link or markup.
    if (has(d.source) || has(d.comment))
      this.root.appendChild(
        h(
          'p',
          { class: 'provenance small' },
          has(d.source)
            ? ['source: ', h('code', {}, String(d.source)), has(d.comment) ? ' ' : null]
            : null,
          has(d.comment) ? String(d.comment) : null,
        ),
      );
    this.resultInfo = h('div', { class: 'result-info' });
    this.root.appendChild(this.resultInfo);

    // Controls.
    this.select = h(
      'select',
      {
        class: 'variant-select',
        'aria-label': 'variant',
        onchange: function (e) {
          self.variant = e.target.value;
          self.onVariant();
        },
      },
      this.variants.map(function (n) {
        return h('option', { value: n, selected: n === self.variant }, n);
      }),
    );
    this.prevBtn = h(
      'button',
      {
        type: 'button',
        class: 'step-prev',
        title: 'previous iteration (←)',
        onclick: function () {
          self.go(self.step - 1);
        },
      },
      '◀ prev',
    );
    this.nextBtn = h(
      'button',
      {
        type: 'button',
        class: 'step-next',
        title: 'next iteration (→)',
        onclick: function () {
          self.go(self.step + 1);
        },
      },
      'next ▶',
    );
    this.slider = h('input', {
      type: 'range',
      class: 'step-slider',
      min: 0,
      max: 0,
      step: 1,
      value: 0,
      'aria-label': 'iteration',
      oninput: function (e) {
        self.go(Number(e.target.value));
      },
    });
    this.stepLabel = h('span', { class: 'step-label' });
    this.fitBtn = h(
      'button',
      {
        type: 'button',
        class: 'view-fit toggle on',
        onclick: function () {
          self.setZoom(false);
        },
      },
      'fit all',
    );
    this.zoomBtn = h(
      'button',
      {
        type: 'button',
        class: 'view-zoom toggle',
        onclick: function () {
          self.setZoom(true);
        },
      },
      'zoom to closest points',
    );
    this.zoomHint = h('span', { class: 'zoom-hint small' });
    this.root.appendChild(
      h(
        'div',
        { class: 'controls' },
        h('label', {}, 'variant ', this.select),
        h('span', { class: 'step-group' }, this.prevBtn, this.slider, this.nextBtn, this.stepLabel),
        h('span', { class: 'view-group' }, 'view ', this.fitBtn, this.zoomBtn, this.zoomHint),
      ),
    );

    var PW = 600,
      PH = 470;
    this.PW = PW;
    this.PH = PH;
    this.svgShapes = sv('svg', {
      class: 'panel-svg shapes-panel',
      viewBox: '0 0 ' + PW + ' ' + PH,
      width: PW,
      height: PH,
    });
    this.svgMink = sv('svg', {
      class: 'panel-svg minkowski-panel',
      viewBox: '0 0 ' + PW + ' ' + PH,
      width: PW,
      height: PH,
    });
    this.root.appendChild(
      h(
        'div',
        { class: 'panels' },
        h(
          'figure',
          { class: 'panel' },
          h('figcaption', {}, 'Shapes A and B (world coordinates)'),
          this.svgShapes,
        ),
        h(
          'figure',
          { class: 'panel' },
          h('figcaption', {}, 'Minkowski difference Z = A − B and the origin'),
          this.svgMink,
        ),
      ),
    );
    this.legendBox = h('div', { class: 'legend viewer-legend' });
    this.root.appendChild(this.legendBox);
    this.stepInfo = h('div', { class: 'step-info' });
    this.notes = h('div', { class: 'case-notes' });
    this.root.appendChild(this.stepInfo);
    this.root.appendChild(this.notes);
    this.drawResults();
  };

  Viewer.prototype.onVariant = function () {
    var n = this.trace().length;
    this.step = Math.min(this.step, Math.max(0, n - 1));
    this.draw();
  };

  Viewer.prototype.go = function (k) {
    var n = this.trace().length;
    k = Math.max(0, Math.min(Math.max(0, n - 1), k | 0));
    if (k === this.step) return;
    this.step = k;
    this.draw();
  };

  Viewer.prototype.setZoom = function (z) {
    this.zoom = !!z;
    this.fitBtn.classList.toggle('on', !this.zoom);
    this.zoomBtn.classList.toggle('on', this.zoom);
    this.draw();
  };

  Viewer.prototype.draw = function () {
    var tr = this.trace(),
      n = tr.length;
    this.slider.max = String(Math.max(0, n - 1));
    this.slider.value = String(this.step);
    this.slider.disabled = n <= 1;
    this.prevBtn.disabled = this.step <= 0;
    this.nextBtn.disabled = this.step >= n - 1;
    var vd = this.vdata();
    this.stepLabel.textContent = n
      ? 'iteration ' +
        (this.step + 1) +
        ' of ' +
        n +
        (this.step === n - 1 && has(vd.stop) ? '  (stop: ' + vd.stop + ')' : '')
      : 'no trace for this variant';
    this.root.setAttribute('data-step', String(this.step));
    this.root.setAttribute('data-variant', String(this.variant));
    this.drawShapes();
    this.drawMinkowski();
    this.drawStepInfo();
    this.drawLegend();
  };

  // World-space content of each panel.
  Viewer.prototype.shapeGeom = function (which) {
    var s = this.d[which] || {};
    var world = pts(s.world);
    if (!world.length) world = pts(s.points); // without world points, show the local ones
    return { pts: world, r: Math.max(0, num(s.radius) || 0) };
  };

  Viewer.prototype.closestPoints = function () {
    var ex = this.d.exact || {},
      vd = this.vdata();
    // On overlap, where the run judged a penetration depth (exact "signed_distance" < 0): the exact
    // penetration pair, and the variant's own when it answered one (a negative distance).
    var overlap = isNum(ex.signed_distance) && num(ex.signed_distance) < 0;
    var signedAnswer = vd.penetration && isNum(vd.distance) && num(vd.distance) < 0;
    return {
      ea: finitePoint(ex.witnessA) ? pt(ex.witnessA) : null,
      eb: finitePoint(ex.witnessB) ? pt(ex.witnessB) : null,
      ga: finitePoint(vd.pointA) ? pt(vd.pointA) : null,
      gb: finitePoint(vd.pointB) ? pt(vd.pointB) : null,
      pa: overlap && finitePoint(ex.penetrationA) ? pt(ex.penetrationA) : null,
      pb: overlap && finitePoint(ex.penetrationB) ? pt(ex.penetrationB) : null,
      signedAnswer: !!signedAnswer,
    };
  };

  // Zoom box around the closest points (never empty): at least a few times the gap and the error.
  function zoomBox(points, fullSpan) {
    var b = bbox(points.filter(Boolean));
    if (!boxOk(b)) return null;
    var span = Math.max(b.x1 - b.x0, b.y1 - b.y0);
    var pad = Math.max(span * 0.6, fullSpan * 1e-9);
    if (!(pad > 0)) pad = Math.max(Math.abs(b.x0), Math.abs(b.y0), 1) * 1e-9;
    return { x0: b.x0 - pad, x1: b.x1 + pad, y0: b.y0 - pad, y1: b.y1 + pad };
  }

  Viewer.prototype.views = function () {
    var A = this.shapeGeom('a'),
      B = this.shapeGeom('b'),
      cp = this.closestPoints();
    var fullS = bbox([]);
    A.pts.forEach(function (p) {
      growBox(fullS, p, A.r);
    });
    B.pts.forEach(function (p) {
      growBox(fullS, p, B.r);
    });
    [cp.ea, cp.eb, cp.ga, cp.gb, cp.pa, cp.pb].forEach(function (p) {
      if (p) growBox(fullS, p, 0);
    });
    var Z = pts(this.d.minkowski),
      rz = A.r + B.r;
    var fullM = bbox([[0, 0]]);
    Z.forEach(function (p) {
      growBox(fullM, p, rz);
    });
    if (!Z.length) {
      // No Minkowski polygon in the data: derive it from the shapes.
      var zz = [];
      A.pts.forEach(function (a) {
        B.pts.forEach(function (b) {
          zz.push([a[0] - b[0], a[1] - b[1]]);
        });
      });
      Z = hull(zz);
      Z.forEach(function (p) {
        growBox(fullM, p, rz);
      });
    }
    var zE = cp.ea && cp.eb ? [cp.ea[0] - cp.eb[0], cp.ea[1] - cp.eb[1]] : null;
    var zG = cp.ga && cp.gb ? [cp.ga[0] - cp.gb[0], cp.ga[1] - cp.gb[1]] : null;
    var spanS = Math.max(fullS.x1 - fullS.x0, fullS.y1 - fullS.y0),
      spanM = Math.max(fullM.x1 - fullM.x0, fullM.y1 - fullM.y0);
    var zs = zoomBox([cp.ea, cp.eb, cp.ga, cp.gb, cp.pa, cp.pb], spanS),
      zm = zoomBox([[0, 0], zE, zG], spanM);
    var PW = this.PW,
      PH = this.PH;
    var vS = makeView(this.zoom && zs ? zs : fullS, PW, PH, 28);
    var vM = makeView(this.zoom && zm ? zm : fullM, PW, PH, 28);
    // How much the zoom magnifies: shown as a hint when the closest points are too close to see.
    var ratio = zs ? spanS / Math.max(zs.x1 - zs.x0, zs.y1 - zs.y0) : 1;
    this.zoomHint.textContent =
      !this.zoom && ratio > 30
        ? 'the gap is ' + fmt(1 / ratio) + ' of this view: zoom in to see it'
        : this.zoom
          ? '×' + fmt(ratio) + ' magnified'
          : '';
    return { A: A, B: B, Z: Z, rz: rz, cp: cp, zE: zE, zG: zG, vS: vS, vM: vM };
  };

  function drawShape(g, v, world, r, fill, stroke, label) {
    if (!world.length) return;
    var px = hull(world.map(v.p));
    var rpx = r * v.s;
    var out = rounded(px, rpx, v);
    if (out.length === 1 && !(rpx > 0.3)) {
      var q = out[0];
      if (v.inside(q)) {
        g.appendChild(
          sv(
            'circle',
            { cx: q[0], cy: q[1], r: 4.5, fill: stroke, stroke: 'white', 'stroke-width': 1 },
            label ? svgTitle(label + ' (a point)') : null,
          ),
        );
        if (label && label.length === 1)
          g.appendChild(
            sv(
              'text',
              { x: q[0] - 16, y: q[1] + 18, class: 'shape-label small-shape-label', fill: stroke },
              label,
            ),
          );
      }
    } else if (out.length === 2 && !(rpx > 0.3)) {
      var sg = clipSeg(out[0], out[1], v.rect);
      if (sg)
        g.appendChild(
          sv('path', {
            d: pathOf(sg, false),
            stroke: stroke,
            'stroke-width': 4,
            'stroke-linecap': 'round',
            fill: 'none',
          }),
        );
    } else {
      var clipped = clipPoly(out, v.rect);
      if (clipped.length)
        g.appendChild(
          sv('path', {
            d: pathOf(clipped, true),
            fill: fill,
            stroke: stroke,
            'stroke-width': 1.8,
            'stroke-linejoin': 'round',
          }),
        );
    }
    if (rpx > 0.3 && px.length) {
      // The core polygon, dashed, inside the rounded outline.
      if (px.length === 1) {
        if (v.inside(px[0]))
          g.appendChild(sv('circle', { cx: px[0][0], cy: px[0][1], r: 2.5, fill: stroke }));
      } else {
        var core = px.length === 2 ? clipSeg(px[0], px[1], v.rect) : clipPoly(px, v.rect);
        if (core && core.length)
          g.appendChild(
            sv('path', {
              d: pathOf(core, px.length > 2),
              fill: 'none',
              stroke: stroke,
              'stroke-width': 1,
              'stroke-dasharray': '4 3',
              opacity: 0.8,
            }),
          );
      }
    }
    return px;
  }

  function dot(g, v, p, r, attrs, title) {
    if (!p) return null;
    var q = v.p(p);
    if (!v.inside(q)) return null;
    var a = { cx: q[0], cy: q[1], r: r };
    Object.keys(attrs || {}).forEach(function (k) {
      a[k] = attrs[k];
    });
    var c = sv('circle', a, title ? svgTitle(title) : null);
    g.appendChild(c);
    return c;
  }

  function seg(g, v, p, q, attrs, title) {
    if (!p || !q) return null;
    var s = clipSeg(v.p(p), v.p(q), v.rect);
    if (!s) return null;
    var a = { d: pathOf(s, false), fill: 'none' };
    Object.keys(attrs || {}).forEach(function (k) {
      a[k] = attrs[k];
    });
    var e = sv('path', a, title ? svgTitle(title) : null);
    g.appendChild(e);
    return e;
  }

  // An arrow from p to q (world points; clipped to the view, its head drawn when q is inside):
  // the minimal translation of a penetration pair.
  function arrow(g, v, p, q, color, title, cls) {
    if (!p || !q) return;
    var a = v.p(p),
      b = v.p(q),
      dx = b[0] - a[0],
      dy = b[1] - a[1],
      L = Math.hypot(dx, dy);
    var s = clipSeg(a, b, v.rect);
    if (!s || !(L > 0)) return;
    var ux = dx / L,
      uy = dy / L,
      hx = -uy,
      hy = ux,
      k = Math.min(11, L / 2);
    var kids = [
      sv('path', { d: pathOf(s, false), fill: 'none', stroke: color, 'stroke-width': 2.2 }),
    ];
    if (v.inside(b))
      kids.push(
        sv('path', {
          d:
            'M' +
            b[0] +
            ' ' +
            b[1] +
            'L' +
            (b[0] - ux * k + hx * k * 0.45) +
            ' ' +
            (b[1] - uy * k + hy * k * 0.45) +
            'L' +
            (b[0] - ux * k - hx * k * 0.45) +
            ' ' +
            (b[1] - uy * k - hy * k * 0.45) +
            'Z',
          fill: color,
        }),
      );
    g.appendChild(sv('g', { class: cls || 'arrow' }, svgTitle(title), kids));
  }

  function cross(g, v, p, size, color, title) {
    if (!p) return;
    var q = v.p(p);
    if (!v.inside(q)) return;
    g.appendChild(
      sv(
        'path',
        {
          d:
            'M' +
            (q[0] - size) +
            ' ' +
            (q[1] - size) +
            'L' +
            (q[0] + size) +
            ' ' +
            (q[1] + size) +
            'M' +
            (q[0] - size) +
            ' ' +
            (q[1] + size) +
            'L' +
            (q[0] + size) +
            ' ' +
            (q[1] - size),
          stroke: color,
          'stroke-width': 2.2,
          fill: 'none',
        },
        title ? svgTitle(title) : null,
      ),
    );
  }

  function diamond(g, v, p, size, fill, title) {
    if (!p) return;
    var q = v.p(p);
    if (!v.inside(q)) return;
    g.appendChild(
      sv(
        'path',
        {
          d:
            'M' +
            q[0] +
            ' ' +
            (q[1] - size) +
            'L' +
            (q[0] + size) +
            ' ' +
            q[1] +
            'L' +
            q[0] +
            ' ' +
            (q[1] + size) +
            'L' +
            (q[0] - size) +
            ' ' +
            q[1] +
            'Z',
          fill: fill,
          stroke: '#6b5200',
          'stroke-width': 1.2,
        },
        title ? svgTitle(title) : null,
      ),
    );
  }

  function text(g, v, p, s, dx, dy, cls) {
    if (!p) return;
    var q = v.p(p);
    if (!v.inside(q)) return;
    g.appendChild(
      sv('text', { x: q[0] + (dx || 0), y: q[1] + (dy || 0), class: cls || 'geo-label' }, s),
    );
  }

  function stepSimplex(st) {
    var s = st && Array.isArray(st.simplex) ? st.simplex : [];
    return s.filter(function (x) {
      return x && finitePoint(x.w);
    });
  }

  Viewer.prototype.drawShapes = function () {
    var svg = this.svgShapes;
    svg.textContent = '';
    var V = this.views(),
      v = V.vS,
      g = sv('g', { class: 'layer', 'data-step': String(this.step) });
    svg.appendChild(sv('rect', { x: 0, y: 0, width: this.PW, height: this.PH, class: 'panel-bg' }));
    var labelsG = sv('g', {});
    drawGrid(svg, v, labelsG);
    svg.appendChild(g);
    svg.appendChild(labelsG); // tick labels stay readable over filled shapes
    var pa = drawShape(g, v, V.A.pts, V.A.r, GEO.aFill, GEO.aStroke, 'A');
    var pb = drawShape(g, v, V.B.pts, V.B.r, GEO.bFill, GEO.bStroke, 'B');
    // Shape labels at the centroids of their hulls (when visible).
    [
      [pa, 'A', GEO.aStroke],
      [pb, 'B', GEO.bStroke],
    ].forEach(function (x) {
      if (!x[0] || !x[0].length) return;
      var c = x[0].reduce(
        function (s, p) {
          return [s[0] + p[0] / x[0].length, s[1] + p[1] / x[0].length];
        },
        [0, 0],
      );
      if (c[0] > 10 && c[0] < v.W - 10 && c[1] > 10 && c[1] < v.H - 10)
        g.appendChild(
          sv(
            'text',
            { x: c[0], y: c[1] + 6, class: 'shape-label', fill: x[2], 'text-anchor': 'middle' },
            x[1],
          ),
        );
    });
    var tr = this.trace(),
      st = tr[this.step],
      col = variantColor(String(this.variant));
    if (st) {
      var simplex = stepSimplex(st);
      // Simplex vertices on each shape, and the current closest points P_A = sum a_i wA_i, P_B likewise.
      var cA = [0, 0],
        cB = [0, 0],
        okC = simplex.length > 0;
      simplex.forEach(function (x, i) {
        if (finitePoint(x.wA))
          dot(
            g,
            v,
            pt(x.wA),
            4.5,
            { fill: GEO.simplexStroke, stroke: 'white', 'stroke-width': 1 },
            'simplex vertex ' +
              (i + 1) +
              ' on A: ' +
              fmtPt(x.wA) +
              (has(x.iA) ? ' (vertex ' + x.iA + ')' : ''),
          );
        if (finitePoint(x.wB))
          dot(
            g,
            v,
            pt(x.wB),
            4.5,
            { fill: GEO.simplexStroke, stroke: 'white', 'stroke-width': 1 },
            'simplex vertex ' +
              (i + 1) +
              ' on B: ' +
              fmtPt(x.wB) +
              (has(x.iB) ? ' (vertex ' + x.iB + ')' : ''),
          );
        var a = isNum(x.a) ? num(x.a) : simplex.length === 1 ? 1 : NaN;
        if (!(finitePoint(x.wA) && finitePoint(x.wB) && isFinite(a))) {
          okC = false;
          return;
        }
        cA = [cA[0] + a * num(x.wA[0]), cA[1] + a * num(x.wA[1])];
        cB = [cB[0] + a * num(x.wB[0]), cB[1] + a * num(x.wB[1])];
      });
      if (okC) {
        seg(
          g,
          v,
          cA,
          cB,
          { stroke: GEO.closest, 'stroke-width': 2, 'stroke-dasharray': '6 4' },
          'current closest points of this iteration',
        );
        dot(
          g,
          v,
          cA,
          5,
          { fill: GEO.closest, stroke: 'white', 'stroke-width': 1.2 },
          'closest point on A at this iteration: ' + fmtPt(cA),
        );
        dot(
          g,
          v,
          cB,
          5,
          { fill: GEO.closest, stroke: 'white', 'stroke-width': 1.2 },
          'closest point on B at this iteration: ' + fmtPt(cB),
        );
      }
      var sp = st.support;
      if (sp && finitePoint(sp.wA))
        diamond(g, v, pt(sp.wA), 7, GEO.support, 'new support point on A: ' + fmtPt(sp.wA));
      if (sp && finitePoint(sp.wB))
        diamond(g, v, pt(sp.wB), 7, GEO.support, 'new support point on B: ' + fmtPt(sp.wB));
    }
    var cp = V.cp;
    seg(g, v, cp.ea, cp.eb, { stroke: GEO.exact, 'stroke-width': 1.2 }, 'exact closest points');
    cross(g, v, cp.ea, 5, GEO.exact, 'exact witness on A: ' + fmtPt(cp.ea));
    cross(g, v, cp.eb, 5, GEO.exact, 'exact witness on B: ' + fmtPt(cp.eb));
    // The minimal translation of B to contact, pA − pB: an arrow from B's point to A's, exact in
    // black, the variant's own (a penetration answer) in its colour.
    if (cp.pa && cp.pb) {
      arrow(
        g,
        v,
        cp.pb,
        cp.pa,
        GEO.exact,
        'exact minimal translation of B: pA − pB, from ' +
          fmtPt(cp.pb) +
          ' to ' +
          fmtPt(cp.pa) +
          ', depth ' +
          fmtFull(-num(this.d.exact.signed_distance)),
        'translation-arrow exact-translation',
      );
      cross(g, v, cp.pa, 4, GEO.exact, 'exact penetration point on A: ' + fmtPt(cp.pa));
      cross(g, v, cp.pb, 4, GEO.exact, 'exact penetration point on B: ' + fmtPt(cp.pb));
    }
    if (cp.signedAnswer)
      arrow(
        g,
        v,
        cp.gb,
        cp.ga,
        col,
        this.variant +
          ' minimal translation of B: pointA − pointB, depth ' +
          fmtFull(-num(this.vdata().distance)),
        'translation-arrow variant-translation',
      );
    dot(
      g,
      v,
      cp.ga,
      4,
      { fill: 'white', stroke: col, 'stroke-width': 2.5 },
      this.variant + ' GJK point on A: ' + fmtPt(cp.ga),
    );
    dot(
      g,
      v,
      cp.gb,
      4,
      { fill: 'white', stroke: col, 'stroke-width': 2.5 },
      this.variant + ' GJK point on B: ' + fmtPt(cp.gb),
    );
    // Vertex indices (they name iA, iB in the trace) when there is room.
    var self = this;
    if (!this.zoom) {
      [
        ['a', V.A],
        ['b', V.B],
      ].forEach(function (x) {
        var s = self.d[x[0]] || {},
          w = pts(s.world);
        if (w.length > 1 && w.length <= 16)
          w.forEach(function (p, i) {
            text(g, v, p, String(i), 6, -6, 'vertex-index');
          });
      });
    }
  };

  Viewer.prototype.drawMinkowski = function () {
    var svg = this.svgMink;
    svg.textContent = '';
    var V = this.views(),
      v = V.vM,
      g = sv('g', { class: 'layer', 'data-step': String(this.step) });
    svg.appendChild(sv('rect', { x: 0, y: 0, width: this.PW, height: this.PH, class: 'panel-bg' }));
    var labelsG = sv('g', {});
    drawGrid(svg, v, labelsG);
    svg.appendChild(g);
    svg.appendChild(labelsG); // tick labels stay readable over filled shapes
    var pz = drawShape(g, v, V.Z, V.rz, GEO.zFill, GEO.zStroke, 'Z = A − B');
    if (pz && pz.length > 2) {
      var c = pz.reduce(
        function (s, p) {
          return [s[0] + p[0] / pz.length, s[1] + p[1] / pz.length];
        },
        [0, 0],
      );
      if (c[0] > 10 && c[0] < v.W - 10 && c[1] > 10 && c[1] < v.H - 10)
        g.appendChild(
          sv(
            'text',
            {
              x: c[0],
              y: c[1] + 6,
              class: 'shape-label',
              fill: GEO.zStroke,
              'text-anchor': 'middle',
            },
            'Z',
          ),
        );
    }
    // Exact distance: circle around the origin through the closest point of Z.
    var ex = this.d.exact || {},
      dE = num(ex.distance);
    var o = v.p([0, 0]);
    if (isFinite(dE) && dE > 0 && dE * v.s > 3 && dE * v.s < 1e6) {
      g.appendChild(
        sv(
          'circle',
          {
            cx: o[0],
            cy: o[1],
            r: dE * v.s,
            fill: 'none',
            stroke: '#999',
            'stroke-width': 1,
            'stroke-dasharray': '2 4',
          },
          svgTitle('exact distance ' + fmtFull(dE)),
        ),
      );
    }
    var tr = this.trace(),
      st = tr[this.step],
      col = variantColor(String(this.variant));
    if (st) {
      var simplex = stepSimplex(st),
        wp = simplex.map(function (x) {
          return v.p(pt(x.w));
        });
      if (wp.length >= 3) {
        var tri = clipPoly(hull(wp), v.rect);
        if (tri.length)
          g.appendChild(
            sv('path', {
              d: pathOf(tri, true),
              fill: GEO.simplexFill,
              'fill-opacity': 0.7,
              stroke: GEO.simplexStroke,
              'stroke-width': 2,
            }),
          );
      } else if (wp.length === 2) {
        var sgm = clipSeg(wp[0], wp[1], v.rect);
        if (sgm)
          g.appendChild(
            sv('path', {
              d: pathOf(sgm, false),
              stroke: GEO.simplexStroke,
              'stroke-width': 3,
              fill: 'none',
            }),
          );
      }
      simplex.forEach(function (x, i) {
        dot(
          g,
          v,
          pt(x.w),
          5.5,
          { fill: GEO.simplexStroke, stroke: 'white', 'stroke-width': 1.2 },
          'w' +
            (i + 1) +
            ' = ' +
            fmtPt(x.w) +
            (isNum(x.a) ? ', weight a = ' + fmt(x.a) : '') +
            (has(x.iA) ? ', iA ' + x.iA + ', iB ' + x.iB : ''),
        );
        text(g, v, pt(x.w), 'w' + (i + 1), 8, 14, 'geo-label simplex-label');
      });
      var P = finitePoint(st.closest) ? pt(st.closest) : null;
      if (P) {
        seg(g, v, [0, 0], P, {
          stroke: GEO.closest,
          'stroke-width': 1.6,
          'stroke-dasharray': '6 4',
        });
        dot(
          g,
          v,
          P,
          5.5,
          { fill: GEO.closest, stroke: 'white', 'stroke-width': 1.2, class: 'closest-marker' },
          'closest point P of the simplex: ' +
            fmtPt(P) +
            ', |P| = ' +
            fmtFull(Math.hypot(P[0], P[1])),
        );
        var dd = finitePoint(st.direction) ? pt(st.direction) : null;
        var dl = dd ? Math.hypot(dd[0], dd[1]) : 0;
        // P's label on the side away from the direction arrow.
        if (dd && dl > 0 && isFinite(dl))
          text(
            g,
            v,
            P,
            'P',
            (-dd[0] / dl) * 16 - 4,
            (dd[1] / dl) * 16 + 5,
            'geo-label closest-label',
          );
        else text(g, v, P, 'P', 8, -8, 'geo-label closest-label');
        if (dd && dl > 0 && isFinite(dl)) {
          var q = v.p(P),
            ux = dd[0] / dl,
            uy = -dd[1] / dl,
            L = 56;
          if (v.inside(q)) {
            var e = [q[0] + ux * L, q[1] + uy * L];
            var hx = -uy,
              hy = ux;
            g.appendChild(
              sv(
                'g',
                { class: 'direction-arrow' },
                svgTitle('search direction d = ' + fmtPt(dd)),
                sv('line', {
                  x1: q[0],
                  y1: q[1],
                  x2: e[0] - ux * 6,
                  y2: e[1] - uy * 6,
                  stroke: GEO.direction,
                  'stroke-width': 2.4,
                }),
                sv('path', {
                  d:
                    'M' +
                    e[0] +
                    ' ' +
                    e[1] +
                    'L' +
                    (e[0] - ux * 11 + hx * 5) +
                    ' ' +
                    (e[1] - uy * 11 + hy * 5) +
                    'L' +
                    (e[0] - ux * 11 - hx * 5) +
                    ' ' +
                    (e[1] - uy * 11 - hy * 5) +
                    'Z',
                  fill: GEO.direction,
                }),
                sv(
                  'text',
                  {
                    x: e[0] + ux * 8 - 3,
                    y: e[1] + uy * 8 + 4,
                    class: 'geo-label',
                    fill: GEO.direction,
                  },
                  'd',
                ),
              ),
            );
          }
        }
      }
      var sp = st.support;
      if (sp && finitePoint(sp.w)) {
        diamond(
          g,
          v,
          pt(sp.w),
          8,
          GEO.support,
          'support point w = ' +
            fmtPt(sp.w) +
            (has(sp.iA) ? ' (iA ' + sp.iA + ', iB ' + sp.iB + ')' : ''),
        );
        text(g, v, pt(sp.w), 'w', -20, -8, 'geo-label support-label');
      }
    }
    // Origin, exact closest point of Z and GJK's.
    cross(g, v, V.zE, 5, GEO.exact, 'exact closest point of Z: ' + fmtPt(V.zE));
    dot(
      g,
      v,
      V.zG,
      4,
      { fill: 'white', stroke: col, 'stroke-width': 2.5 },
      this.variant + ' GJK result pA − pB: ' + fmtPt(V.zG),
    );
    if (v.inside(o)) {
      g.appendChild(
        sv(
          'g',
          { class: 'origin' },
          svgTitle('origin'),
          sv('circle', { cx: o[0], cy: o[1], r: 3.5, fill: GEO.origin }),
          sv('line', {
            x1: o[0] - 10,
            x2: o[0] + 10,
            y1: o[1],
            y2: o[1],
            stroke: GEO.origin,
            'stroke-width': 1,
          }),
          sv('line', {
            x1: o[0],
            x2: o[0],
            y1: o[1] - 10,
            y2: o[1] + 10,
            stroke: GEO.origin,
            'stroke-width': 1,
          }),
          sv('text', { x: o[0] - 14, y: o[1] + 16, class: 'geo-label' }, 'O'),
        ),
      );
    } else {
      // Point to the origin from the panel edge.
      var dx = o[0] - v.W / 2,
        dy = o[1] - v.H / 2,
        t = Math.min((v.W / 2 - 14) / Math.abs(dx || 1e-9), (v.H / 2 - 14) / Math.abs(dy || 1e-9));
      var ax = v.W / 2 + dx * t,
        ay = v.H / 2 + dy * t,
        l = Math.hypot(dx, dy) || 1;
      g.appendChild(
        sv(
          'g',
          { class: 'origin-off' },
          svgTitle('the origin is outside this view'),
          sv('path', {
            d:
              'M' +
              ax +
              ' ' +
              ay +
              'l' +
              ((-dx / l) * 12 + (dy / l) * 5) +
              ' ' +
              ((-dy / l) * 12 - (dx / l) * 5) +
              'l' +
              (-dy / l) * 10 +
              ' ' +
              (dx / l) * 10 +
              'Z',
            fill: GEO.origin,
          }),
          sv(
            'text',
            {
              x: ax - (dx / l) * 26,
              y: ay - (dy / l) * 26 + 4,
              class: 'geo-label',
              'text-anchor': 'middle',
            },
            'O',
          ),
        ),
      );
    }
  };

  Viewer.prototype.drawLegend = function () {
    var col = variantColor(String(this.variant));
    this.legendBox.textContent = '';
    append(this.legendBox, [
      legendItem(GEO.aFill, 'A'),
      legendItem(GEO.bFill, 'B'),
      legendItem(GEO.zFill, 'Z = A − B'),
      legendItem(GEO.simplexFill, 'simplex (w = wA − wB)'),
      legendItem(GEO.closest, 'closest point P (this iteration)', 'circle'),
      legendItem(GEO.direction, 'search direction d', 'line'),
      legendItem(GEO.support, 'new support point', 'diamond'),
      legendItem(GEO.exact, 'exact closest points', 'cross'),
      legendItem(col, this.variant + ': GJK closest points', 'ring'),
      legendItem('#999', 'exact distance around O', 'dash'),
    ]);
  };

  Viewer.prototype.drawStepInfo = function () {
    var tr = this.trace(),
      st = tr[this.step];
    this.stepInfo.textContent = '';
    if (!st) {
      this.stepInfo.appendChild(h('p', { class: 'note' }, 'No trace recorded for this variant.'));
      return;
    }
    var simplex = stepSimplex(st);
    var rows = simplex.map(function (x, i) {
      return h(
        'tr',
        {},
        h('td', {}, 'w' + (i + 1)),
        h('td', { class: 'mono' }, fmtPt(x.w)),
        h('td', { class: 'num' }, fmt(x.a, 4)),
        h('td', { class: 'num' }, has(x.iA) ? String(x.iA) : '—'),
        h('td', { class: 'num' }, has(x.iB) ? String(x.iB) : '—'),
      );
    });
    var P = finitePoint(st.closest) ? pt(st.closest) : null;
    var sp = st.support;
    var vd = this.vdata();
    append(this.stepInfo, [
      h('h4', {}, 'Iteration ' + (this.step + 1) + ' of ' + tr.length),
      h(
        'div',
        { class: 'info-row' },
        h(
          'table',
          { class: 'data compact' },
          h(
            'thead',
            {},
            h(
              'tr',
              {},
              h('th', {}, 'simplex'),
              h('th', {}, 'w = wA − wB'),
              h('th', { class: 'num' }, 'weight a'),
              h('th', { class: 'num' }, 'iA'),
              h('th', { class: 'num' }, 'iB'),
            ),
          ),
          h('tbody', {}, rows),
        ),
        h(
          'dl',
          { class: 'kv small-kv' },
          h('dt', {}, 'closest point P'),
          h('dd', { class: 'mono' }, P ? fmtPt(P) : '—'),
          h('dt', {}, '|P|'),
          h('dd', { class: 'mono' }, P ? fmtFull(Math.hypot(P[0], P[1])) : '—'),
          h('dt', {}, 'search direction d'),
          h('dd', { class: 'mono' }, fmtPt(st.direction)),
          h('dt', {}, 'support point w'),
          h(
            'dd',
            { class: 'mono' },
            sp && finitePoint(sp.w)
              ? fmtPt(sp.w) + (has(sp.iA) ? '   (iA ' + sp.iA + ', iB ' + sp.iB + ')' : '')
              : 'none' + (this.step === tr.length - 1 && has(vd.stop) ? ' — stop: ' + vd.stop : ''),
          ),
          this.step === tr.length - 1 && has(vd.stop)
            ? [h('dt', {}, 'stop'), h('dd', {}, String(vd.stop))]
            : null,
        ),
      ),
    ]);
  };

  // A variant's verdict on this case, for the results table: invalid (with its reason), misclassified,
  // skipped or refused, a plugin's error, or correct.
  function caseClass(r) {
    if (has(r.invalid))
      return h(
        'td',
        { class: 'bad invalid-reason', title: 'not a valid answer (docs/report-schema.md)' },
        'invalid: ' + String(r.invalid).replace(/_/g, ' '),
      );
    if (r.misclassified) return h('td', { class: 'bad' }, String(r.misclassified));
    if (has(r.plugin_status))
      return h(
        'td',
        { class: 'bad small' },
        'plugin ' + r.plugin_status + (has(r.plugin_detail) ? ': ' + r.plugin_detail : ''),
      );
    if (has(r.skipped)) return h('td', { class: 'small muted' }, 'not run: ' + String(r.skipped));
    return h('td', { class: 'small muted' }, 'correct');
  }

  Viewer.prototype.drawResults = function () {
    var d = this.d,
      ex = d.exact || {},
      vmap = d.variants || {};
    var names = this.variants;
    var any = function (f) {
      return names.some(function (n) {
        return vmap[n] && f(vmap[n]);
      });
    };
    var hasBound = any(function (r) {
      return r.errors && has(r.errors.bound_ratio);
    });
    // The witness columns when some variant was held to a witness bound (or answered invalidly).
    var hasWit = any(function (r) {
      return has(r.witness_bound) || has(r.invalid);
    });
    var sq = has(ex.squared) ? String(ex.squared) : null;
    append(this.resultInfo, [
      h(
        'div',
        { class: 'table-wrap' },
        h(
          'table',
          { class: 'data compact results' },
          h(
            'thead',
            {},
            h(
              'tr',
              {},
              h('th', {}, ''),
              h('th', { class: 'num' }, 'distance'),
              h('th', { class: 'num' }, 'abs error'),
              h('th', { class: 'num' }, 'ulps'),
              h('th', { class: 'num' }, 'error / (u·R)'),
              hasBound ? h('th', { class: 'num' }, 'error / bound') : null,
              hasWit
                ? [
                    h(
                      'th',
                      { class: 'num', title: 'largest distance of a witness point to its shape' },
                      'witness error',
                    ),
                    h(
                      'th',
                      { class: 'num', title: 'the derived witness bound this answer was held to' },
                      'witness bound',
                    ),
                  ]
                : null,
              h('th', { class: 'num' }, 'iter.'),
              h('th', {}, 'stop'),
              h('th', {}, 'class'),
            ),
          ),
          h(
            'tbody',
            {},
            h(
              'tr',
              { class: 'exact-row' },
              h('td', {}, 'exact'),
              h('td', { class: 'num mono' }, fmtFull(ex.distance)),
              h('td', { colspan: 5 + (hasBound ? 1 : 0) + (hasWit ? 2 : 0) }),
              h(
                'td',
                { class: 'small muted' },
                ex.overlap === true ? 'overlap' : ex.overlap === false ? 'separated' : '',
              ),
            ),
            names.map(function (n) {
              var r = vmap[n] || {},
                e = r.errors || {};
              return h(
                'tr',
                { 'data-variant': n },
                h('td', { class: 'variant-cell' }, variantDot(n), n),
                h('td', { class: 'num mono' }, fmtFull(r.distance)),
                h('td', { class: 'num' }, fmt(e.abs)),
                h('td', { class: 'num' }, fmt(e.ulps)),
                h('td', { class: 'num' }, fmt(e.normalized)),
                hasBound
                  ? h(
                      'td',
                      { class: 'num' + (num(e.bound_ratio) > 1 ? ' bad' : '') },
                      fmt(e.bound_ratio),
                    )
                  : null,
                hasWit
                  ? [
                      h(
                        'td',
                        { class: 'num' + (num(e.witness) > num(r.witness_bound) ? ' bad' : '') },
                        fmt(e.witness),
                      ),
                      h('td', { class: 'num witness-bound' }, fmt(r.witness_bound)),
                    ]
                  : null,
                h('td', { class: 'num' }, fmtInt(r.iterations)),
                h('td', { class: 'small' }, has(r.stop) ? String(r.stop) : '—'),
                caseClass(r),
              );
            }),
          ),
        ),
      ),
    ]);
    append(this.notes, [
      h(
        'p',
        { class: 'small muted' },
        'A: ' + shapeText(d.a) + '. B: ' + shapeText(d.b) + '.',
        has(ex.lower) || has(ex.upper)
          ? ' The exact distance rounds to [' + fmtFull(ex.lower) + ', ' + fmtFull(ex.upper) + '].'
          : '',
      ),
      sq
        ? h(
            'p',
            { class: 'small muted' },
            'Exact squared distance of the cores: ',
            h(
              'code',
              { title: sq },
              sq.length > 120 ? sq.slice(0, 58) + ' … ' + sq.slice(-58) : sq,
            ),
          )
        : null,
    ]);
  };

  function shapeText(s) {
    if (!s || typeof s !== 'object') return 'missing';
    var n = Array.isArray(s.points) ? s.points.length : 0;
    var r = num(s.radius);
    var t = s.transform || {};
    return (
      (n === 1 ? 'a point' : n === 2 ? 'a segment' : n + ' points') +
      (r > 0 ? ', radius ' + fmt(r) : '') +
      (finitePoint(t.p)
        ? ', at ' +
          fmtPt(t.p, function (x) {
            return fmt(x, 4);
          })
        : '') +
      (finitePoint(t.q)
        ? ', rotated ' + fmt((Math.atan2(num(t.q[1]), num(t.q[0])) * 180) / Math.PI) + '°'
        : '')
    );
  }

  // --- Pages --------------------------------------------------------------------------------------

  function readData() {
    var node = document.getElementById('report-data');
    if (!node) throw new Error('no report-data block in the page');
    return JSON.parse(node.textContent);
  }

  function renderReportPage(app, report) {
    if (!report || typeof report !== 'object')
      throw new Error('the report data is not a JSON object');
    readJudged(report);
    // Every name the page draws: the report's variants, the families' and the worst cases'.
    var drawn = variantNames(report);
    (Array.isArray(report.worst) ? report.worst : []).forEach(function (w) {
      if (w && w.variants && typeof w.variants === 'object')
        drawn = drawn.concat(Object.keys(w.variants));
    });
    setVariantNames(drawn);
    document.title =
      'GJK report — ' +
      (report.passed === true ? 'PASS' : report.passed === false ? 'FAIL' : 'no verdict') +
      (report.context && report.context.date ? ' — ' + report.context.date : '');
    app.appendChild(
      guarded('header', function () {
        return renderHeader(report);
      }),
    );
    // The schema this page was made for: the renderer writes it into <html data-schema> (its one
    // home is kReportSchema, validation/src/report/report.hpp).
    var schema = document.documentElement.getAttribute('data-schema');
    if (has(report.schema) && schema && String(report.schema) !== schema) {
      app.appendChild(
        h(
          'div',
          { class: 'error-box' },
          'This page was made for schema ' +
            schema +
            '; the data says ' +
            report.schema +
            '. Some parts may be missing.',
        ),
      );
    }
    var main = h('main', {});
    app.appendChild(main);
    // The first screen answers: did anything fail (header), where is each variant weakest (heat map),
    // what does its accuracy cost in time (speed plot). The detail follows, folded.
    [
      ['overview', renderOverview],
      ['families', renderFamilies],
      ['context', renderContext],
      ['worst cases', renderWorst],
      ['rejected', renderRejected],
    ].forEach(function (x) {
      main.appendChild(
        guarded(x[0], function () {
          return x[1](report);
        }),
      );
    });
    window.addEventListener('hashchange', openFromHash);
    if (location.hash.indexOf('#family-') === 0) openFromHash();
    app.appendChild(
      h(
        'footer',
        {},
        'Rendered by gjk2d_html from report.json (schema ' +
          (has(report.schema) ? report.schema : 'unknown') +
          '). Self-contained: no network, no external files.',
      ),
    );
  }

  function renderCasePage(app, detail) {
    if (!detail || typeof detail !== 'object')
      throw new Error('the case data is not a JSON object');
    document.title = 'GJK case — ' + (has(detail.name) ? detail.name : 'unnamed');
    setVariantNames(
      detail.variants && typeof detail.variants === 'object' ? Object.keys(detail.variants) : [],
    );
    app.appendChild(
      h(
        'header',
        { class: 'page-head' },
        h(
          'div',
          { class: 'title-row' },
          h(
            'div',
            {},
            h('h1', {}, 'GJK iteration viewer'),
            h(
              'div',
              { class: 'subtitle' },
              'case ',
              h('code', {}, has(detail.name) ? String(detail.name) : 'unnamed'),
            ),
          ),
        ),
      ),
    );
    var main = h('main', {});
    app.appendChild(main);
    var sec = section(
      'worst',
      'Case',
      "Left: the shapes in world coordinates with the exact closest points (black) and GJK's (variant colour). Right: the Minkowski difference Z = A − B with the origin, GJK's simplex, its closest point to the origin and the search direction at the chosen iteration. Step with the buttons, the slider or the arrow keys.",
    );
    sec.appendChild(
      guarded('case viewer', function () {
        return new Viewer(detail, null).root;
      }),
    );
    main.appendChild(sec);
    app.appendChild(
      h(
        'footer',
        {},
        'Rendered by gjk2d_html (gjk-validate explain --html). Self-contained: no network, no external files.',
      ),
    );
  }

  // --- Self-test (tests/report): location.hash == "#selftest" --------------------------------------

  function selfTest(mode, data) {
    var v = { mode: mode, errors: [], checks: {} };
    function check(name, ok, detail) {
      v.checks[name] = { ok: !!ok, detail: detail };
    }
    try {
      if (mode === 'report') {
        // The speed plot: one point per variant with a timing and an error in the chosen family,
        // on every family of the selector and on the all-families view; then back to the start.
        var sel = document.querySelector('select.speed-family');
        var start = sel ? sel.value : null;
        v.scatterStart = start;
        v.scatterPoints = document.querySelectorAll('#scatter .pt').length;
        v.scatterExpected = start === null ? 0 : speedItems(data, start).length;
        check(
          'scatter points',
          v.scatterPoints === v.scatterExpected,
          v.scatterPoints + ' drawn, ' + v.scatterExpected + ' expected',
        );
        var bad = [];
        if (sel) {
          for (var si = 0; si < sel.options.length; ++si) {
            sel.selectedIndex = si;
            sel.dispatchEvent(new Event('change'));
            var want = speedItems(data, sel.value).length,
              got = document.querySelectorAll('#scatter .pt').length;
            if (got !== want || want === 0)
              bad.push(sel.value + ': ' + got + ' drawn, ' + want + ' expected');
          }
          sel.value = start;
          sel.dispatchEvent(new Event('change'));
        }
        check(
          'scatter points on every family',
          bad.length === 0,
          bad.join('; ') || (sel ? sel.options.length + ' views' : 'no selector'),
        );
        // The heat map: a cell per family x variant, and a click opens the family's detail.
        var nVar = orderedVariants(data).length;
        v.heatCells = document.querySelectorAll('#heatmap .hm-cell').length;
        check(
          'heat map cells',
          v.heatCells === families(data).length * nVar,
          v.heatCells + ' cells for ' + families(data).length + ' families x ' + nVar + ' variants',
        );
        var cell = document.querySelector('#heatmap .hm-cell');
        if (cell) {
          var fam = document.getElementById('family-' + slug(cell.getAttribute('data-family')));
          cell.dispatchEvent(new MouseEvent('click', { bubbles: true }));
          check(
            'heat map click opens the family',
            fam && fam.open === true,
            fam ? 'open: ' + fam.open : 'no family block',
          );
          if (fam) fam.open = false;
        }
        v.families = families(data).map(function (f) {
          return String(f.name);
        });
        v.familyCards = document.querySelectorAll('.family').length;
        check('family cards', v.familyCards === v.families.length, v.familyCards + ' cards');
        v.summaryRows = document.querySelectorAll('table.summary tbody tr').length;
        // Every metric of every histogram draws without error.
        document.querySelectorAll('select.metric-select').forEach(function (s) {
          for (var i = 0; i < s.options.length; ++i) {
            s.selectedIndex = i;
            s.dispatchEvent(new Event('change'));
          }
          s.selectedIndex = 0;
          s.dispatchEvent(new Event('change'));
        });
      }
      var viewers = document.querySelectorAll('.viewer');
      v.viewers = viewers.length;
      var expectedViewers = mode === 'case' ? 1 : Array.isArray(data.worst) ? data.worst.length : 0;
      check(
        'viewers',
        viewers.length === expectedViewers,
        viewers.length + ' viewers, ' + expectedViewers + ' expected',
      );
      v.steps = [];
      viewers.forEach(function (vw, idx) {
        var r = { name: vw.getAttribute('data-case') };
        var mink = vw.querySelector('.minkowski-panel');
        var next = vw.querySelector('.step-next'),
          prev = vw.querySelector('.step-prev'),
          slider = vw.querySelector('.step-slider');
        r.steps = Number(slider.max) + 1;
        var before = vw.getAttribute('data-step'),
          drawnBefore = mink.querySelector('.layer').getAttribute('data-step'),
          svgBefore = mink.innerHTML;
        next.click();
        var afterNext = vw.getAttribute('data-step'),
          drawnAfter = mink.querySelector('.layer').getAttribute('data-step');
        r.next = {
          before: before,
          after: afterNext,
          drawn: drawnAfter,
          svgChanged: mink.innerHTML !== svgBefore,
        };
        slider.value = String(slider.max);
        slider.dispatchEvent(new Event('input'));
        r.sliderEnd = vw.getAttribute('data-step');
        prev.click();
        r.prev = vw.getAttribute('data-step');
        vw.querySelector('.view-zoom').click();
        r.zoomedLayers = vw.querySelectorAll('.layer').length;
        vw.querySelector('.view-fit').click();
        var sel = vw.querySelector('.variant-select');
        r.variants = sel.options.length;
        for (var i = 0; i < sel.options.length; ++i) {
          sel.selectedIndex = i;
          sel.dispatchEvent(new Event('change'));
        }
        slider.value = '0';
        slider.dispatchEvent(new Event('input'));
        r.stepWorks =
          r.steps > 1
            ? afterNext === String(Number(before) + 1) &&
              drawnAfter === afterNext &&
              r.next.svgChanged &&
              r.sliderEnd === String(r.steps - 1) &&
              r.prev === String(r.steps - 2)
            : true;
        v.steps.push(r);
        if (idx === 0)
          check('step control (first viewer)', r.steps > 1 && r.stepWorks, JSON.stringify(r));
        else check('step control (viewer ' + (idx + 1) + ')', r.stepWorks, JSON.stringify(r));
      });
    } catch (err) {
      v.errors.push('self-test: ' + (err && err.stack ? err.stack : err));
    }
    v.errors = v.errors.concat(window.__gjkErrors || []);
    v.ok =
      v.errors.length === 0 &&
      Object.keys(v.checks).every(function (k) {
        return v.checks[k].ok;
      });
    var pre = document.getElementById('selftest');
    pre.textContent = JSON.stringify(v);
    pre.hidden = false;
    pre.setAttribute('data-done', '1');
  }

  function main() {
    var app = document.getElementById('app');
    app.textContent = '';
    var mode = document.documentElement.getAttribute('data-mode') === 'case' ? 'case' : 'report';
    var data = null;
    try {
      data = readData();
      if (mode === 'case') renderCasePage(app, data);
      else renderReportPage(app, data);
    } catch (err) {
      console.error('gjk report: ' + (err && err.stack ? err.stack : err));
      app.appendChild(h('div', { class: 'error-box' }, 'The page could not be drawn: ' + err));
    }
    if (location.hash === '#selftest') selfTest(mode, data || {});
  }

  window.gjkReport = { fmt: fmt, num: num, hull: hull, rounded: rounded, clipPoly: clipPoly };
  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', main);
  else main();
})();
