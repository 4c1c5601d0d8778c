// ncc view: the page's script (sim/view/view.js). It reads the run that sim/view.cpp
// wrote into #ncc-data (the format is in view.cpp's head comment), draws it with
// three.js, and steps through the blocks that ran. Its state, for people and for the
// browser tests (tests/view), is `window.nccView` and the JSON in #ncc-state.
//
// URL hash: block=N (0 the start, 1.. the blocks that ran, `last`), step=K (then K
// blocks on or back), view=iso|top|front|right|fit, surface=0, rapids=0, ui=0 (the
// 3-D view alone), walk=1 (the state lists every block's line and end point).
(function () {
  'use strict';

  // ---- State for the tests ------------------------------------------------------
  var state = { ready: false, errors: window.nccErrors || [], warnings: [] };
  var statePre = document.getElementById('ncc-state');
  var consoleError = console.error, consoleWarn = console.warn;
  console.error = function () {
    state.errors.push(Array.prototype.map.call(arguments, String).join(' '));
    consoleError.apply(console, arguments);
  };
  console.warn = function () {
    state.warnings.push(Array.prototype.map.call(arguments, String).join(' '));
    consoleWarn.apply(console, arguments);
  };
  function publish() { statePre.textContent = JSON.stringify(state); }

  var hash = {};
  location.hash.replace(/^#/, '').split('&').forEach(function (kv) {
    if (!kv) return;
    var eq = kv.indexOf('=');
    hash[decodeURIComponent(eq < 0 ? kv : kv.slice(0, eq))] = eq < 0 ? '1' : decodeURIComponent(kv.slice(eq + 1));
  });
  if (hash.ui === '0') document.body.classList.add('bare');

  var $ = function (id) { return document.getElementById(id); };
  var timing = { start: Math.round(performance.now()) };  // ms since the page was asked for
  function mark(name) { timing[name] = Math.round(performance.now()); }
  var data = JSON.parse($('ncc-data').textContent);
  mark('parsed');
  var perUnit = Math.round(1 / data.unit);  // integers / perUnit: the same doubles as the decimals

  // ---- The records ----------------------------------------------------------------
  var nRec = data.counts.records;
  var kindOf = new Uint8Array(nRec);       // 0 rapid, 1 line, 2 arc, 3 thread
  var progOf = new Uint8Array(nRec);       // 1: programmed path under compensation
  var toolOf = new Int32Array(nRec);
  var procOf = new Uint8Array(nRec);
  var feedOf = new Float64Array(nRec);
  var ends = new Float64Array(nRec * 6);   // start x y z, end x y z (mm)
  var arcOf = new Int32Array(nRec).fill(-1);  // index into arcs
  var arcs = [];                              // {u, v, w, cu, cv, sweep (rad)} or null (drawn straight)
  (function decode() {
    var ops = data.moves, lanes = [], jump = null, proc = 0, tool = 0, feed = 0, r = 0;
    for (var k = 0; k < ops.length;) {
      var op = ops[k++];
      if (op === 8) { jump = [ops[k], ops[k + 1], ops[k + 2]]; k += 3; continue; }
      if (op === 9) { tool = ops[k++]; continue; }
      if (op === 10) { proc = ops[k++]; continue; }
      if (op === 11) { feed = ops[k++]; continue; }
      if (op >= 16) { feed = data.feeds[(op >> 4) - 1]; op &= 7; }
      var lane = proc * 2 + (op >= 4 ? 1 : 0);
      var p = jump || lanes[lane] || [0, 0, 0];
      jump = null;
      var e = [p[0] + ops[k], p[1] + ops[k + 1], p[2] + ops[k + 2]];
      k += 3;
      kindOf[r] = op & 3;
      progOf[r] = op >= 4 ? 1 : 0;
      toolOf[r] = tool;
      procOf[r] = proc;
      feedOf[r] = feed;
      for (var i = 0; i < 3; ++i) {
        ends[r * 6 + i] = p[i] / perUnit;
        ends[r * 6 + 3 + i] = e[i] / perUnit;
      }
      if ((op & 3) === 2) {
        var plane = ops[k], du = ops[k + 1], dv = ops[k + 2], sweep = ops[k + 3];
        k += 4;
        arcOf[r] = arcs.length;
        if (plane < 0) {
          arcs.push(null);
        } else {
          var u = Math.floor(plane / 3), v = plane % 3;
          arcs.push({ u: u, v: v, w: 3 - u - v, cu: (p[u] + du) / perUnit, cv: (p[v] + dv) / perUnit,
                      sweep: sweep * Math.PI / 180 });
        }
      }
      lanes[lane] = e;
      ++r;
    }
  })();

  mark('decoded');
  // ---- The steps (blocks that ran); step 0 is the start ----------------------------
  var steps = [];  // dline, records for each step (data.steps writes -n for n steps of 1, 1)
  (function () {
    var d = data.steps;
    for (var k = 0; k < d.length;) {
      if (d[k] < 0) { for (var n = -d[k++]; n > 0; --n) steps.push(1, 1); }
      else { steps.push(d[k], d[k + 1]); k += 2; }
    }
  })();
  var nSteps = steps.length / 2;
  var stepLine = new Int32Array(nSteps + 1), stepFile = new Int32Array(nSteps + 1);
  var stepRecEnd = new Int32Array(nSteps + 1);  // records drawn once the step has run
  var stepPosRec = new Int32Array(nSteps + 1);  // the last tool-centre record so far (-1: none)
  var stepMoved = new Uint8Array(nSteps + 1);
  (function () {
    var line = 0, rec = 0, last = -1, files = data.files, f = 0, file = 0;
    stepPosRec[0] = -1;
    for (var s = 1; s <= nSteps; ++s) {
      while (f < files.length && files[f][0] <= s) file = files[f++][1];
      line += steps[2 * s - 2];
      var n = steps[2 * s - 1];
      for (var i = rec; i < rec + n; ++i)
        if (!progOf[i]) { last = i; stepMoved[s] = 1; }
      rec += n;
      stepLine[s] = line;
      stepFile[s] = file;
      stepRecEnd[s] = rec;
      stepPosRec[s] = last;
    }
    if (nSteps > 0) { stepLine[0] = stepLine[1]; stepFile[0] = stepFile[1]; }
  })();
  var firstCentre = -1;
  for (var fc = 0; fc < nRec; ++fc) if (!progOf[fc]) { firstCentre = fc; break; }

  function before(list, s) {  // how many entries of [[step, ...]] (in step order) are at or before s
    var lo = 0, hi = list.length;
    while (lo < hi) { var mid = (lo + hi) >> 1; if (list[mid][0] <= s) lo = mid + 1; else hi = mid; }
    return lo;
  }
  var radii = {};
  data.tools.forEach(function (t) { radii[t[0]] = t[1]; });
  var times = data.times.map(function (deltas) {  // seconds at each step's end
    var t = new Float64Array(nSteps + 1), acc = 0;
    for (var s = 1; s <= nSteps; ++s) { acc += deltas[s - 1]; t[s] = acc / 10; }
    return t;
  });

  // What a step shows: the tool's place, the block, the tool, the offset.
  function stepState(s) {
    var rec = stepPosRec[s], pos;
    if (rec >= 0) pos = [ends[rec * 6 + 3], ends[rec * 6 + 4], ends[rec * 6 + 5]];
    else if (firstCentre >= 0) pos = [ends[firstCentre * 6], ends[firstCentre * 6 + 1], ends[firstCentre * 6 + 2]];
    else pos = [0, 0, 0];
    var t = data.tools_at[before(data.tools_at, s) - 1];
    var o = data.offsets[before(data.offsets, s) - 1];
    var notes = [];
    for (var n = before(data.notes, s - 1); n < data.notes.length && data.notes[n][0] === s; ++n) notes.push(data.notes[n][1]);
    return { block: s, file: stepFile[s], line: stepLine[s], position: pos, moved: !!stepMoved[s],
             tool: t ? t[1] : 0,
             process: rec >= 0 ? procOf[rec] : 0,
             feed: rec >= 0 && kindOf[rec] !== 0 ? feedOf[rec] : 0,
             offset: o ? { number: o[1], values: [o[2], o[3], o[4]] } : null, notes: notes };
  }

  // ---- Text ----------------------------------------------------------------------
  function fixed(x, d) { var s = x.toFixed(d); return s === '-' + (0).toFixed(d) ? (0).toFixed(d) : s; }
  function short(x) { return String(Math.round(x * 10000) / 10000); }
  function duration(sec) {
    var t = Math.round(sec * 10) / 10, h = Math.floor(t / 3600), m = Math.floor((t - h * 3600) / 60);
    var s = t - h * 3600 - m * 60, ss = (s < 10 ? '0' : '') + s.toFixed(1);
    return h > 0 ? h + ':' + (m < 10 ? '0' : '') + m + ':' + ss : m + ':' + ss;
  }
  function escapeHtml(s) {
    return s.replace(/[&<>"]/g, function (c) { return { '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' }[c]; });
  }
  function offsetName(o) {
    if (!o) return '\u2013 (none selected yet)';
    if (o.number === 0) return 'none (machine zero)';
    if (data.dialect === 'nc110') return 'origin ' + o.number;
    return o.number >= 1 && o.number <= 6 ? 'G' + (53 + o.number) : 'offset ' + o.number;
  }
  function fileName(f) { return data.sources[f] ? data.sources[f].name : '?'; }

  // ---- Geometry of the path --------------------------------------------------------
  var PALETTE = [0x4fc3f7, 0xffb74d, 0x81c784, 0xf06292, 0xfff176, 0xba68c8, 0x4db6ac, 0xa1887f];
  var RAPID = 0xff5252, PROGRAMMED = 0xcfd8dc, BACKGROUND = 0x1e2227;
  var toolColour = {}, toolOrder = [];
  for (var tr = 0; tr < nRec; ++tr) {
    if (progOf[tr] || kindOf[tr] === 0) continue;
    if (!(toolOf[tr] in toolColour)) { toolColour[toolOf[tr]] = PALETTE[toolOrder.length % PALETTE.length]; toolOrder.push(toolOf[tr]); }
  }

  // Chords of an arc record within `tol`: its points after the start, the end last.
  function arcSegments(a, r, tol) {
    var radius = Math.hypot(ends[r * 6 + a.u] - a.cu, ends[r * 6 + a.v] - a.cv);
    var step = tol < radius ? 2 * Math.acos(1 - tol / radius) : Math.PI / 2;
    return Math.max(1, Math.min(100000, Math.ceil(Math.abs(a.sweep) / Math.min(step, Math.PI / 2))));
  }
  var arcTolerance = data.arc_tolerance;
  (function () {  // at most ~3 million chords for all the arcs: coarser when there are more
    for (;;) {
      var total = 0;
      for (var r = 0; r < nRec; ++r) if (arcOf[r] >= 0 && arcs[arcOf[r]]) total += arcSegments(arcs[arcOf[r]], r, arcTolerance);
      if (total <= 3e6) break;
      arcTolerance *= 2;
    }
  })();
  // Calls f(x, y, z) for each point after the record's start, its end last.
  function recordPoints(r, f) {
    var a = arcOf[r] >= 0 ? arcs[arcOf[r]] : null, o = r * 6;
    if (!a) { f(ends[o + 3], ends[o + 4], ends[o + 5]); return; }
    var n = arcSegments(a, r, arcTolerance);
    var su = ends[o + a.u] - a.cu, sv = ends[o + a.v] - a.cv;
    var r0 = Math.hypot(su, sv), r1 = Math.hypot(ends[o + 3 + a.u] - a.cu, ends[o + 3 + a.v] - a.cv);
    var t0 = Math.atan2(sv, su), p = [0, 0, 0];
    for (var i = 1; i < n; ++i) {
      var t = i / n, ang = t0 + a.sweep * t, rad = r0 + (r1 - r0) * t;
      p[a.u] = a.cu + rad * Math.cos(ang);
      p[a.v] = a.cv + rad * Math.sin(ang);
      p[a.w] = ends[o + a.w] + (ends[o + 3 + a.w] - ends[o + a.w]) * t;
      f(p[0], p[1], p[2]);
    }
    f(ends[o + 3], ends[o + 4], ends[o + 5]);
  }

  // The box round the path and the stock; the scene is drawn about its centre so
  // that the GPU's 32-bit floats keep the small features.
  var box = [Infinity, Infinity, Infinity, -Infinity, -Infinity, -Infinity];
  function grow(x, y, z) {
    if (x < box[0]) box[0] = x; if (y < box[1]) box[1] = y; if (z < box[2]) box[2] = z;
    if (x > box[3]) box[3] = x; if (y > box[4]) box[4] = y; if (z > box[5]) box[5] = z;
  }
  var counts = [0, 0, 0];  // segments: feed, rapid, programmed
  function setOf(r) { return progOf[r] ? 2 : kindOf[r] === 0 ? 1 : 0; }
  for (var gr = 0; gr < nRec; ++gr) {
    grow(ends[gr * 6], ends[gr * 6 + 1], ends[gr * 6 + 2]);
    recordPoints(gr, function (x, y, z) { grow(x, y, z); counts[setOf(gr)]++; });
  }
  var stock = data.stock;
  if (stock) { grow(stock[0], stock[1], stock[2]); grow(stock[3], stock[4], stock[5]); }
  if (!(box[0] <= box[3])) box = [-10, -10, -10, 10, 10, 10];
  var centre = [(box[0] + box[3]) / 2, (box[1] + box[4]) / 2, (box[2] + box[5]) / 2];
  var diag = Math.max(1e-3, Math.hypot(box[3] - box[0], box[4] - box[1], box[5] - box[2]));

  // Vertices of each set and, per step, how many of them are done.
  var sets = [0, 1, 2].map(function (k) {
    return { pos: new Float32Array(counts[k] * 6), col: k === 0 ? new Float32Array(counts[k] * 6) : null,
             dist: k === 1 ? new Float32Array(counts[k] * 2) : null, n: 0, done: new Int32Array(nSteps + 1) };
  });
  (function build() {
    var r = 0;
    for (var s = 1; s <= nSteps; ++s) {
      for (; r < stepRecEnd[s]; ++r) {
        var set = sets[setOf(r)], px = ends[r * 6] - centre[0], py = ends[r * 6 + 1] - centre[1], pz = ends[r * 6 + 2] - centre[2];
        var c = set.col ? new THREE_Color(toolColour[toolOf[r]]) : null;
        recordPoints(r, function (x, y, z) {
          x -= centre[0]; y -= centre[1]; z -= centre[2];
          var o = set.n * 6;
          set.pos[o] = px; set.pos[o + 1] = py; set.pos[o + 2] = pz;
          set.pos[o + 3] = x; set.pos[o + 4] = y; set.pos[o + 5] = z;
          if (c) { set.col[o] = set.col[o + 3] = c[0]; set.col[o + 1] = set.col[o + 4] = c[1]; set.col[o + 2] = set.col[o + 5] = c[2]; }
          if (set.dist) { set.dist[set.n * 2] = 0; set.dist[set.n * 2 + 1] = Math.hypot(x - px, y - py, z - pz); }
          set.n++;
          px = x; py = y; pz = z;
        });
      }
      for (var k = 0; k < 3; ++k) sets[k].done[s] = sets[k].n * 2;
    }
  })();
  mark('geometry');
  function THREE_Color(hex) { return [((hex >> 16) & 255) / 255, ((hex >> 8) & 255) / 255, (hex & 255) / 255]; }

  // ---- The height map of the stock's top ------------------------------------------
  var surf = null;
  if (stock && data.cells[0] > 0) {
    var nx = data.cells[0], ny = data.cells[1], cells = nx * ny;
    surf = { nx: nx, ny: ny, cell: data.grid, x0: stock[0], y0: stock[1], x1: stock[3], y1: stock[4],
             bottom: stock[2], top: stock[5], h: new Float32Array(cells).fill(stock[5]), applied: 0, snaps: [],
             snapEvery: Math.max(2000, Math.ceil(nRec / 64)), maxSnaps: Math.max(4, Math.floor(64e6 / (cells * 4))) };
  }
  function radiusOf(tool) { return radii[tool] > 0 ? radii[tool] : 0; }
  // A flat end mill of radius r whose tip goes from a to b: every cell whose centre
  // comes within r of the centre line, as seen from above, goes down to the lowest
  // tip height over that part of the line.
  function cutSegment(ax, ay, az, bx, by, bz, r) {
    var S = surf;
    if (Math.min(az, bz) >= S.top) return;
    var cell = S.cell, nx = S.nx, h = S.h;
    var i0 = Math.max(0, Math.ceil((Math.min(ax, bx) - r - S.x0) / cell - 0.5));
    var i1 = Math.min(nx - 1, Math.floor((Math.max(ax, bx) + r - S.x0) / cell - 0.5));
    var j0 = Math.max(0, Math.ceil((Math.min(ay, by) - r - S.y0) / cell - 0.5));
    var j1 = Math.min(S.ny - 1, Math.floor((Math.max(ay, by) + r - S.y0) / cell - 0.5));
    var dx = bx - ax, dy = by - ay, dz = bz - az, a = dx * dx + dy * dy, r2 = r * r;
    for (var j = j0; j <= j1; ++j) {
      var py = ay - (S.y0 + (j + 0.5) * cell);
      for (var i = i0; i <= i1; ++i) {
        var px = ax - (S.x0 + (i + 0.5) * cell), c = px * px + py * py - r2, z;
        if (a < 1e-18) {
          if (c > 0) continue;
          z = Math.min(az, bz);
        } else {
          var b = 2 * (dx * px + dy * py), disc = b * b - 4 * a * c;
          if (disc < 0) continue;
          var sq = Math.sqrt(disc), t0 = (-b - sq) / (2 * a), t1 = (-b + sq) / (2 * a);
          if (t1 < 0 || t0 > 1) continue;
          z = Math.min(az + dz * Math.max(t0, 0), az + dz * Math.min(t1, 1));
        }
        if (z < S.bottom) z = S.bottom;
        var at = j * nx + i;
        if (z < h[at]) h[at] = z;
      }
    }
  }
  function cutRecord(r) {
    if (progOf[r] || kindOf[r] === 0) return;
    var rad = radiusOf(toolOf[r]) || surf.cell * 0.75, o = r * 6, x = ends[o], y = ends[o + 1], z = ends[o + 2];
    recordPoints(r, function (bx, by, bz) { cutSegment(x, y, z, bx, by, bz, rad); x = bx; y = by; z = bz; });
  }
  // Brings the height map to `rec` records in slices of `budget` ms; true when there.
  function surfaceTo(rec, budget) {
    var S = surf;
    if (rec < S.applied) {
      var snap = null;
      S.snaps.forEach(function (sn) { if (sn.rec <= rec) snap = sn; });
      if (snap) S.h.set(snap.h); else S.h.fill(S.top);
      S.applied = snap ? snap.rec : 0;
    }
    var until = performance.now() + budget;
    while (S.applied < rec) {
      cutRecord(S.applied++);
      if (S.applied % S.snapEvery === 0 && S.snaps.length < S.maxSnaps &&
          !(S.snaps.length && S.snaps[S.snaps.length - 1].rec >= S.applied))
        S.snaps.push({ rec: S.applied, h: S.h.slice() });
      if ((S.applied & 255) === 0 && performance.now() > until) return false;
    }
    return true;
  }

  // ---- The scene -------------------------------------------------------------------
  var have3d = typeof THREE !== 'undefined' && typeof THREE.OrbitControls !== 'undefined';
  var renderer = null, scene, camera, controls, world, objects = {}, toolMesh, surfaceMesh, pickMarks, pickLine;
  function notice(text) { var n = $('notice'); n.textContent = text; n.hidden = !text; }
  if (have3d) {
    try {
      renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    } catch (e) {
      renderer = null;
      state.warnings.push('WebGL: ' + e.message);
    }
  }
  if (!have3d) notice('This ncc was built without three.js (Debian\'s libjs-three): the 3-D view is missing.');
  else if (!renderer) notice('This browser gives the page no WebGL: the 3-D view is missing.');

  if (renderer) {
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setClearColor(BACKGROUND, 1);
    $('viewport').appendChild(renderer.domElement);
    scene = new THREE.Scene();
    camera = new THREE.PerspectiveCamera(35, 1, diag / 2000, diag * 200);
    camera.up.set(0, 0, 1);
    scene.add(camera);
    scene.add(new THREE.AmbientLight(0xffffff, 0.55));
    var light = new THREE.DirectionalLight(0xffffff, 0.65);
    light.position.set(0.3, 0.5, 1);
    camera.add(light);
    world = new THREE.Group();
    world.position.set(centre[0], centre[1], centre[2]);
    scene.add(world);

    // The path: what has run bright, what is ahead dim.
    var mats = [
      [new THREE.LineBasicMaterial({ vertexColors: THREE.VertexColors }),
       new THREE.LineBasicMaterial({ vertexColors: THREE.VertexColors, transparent: true, opacity: 0.22, depthWrite: false })],
      [new THREE.LineDashedMaterial({ color: RAPID, dashSize: diag / 150, gapSize: diag / 250 }),
       new THREE.LineDashedMaterial({ color: RAPID, dashSize: diag / 150, gapSize: diag / 250, transparent: true, opacity: 0.22, depthWrite: false })],
      [new THREE.LineBasicMaterial({ color: PROGRAMMED, transparent: true, opacity: 0.55 }),
       new THREE.LineBasicMaterial({ color: PROGRAMMED, transparent: true, opacity: 0.15, depthWrite: false })]];
    sets.forEach(function (set, k) {
      var position = new THREE.BufferAttribute(set.pos, 3);
      var colour = set.col ? new THREE.BufferAttribute(set.col, 3) : null;
      var dist = set.dist ? new THREE.BufferAttribute(set.dist, 1) : null;
      set.objects = [0, 1].map(function (ahead) {
        var g = new THREE.BufferGeometry();
        g.setAttribute('position', position);
        if (colour) g.setAttribute('color', colour);
        if (dist) g.setAttribute('lineDistance', dist);
        var o = new THREE.LineSegments(g, mats[k][ahead]);
        o.frustumCulled = false;
        o.renderOrder = ahead ? 0 : 1;
        o.userData.set = k;
        world.add(o);
        return o;
      });
    });

    // The work zero's axes, X red, Y green, Z blue.
    var axes = new THREE.AxesHelper(diag / 12);
    axes.position.set(-centre[0], -centre[1], -centre[2]);
    world.add(axes);

    // The stock: its edges, faint faces, corners to measure from, the machined top.
    if (stock) {
      var sx = stock[3] - stock[0], sy = stock[4] - stock[1], sz = stock[5] - stock[2];
      var sc = [(stock[0] + stock[3]) / 2 - centre[0], (stock[1] + stock[4]) / 2 - centre[1], (stock[2] + stock[5]) / 2 - centre[2]];
      var boxGeometry = new THREE.BoxBufferGeometry(sx, sy, sz);
      objects.stockEdges = new THREE.LineSegments(new THREE.EdgesGeometry(boxGeometry), new THREE.LineBasicMaterial({ color: 0x90a4ae }));
      objects.stockFaces = new THREE.Mesh(boxGeometry, new THREE.MeshBasicMaterial({ color: 0x90a4ae, transparent: true, opacity: 0.08, depthWrite: false, side: THREE.DoubleSide }));
      objects.stockEdges.position.set(sc[0], sc[1], sc[2]);
      objects.stockFaces.position.set(sc[0], sc[1], sc[2]);
      world.add(objects.stockEdges);
      world.add(objects.stockFaces);
      var corners = new Float32Array(24);
      for (var ci = 0; ci < 8; ++ci) {
        corners[ci * 3] = stock[ci & 1 ? 3 : 0] - centre[0];
        corners[ci * 3 + 1] = stock[ci & 2 ? 4 : 1] - centre[1];
        corners[ci * 3 + 2] = stock[ci & 4 ? 5 : 2] - centre[2];
      }
      var cornerGeometry = new THREE.BufferGeometry();
      cornerGeometry.setAttribute('position', new THREE.BufferAttribute(corners, 3));
      objects.corners = new THREE.Points(cornerGeometry, new THREE.PointsMaterial({ color: 0xb0bec5, size: 5, sizeAttenuation: false }));
      world.add(objects.corners);
    }
    if (surf) {
      var mx = Math.max(2, surf.nx), my = Math.max(2, surf.ny);
      surf.mx = mx; surf.my = my;
      var sp = new Float32Array(mx * my * 3), idx = [];
      for (var j = 0; j < my; ++j)
        for (var i = 0; i < mx; ++i) {
          var v = (j * mx + i) * 3;
          sp[v] = (i === 0 ? surf.x0 : i === mx - 1 ? surf.x1 : surf.x0 + (i + 0.5) * surf.cell) - centre[0];
          sp[v + 1] = (j === 0 ? surf.y0 : j === my - 1 ? surf.y1 : surf.y0 + (j + 0.5) * surf.cell) - centre[1];
          sp[v + 2] = surf.top - centre[2];
          if (i + 1 < mx && j + 1 < my) {
            var q = j * mx + i;
            idx.push(q, q + 1, q + mx + 1, q, q + mx + 1, q + mx);
          }
        }
      var sg = new THREE.BufferGeometry();
      sg.setAttribute('position', new THREE.BufferAttribute(sp, 3));
      sg.setAttribute('color', new THREE.BufferAttribute(new Float32Array(mx * my * 3), 3));
      sg.setIndex(mx * my > 65535 ? new THREE.Uint32BufferAttribute(idx, 1) : new THREE.Uint16BufferAttribute(idx, 1));
      surfaceMesh = new THREE.Mesh(sg, new THREE.MeshLambertMaterial({
        vertexColors: THREE.VertexColors, side: THREE.DoubleSide, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 }));
      world.add(surfaceMesh);
    }

    // The tool: a cylinder of its radius standing on the tip (a cone when its radius is unknown).
    toolMesh = new THREE.Group();
    world.add(toolMesh);

    // Measuring: the two points picked and the line between them.
    var markGeometry = new THREE.BufferGeometry();
    markGeometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(6), 3));
    pickMarks = new THREE.Points(markGeometry, new THREE.PointsMaterial({ color: 0xffeb3b, size: 9, sizeAttenuation: false, depthTest: false }));
    pickLine = new THREE.Line(markGeometry, new THREE.LineBasicMaterial({ color: 0xffeb3b, depthTest: false }));
    pickMarks.renderOrder = pickLine.renderOrder = 10;
    pickMarks.visible = pickLine.visible = false;
    pickMarks.frustumCulled = pickLine.frustumCulled = false;
    world.add(pickMarks);
    world.add(pickLine);

    controls = new THREE.OrbitControls(camera, renderer.domElement);
    controls.enableKeys = false;  // the arrows step through the blocks
    controls.screenSpacePanning = true;
    controls.addEventListener('change', requestRender);
    controls.addEventListener('start', function () { fitted = null; });
  }

  mark('scene');
  var renderQueued = false;
  var loading = true;  // one picture when everything is in place
  function render() {
    renderQueued = false;
    if (renderer && !loading) renderer.render(scene, camera);
  }
  function requestRender() {
    if (renderQueued) return;
    renderQueued = true;
    requestAnimationFrame(render);
  }
  function resize() {
    if (!renderer) return;
    var el = $('viewport'), w = Math.max(1, el.clientWidth), h = Math.max(1, el.clientHeight);
    renderer.setSize(w, h, false);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    if (fitted) setView(fitted);  // untouched since: fitted again to the new shape
    else render();
  }
  window.addEventListener('resize', resize);

  var fitted = null;  // the view last chosen, while the mouse has not moved the camera since
  function setView(name) {
    if (!renderer) return;
    fitted = name;
    var dirs = { iso: [1, -1, 0.9], top: [0, -1e-4, 1], front: [0, -1, 0], right: [1, 0, 0], fit: null };
    var d = dirs[name] || null;
    if (!d) {  // fit: the direction the camera looks from now
      var now = camera.position.clone().sub(controls.target);
      d = now.lengthSq() > 0 ? [now.x, now.y, now.z] : dirs.iso;
    }
    var len = Math.hypot(d[0], d[1], d[2]);
    // Far enough that the box, seen from there, fills the view with a margin.
    var back = new THREE.Vector3(d[0] / len, d[1] / len, d[2] / len);
    var right = new THREE.Vector3().crossVectors(camera.up, back);
    if (right.lengthSq() < 1e-12) right.set(1, 0, 0);
    right.normalize();
    var up = new THREE.Vector3().crossVectors(back, right);
    var halfW = 0, halfH = 0, halfD = 0;
    for (var c = 0; c < 8; ++c) {
      var v = new THREE.Vector3(box[c & 1 ? 3 : 0] - centre[0], box[c & 2 ? 4 : 1] - centre[1], box[c & 4 ? 5 : 2] - centre[2]);
      halfW = Math.max(halfW, Math.abs(v.dot(right)));
      halfH = Math.max(halfH, Math.abs(v.dot(up)));
      halfD = Math.max(halfD, v.dot(back));
    }
    var tanV = Math.tan(camera.fov * Math.PI / 360), tanH = tanV * camera.aspect;
    var dist = Math.max(halfW / tanH, halfH / tanV, diag / 100) * 1.08 + halfD;
    controls.target.set(centre[0], centre[1], centre[2]);
    camera.position.set(centre[0] + d[0] / len * dist, centre[1] + d[1] / len * dist, centre[2] + d[2] / len * dist);
    camera.up.set(0, 0, 1);
    camera.lookAt(controls.target);
    controls.update();
    state.camera = { view: name, position: camera.position.toArray(), target: controls.target.toArray(), aspect: camera.aspect };
    render();
  }
  Array.prototype.forEach.call(document.querySelectorAll('#toolbar button[data-view]'), function (b) {
    b.addEventListener('click', function () { setView(b.getAttribute('data-view')); });
  });

  // ---- Stepping ------------------------------------------------------------------
  var current = 0, surfaceWanted = 0, surfaceTimer = 0;
  function updateTool(st) {
    if (!renderer) return;
    toolMesh.position.set(st.position[0] - centre[0], st.position[1] - centre[1], st.position[2] - centre[2]);
    if (toolMesh.userData.tool === st.tool) return;
    toolMesh.userData.tool = st.tool;
    while (toolMesh.children.length) {
      var c = toolMesh.children.pop();
      c.geometry.dispose();
      c.material.dispose();
    }
    var colour = toolColour[st.tool] !== undefined ? toolColour[st.tool] : 0xeceff1;
    var r = radiusOf(st.tool), mat = new THREE.MeshLambertMaterial({ color: colour, transparent: true, opacity: 0.7 });
    var mesh;
    if (r > 0) {
      var len = Math.max(4 * r, diag / 20);
      mesh = new THREE.Mesh(new THREE.CylinderBufferGeometry(r, r, len, 32), mat);
      mesh.rotation.x = Math.PI / 2;
      mesh.position.z = len / 2;
    } else {
      var size = diag / 60;
      mesh = new THREE.Mesh(new THREE.ConeBufferGeometry(size / 3, size, 16), mat);
      mesh.rotation.x = -Math.PI / 2;
      mesh.position.z = size / 2;
    }
    toolMesh.add(mesh);
  }
  function updatePath(s) {
    if (!renderer) return;
    var ahead = $('show-future').checked;
    sets.forEach(function (set) {
      var done = set.done[s], all = set.n * 2;
      set.objects[0].geometry.setDrawRange(0, done);
      set.objects[1].geometry.setDrawRange(done, all - done);
      set.objects[1].visible = ahead && set.objects[0].visible;
    });
  }
  var colourTop = [0.66, 0.72, 0.78], colourDeep = [0.33, 0.45, 0.58];  // the stock's top, the deepest cut
  function updateSurfaceMesh() {
    if (!surfaceMesh) return;
    var S = surf, g = surfaceMesh.geometry, pos = g.attributes.position.array, col = g.attributes.color.array;
    var depth = Math.max(1e-9, S.top - S.bottom);
    for (var j = 0; j < S.my; ++j)
      for (var i = 0; i < S.mx; ++i) {
        var v = j * S.mx + i, z = S.h[Math.min(j, S.ny - 1) * S.nx + Math.min(i, S.nx - 1)];
        pos[v * 3 + 2] = z - centre[2];
        var t = Math.min(1, Math.max(0, (S.top - z) / depth)), k = t > 0 ? 0.35 + 0.65 * t : 0;
        for (var c = 0; c < 3; ++c) col[v * 3 + c] = colourTop[c] + (colourDeep[c] - colourTop[c]) * k;
      }
    g.attributes.position.needsUpdate = true;
    g.attributes.color.needsUpdate = true;
    g.computeVertexNormals();
  }
  // The surface follows the step in slices, so that a long jump does not freeze the page.
  function surfaceWork() {
    surfaceTimer = 0;
    if (!surf) return finishLoad();
    var doneNow = surfaceTo(surfaceWanted, state.ready ? 30 : 1000);
    if (doneNow) updateSurfaceMesh();
    state.surface.block = doneNow ? current : null;
    if (doneNow) {
      var cut = 0, lowest = surf.top;
      for (var i = 0; i < surf.h.length; ++i) if (surf.h[i] < surf.top) { ++cut; if (surf.h[i] < lowest) lowest = surf.h[i]; }
      state.surface.cut = cut;
      state.surface.lowest = Math.round(lowest * perUnit) / perUnit;
    }
    render();
    if (!doneNow) { surfaceTimer = setTimeout(surfaceWork, 0); publish(); return; }
    finishLoad();
  }

  function go(s) {
    s = Math.max(0, Math.min(nSteps, Math.round(s)));
    current = s;
    var st = stepState(s);
    updatePath(s);
    updateTool(st);
    showPanel(st);
    sourceShow(st.file, st.line, true);
    $('slider').value = s;
    state.block = s;
    state.file = st.file;
    state.line = st.line;
    state.position = st.position;
    state.tool = st.tool;
    state.feed = st.feed;
    state.offset = st.offset;
    state.moved = st.moved;
    state.times = {};
    data.models.forEach(function (m, k) { state.times[m.name] = times[k][s]; });
    if (surf) {
      surfaceWanted = stepRecEnd[s];
      if (!surfaceTimer) surfaceTimer = setTimeout(surfaceWork, 0);
    }
    requestRender();
    publish();
  }
  function step(n) { go(current + n); }

  // ---- The panel ---------------------------------------------------------------------
  function showPanel(st) {
    var s = st.block;
    $('info-block').textContent = s === 0 ? 'start (none ran yet)' : s + ' of ' + nSteps + (st.moved ? '' : ' (no move)');
    $('info-source').textContent = nSteps ? fileName(st.file) + ':' + st.line : '';
    $('info-position').textContent = 'X' + fixed(st.position[0], 4) + '  Y' + fixed(st.position[1], 4) + '  Z' + fixed(st.position[2], 4);
    var r = radiusOf(st.tool);
    $('info-tool').textContent = (st.tool ? 'T' + st.tool : 'no T') +
      (r > 0 ? ' (radius ' + short(r) + ' mm)' : st.tool ? ' (radius unknown)' : '');
    $('info-feed').textContent = st.feed > 0 ? 'F' + short(st.feed) + ' mm/min' : (stepPosRec[s] >= 0 && kindOf[stepPosRec[s]] === 0 ? 'rapid' : '\u2013');
    var o = st.offset;
    $('info-offset').textContent = offsetName(o) + (o && o.number ? '  X' + short(o.values[0]) + ' Y' + short(o.values[1]) + ' Z' + short(o.values[2]) : '');
    $('info-note-row').hidden = !st.notes.length;
    $('info-note').textContent = st.notes.join('; ');
    var rows = '';
    data.models.forEach(function (m, k) {
      rows += '<tr><td>' + escapeHtml(m.name) + '</td><td>' + duration(times[k][s]) + '</td><td>' + duration(m.total) + '</td></tr>';
    });
    $('times-body').innerHTML = rows;
    $('counter').textContent = 'block ' + s + ' / ' + nSteps;
  }

  // ---- The source pane (only the lines in sight are in the document) --------------
  var sourceLines = data.sources.map(function (f) { return f.text.split('\n'); });
  var lineMarks = data.sources.map(function () { return {}; });
  data.diagnostics.forEach(function (d) {
    if (d.line > 0 && lineMarks[d.file] && lineMarks[d.file][d.line] !== 'error')
      lineMarks[d.file][d.line] = d.severity === 'warning' || d.severity === 'note' ? 'warning' : 'error';
  });
  var ranLines = data.sources.map(function () { return new Uint8Array(0); });
  (function () {
    sourceLines.forEach(function (ls, f) { ranLines[f] = new Uint8Array(ls.length + 2); });
    for (var s = 1; s <= nSteps; ++s) if (ranLines[stepFile[s]] && stepLine[s] < ranLines[stepFile[s]].length) ranLines[stepFile[s]][stepLine[s]] = 1;
  })();
  var pane = $('source-pane'), paneLines = $('source-lines'), LINE = 18;
  var shownFile = -1, curFile = -1, curLine = 0, flashLine = 0;
  data.sources.forEach(function (f, i) {
    var o = document.createElement('option');
    o.value = i;
    o.textContent = f.name;
    $('source-file').appendChild(o);
  });
  $('source-file').hidden = data.sources.length < 2;
  $('source-file').addEventListener('change', function () { sourceFile(+this.value); });
  function sourceFile(f) {
    if (f === shownFile || !sourceLines[f]) return;
    shownFile = f;
    $('source-file').value = f;
    $('source-spacer').style.height = sourceLines[f].length * LINE + 'px';
    pane.scrollTop = 0;
    drawLines();
  }
  function drawLines() {
    var ls = sourceLines[shownFile];
    if (!ls) return;
    var first = Math.max(0, Math.floor(pane.scrollTop / LINE) - 20);
    var last = Math.min(ls.length, first + Math.ceil((pane.clientHeight || 600) / LINE) + 40);
    var html = '';
    for (var i = first; i < last; ++i) {
      var n = i + 1, cls = 'ln';
      if (ranLines[shownFile][n]) cls += ' ran';
      if (lineMarks[shownFile][n]) cls += ' ' + lineMarks[shownFile][n];
      if (shownFile === curFile && n === curLine) cls += ' cur';
      if (n === flashLine) cls += ' flash';
      html += '<div class="' + cls + '" data-line="' + n + '"><span class="no">' + n + '</span>' + escapeHtml(ls[i].replace(/\r$/, '')) + '</div>';
    }
    paneLines.style.top = first * LINE + 'px';
    paneLines.innerHTML = html;
  }
  pane.addEventListener('scroll', drawLines);
  function sourceShow(f, line, isCurrent) {
    if (!sourceLines.length) return;
    if (isCurrent) { curFile = f; curLine = line; flashLine = 0; }
    sourceFile(f);
    $('source-where').textContent = line ? fileName(f) + ':' + line : '';
    var y = (line - 1) * LINE, h = pane.clientHeight || 300;
    if (y < pane.scrollTop + LINE || y > pane.scrollTop + h - 2 * LINE) pane.scrollTop = Math.max(0, y - h / 3);
    drawLines();
  }
  paneLines.addEventListener('click', function (e) {
    var el = e.target.closest('.ln');
    if (!el) return;
    var line = +el.getAttribute('data-line');
    for (var k = 1; k <= nSteps; ++k) {  // the next block that ran this line, after the one shown
      var s = (current + k - 1) % nSteps + 1;
      if (stepFile[s] === shownFile && stepLine[s] === line) { go(s); return; }
    }
  });

  // ---- Diagnostics -------------------------------------------------------------------
  (function () {
    var list = data.diagnostics;
    if (!list.length) return;
    var errors = list.filter(function (d) { return d.severity === 'error' || d.severity === 'fatal'; }).length;
    $('diagnostics').hidden = false;
    $('diagnostics-head').textContent = list.length + (list.length === 1 ? ' diagnostic' : ' diagnostics') +
      (errors ? ': the path shown is what ran up to the first error.' : '');
    list.forEach(function (d) {
      var li = document.createElement('li');
      li.className = d.severity;
      li.textContent = (d.line ? fileName(d.file) + ':' + d.line + ':' + d.column + ': ' : '') + d.severity + ': ' + d.message + (d.id ? ' [' + d.id + ']' : '');
      if (d.line) li.addEventListener('click', function () {
        sourceShow(d.file, d.line, false);
        flashLine = d.line;
        drawLines();
      });
      $('diagnostics-list').appendChild(li);
    });
  })();

  // ---- Measuring -------------------------------------------------------------------
  var picks = [];
  function showMeasure() {
    var el = $('measure-text');
    var p = function (q) { return 'X' + fixed(q[0], 3) + ' Y' + fixed(q[1], 3) + ' Z' + fixed(q[2], 3); };
    if (!picks.length) { el.innerHTML = '<span class="dim">Click two points of the path or the stock to measure.</span>'; return; }
    var html = 'A ' + p(picks[0]);
    if (picks.length > 1) {
      var d = [picks[1][0] - picks[0][0], picks[1][1] - picks[0][1], picks[1][2] - picks[0][2]];
      html += '<br>B ' + p(picks[1]) + '<br>dX ' + fixed(d[0], 3) + ' dY ' + fixed(d[1], 3) + ' dZ ' + fixed(d[2], 3) +
              '<br>distance ' + fixed(Math.hypot(d[0], d[1], d[2]), 3) + ' mm';
    } else {
      html += '<br><span class="dim">and a second point.</span>';
    }
    el.innerHTML = html + ' <button type="button" id="measure-clear">clear</button>';
    $('measure-clear').addEventListener('click', clearPicks);
  }
  function showPicks() {
    if (!renderer) return;
    var a = pickMarks.geometry.attributes.position;
    picks.forEach(function (q, i) { a.setXYZ(i, q[0] - centre[0], q[1] - centre[1], q[2] - centre[2]); });
    if (picks.length === 1) a.setXYZ(1, picks[0][0] - centre[0], picks[0][1] - centre[1], picks[0][2] - centre[2]);
    a.needsUpdate = true;
    pickMarks.visible = picks.length > 0;
    pickLine.visible = picks.length > 1;
    render();
  }
  function clearPicks() { picks = []; showMeasure(); showPicks(); state.picks = picks; publish(); }
  function pick(clientX, clientY) {
    var rect = renderer.domElement.getBoundingClientRect();
    var mouse = new THREE.Vector2((clientX - rect.left) / rect.width * 2 - 1, -(clientY - rect.top) / rect.height * 2 + 1);
    var ray = new THREE.Raycaster();
    ray.setFromCamera(mouse, camera);
    var perPixel = 2 * camera.position.distanceTo(controls.target) * Math.tan(camera.fov * Math.PI / 360) / rect.height;
    ray.params.Line.threshold = 6 * perPixel;
    ray.params.Points.threshold = 8 * perPixel;
    var targets = [];
    sets.forEach(function (set) { set.objects.forEach(function (o) { if (o.visible) targets.push(o); }); });
    if (objects.corners && objects.corners.visible) targets.push(objects.corners);
    var best = null, bestDist = Infinity;
    ray.intersectObjects(targets, false).forEach(function (hit) {
      var d = ray.ray.distanceToPoint(hit.point);
      if (hit.object === objects.corners) d -= 2 * perPixel;  // a corner wins over a line through it
      if (d < bestDist) { bestDist = d; best = hit; }
    });
    if (!best) return null;
    var pos = best.object.geometry.attributes.position, v = best.index;
    if (best.object !== objects.corners) {  // the nearer end of the segment hit
      var a = new THREE.Vector3().fromBufferAttribute(pos, v), b = new THREE.Vector3().fromBufferAttribute(pos, v + 1);
      var local = world.worldToLocal(best.point.clone());
      if (local.distanceToSquared(b) < local.distanceToSquared(a)) v += 1;
    }
    var q = [pos.getX(v) + centre[0], pos.getY(v) + centre[1], pos.getZ(v) + centre[2]];
    return q.map(function (x) { return Math.round(x * perUnit) / perUnit; });
  }
  if (renderer) {
    var down = null;
    renderer.domElement.addEventListener('pointerdown', function (e) { down = e.button === 0 ? [e.clientX, e.clientY] : null; });
    renderer.domElement.addEventListener('pointerup', function (e) {
      if (!down || Math.hypot(e.clientX - down[0], e.clientY - down[1]) > 4) return;
      clickAt(e.clientX, e.clientY);
    });
  }
  function clickAt(clientX, clientY) {
    var q = pick(clientX, clientY);
    if (!q) return;
    if (picks.length >= 2) picks = [];
    picks.push(q);
    state.picks = picks;
    showMeasure();
    showPicks();
    state.measured = $('measure-text').textContent;
    publish();
  }
  // Where a point (mm) is on the screen (client pixels).
  function onScreen(p) {
    var rect = renderer.domElement.getBoundingClientRect();
    var v = new THREE.Vector3(p[0], p[1], p[2]).project(camera);
    return [rect.left + (v.x + 1) / 2 * rect.width, rect.top + (1 - v.y) / 2 * rect.height];
  }
  showMeasure();

  // ---- Controls ----------------------------------------------------------------------
  var slider = $('slider');
  slider.max = nSteps;
  slider.addEventListener('input', function () { stopPlay(); go(+slider.value); });
  $('go-first').addEventListener('click', function () { stopPlay(); go(0); });
  $('go-back').addEventListener('click', function () { stopPlay(); step(-1); });
  $('go-forward').addEventListener('click', function () { stopPlay(); step(1); });
  $('go-last').addEventListener('click', function () { stopPlay(); go(nSteps); });
  var playing = 0;
  function stopPlay() {
    if (!playing) return;
    clearInterval(playing);
    playing = 0;
    $('go-play').innerHTML = '&#x25B6;';
  }
  function play() {
    if (playing) { stopPlay(); return; }
    if (current >= nSteps) go(0);
    $('go-play').innerHTML = '&#x275A;&#x275A;';
    playing = setInterval(function () {
      if (current >= nSteps) { stopPlay(); return; }
      step(+$('play-speed').value);
    }, 60);
  }
  $('go-play').addEventListener('click', play);
  window.addEventListener('keydown', function (e) {
    var t = e.target;
    if (t && (t.tagName === 'SELECT' || (t.tagName === 'INPUT' && t.type !== 'checkbox' && t !== slider))) return;
    var n = e.shiftKey ? 10 : e.ctrlKey || e.metaKey ? 100 : 1;
    if (e.key === 'ArrowRight' || e.key === 'ArrowDown') { stopPlay(); step(n); }
    else if (e.key === 'ArrowLeft' || e.key === 'ArrowUp') { stopPlay(); step(-n); }
    else if (e.key === 'Home') { stopPlay(); go(0); }
    else if (e.key === 'End') { stopPlay(); go(nSteps); }
    else if (e.key === ' ') play();
    else if (e.key === 'Escape') clearPicks();
    else return;
    e.preventDefault();
  });
  function visibility() {
    if (!renderer) return;
    var rapids = $('show-rapids').checked, programmed = $('show-programmed').checked, ahead = $('show-future').checked;
    sets[1].objects[0].visible = rapids;
    sets[2].objects[0].visible = programmed;
    sets.forEach(function (set) { set.objects[1].visible = ahead && set.objects[0].visible; });
    ['stockEdges', 'stockFaces', 'corners'].forEach(function (k) { if (objects[k]) objects[k].visible = $('show-stock').checked; });
    if (surfaceMesh) surfaceMesh.visible = $('show-surface').checked;
    render();
  }
  ['show-rapids', 'show-programmed', 'show-future', 'show-stock', 'show-surface'].forEach(function (id) {
    $(id).addEventListener('change', visibility);
  });
  $('help-button').addEventListener('click', function () { $('help').hidden = !$('help').hidden; });

  // ---- Header and legend -------------------------------------------------------------
  $('title').textContent = data.title;
  $('dialect').textContent = data.dialect;
  $('dialect').hidden = !data.dialect;
  var summary = nSteps + ' blocks ran, ' + data.counts.moves + ' moves';
  if (data.counts.records !== data.counts.moves) summary += ' (drawn as ' + data.counts.records + ', straight runs merged within ' + data.tolerance + ' mm)';
  summary += '; arcs as chords within ' + short(arcTolerance) + ' mm';
  if (surf) {
    summary += '; surface: height map of ' + short(surf.cell) + ' mm cells (' + surf.nx + ' \u00d7 ' + surf.ny +
               '), cut by a flat end mill of the tool\'s radius';
    if (toolOrder.some(function (t) { return !(radiusOf(t) > 0); })) summary += ' (unknown: 0.75 cell)';
  }
  $('summary').textContent = summary;
  (function () {
    var html = '';
    var hex = function (c) { return '#' + ('00000' + c.toString(16)).slice(-6); };
    toolOrder.forEach(function (t) {
      html += '<span class="swatch" style="background:' + hex(toolColour[t]) + '"></span>' + (t ? 'T' + t : 'no tool') +
              (radiusOf(t) > 0 ? ' R' + short(radiusOf(t)) : '');
    });
    if (sets[1].n) html += '<span class="swatch dashed"></span>rapid';
    if (sets[2].n) html += '<span class="swatch" style="background:' + hex(PROGRAMMED) + '"></span>programmed';
    $('legend').innerHTML = html;
    $('legend').hidden = !html;
  })();

  // ---- The page's API, and the start ------------------------------------------------
  state.blocks = nSteps;
  state.moves = data.counts.moves;
  state.records = data.counts.records;
  state.tolerance = data.tolerance;
  state.arcTolerance = arcTolerance;
  state.origin = data.origin;
  state.surface = surf ? { cell: surf.cell, nx: surf.nx, ny: surf.ny, block: null } : null;
  state.webgl = !!renderer;
  if (renderer) {
    var gl = renderer.getContext(), info = gl.getExtension('WEBGL_debug_renderer_info');
    state.renderer = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
  }
  state.diagnostics = data.diagnostics.length;
  window.nccView = {
    get ready() { return state.ready; },
    get block() { return current; },
    get blocks() { return nSteps; },
    get position() { return stepState(current).position; },
    step: step,
    go: go,
    first: function () { go(0); },
    last: function () { go(nSteps); },
    view: setView,
    at: stepState,
    state: function () { return JSON.parse(JSON.stringify(state)); }
  };

  function finishLoad() {
    if (state.ready) { publish(); return; }
    mark('surface');
    loading = false;
    render();
    mark('render');
    state.canvas = canvasCheck();
    if (hash.measure && renderer) {  // clicks where the ends of records A and B are drawn (tests)
      state.aimed = hash.measure.split(',').map(function (r) {
        var p = [ends[+r * 6 + 3], ends[+r * 6 + 4], ends[+r * 6 + 5]], at = onScreen(p);
        clickAt(at[0], at[1]);
        return p;
      });
    }
    mark('ready');
    state.timing = timing;
    state.loadMs = timing.ready;
    state.ready = true;
    publish();
  }
  // The pixels that differ from the background: the test of a drawn canvas.
  function canvasCheck() {
    if (!renderer) return { width: 0, height: 0, drawn: 0 };
    var gl = renderer.getContext(), w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
    var px = new Uint8Array(w * h * 4), drawn = 0;
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, px);
    var bg = THREE_Color(BACKGROUND).map(function (c) { return Math.round(c * 255); });
    for (var i = 0; i < px.length; i += 4)
      if (Math.abs(px[i] - bg[0]) + Math.abs(px[i + 1] - bg[1]) + Math.abs(px[i + 2] - bg[2]) > 24) ++drawn;
    return { width: w, height: h, drawn: drawn };
  }

  if (hash.surface === '0') $('show-surface').checked = false;
  if (hash.rapids === '0') $('show-rapids').checked = false;
  resize();
  visibility();
  setView(hash.view || 'iso');
  var start = hash.block === undefined || hash.block === 'last' ? nSteps : +hash.block;
  mark('views');
  go(isFinite(start) ? start : nSteps);
  mark('go');
  if (hash.step) step(+hash.step);
  if (hash.walk === '1') {
    state.walk = [];
    for (var w = 0; w <= nSteps; ++w) {
      var ws = stepState(w);
      state.walk.push([ws.file, ws.line, ws.position[0], ws.position[1], ws.position[2], ws.moved ? 1 : 0]);
    }
  }
  if (!surf) finishLoad();
  else publish();
  window.addEventListener('hashchange', function () {  // #block=N and #view=V typed into the address bar
    var b = /[#&]block=(\d+|last)/.exec(location.hash), v = /[#&]view=(\w+)/.exec(location.hash);
    if (b) go(b[1] === 'last' ? nSteps : +b[1]);
    if (v) setView(v[1]);
  });
})();
