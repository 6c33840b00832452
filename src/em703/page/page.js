// The EM-703 coordinatograph in the page: the tapes of a job sheet, decoded
// by em703 (the page reads the frames and the rows it was given, it never
// decodes a tape), run frame by frame by the rules of em703_sim.
// Units: 0.01 mm (the tape's), integers; lengths summed as em703 sim sums
// them (a cycle pair's passes added as reps * length when the pair ends).
(function () {
  'use strict';
  var LINE_SPEED = 5500, ARC_SPEED = 1500, TRAVEL_SPEED = 5500;   // mm/min
  var TWO_PI = 2 * Math.PI;
  var LINE = 1, TRAVEL = 2, ARC = 3, DOT = 4, RAISE = 5;
  var NF = 7;                       // numbers a frame: x y dx dy cyc k row-step
  var ALPHABET = '0123456789abcdefghijklmnopqrstuv';
  var SERVICE = { 10: 'X', 11: 'Y', 12: '-', 14: 'K', 15: 'KK', 16: 'DX', 17: 'DY',
                  24: 'CYC', 31: 'GM' };
  var SERVICE_CYR = { 16: '\u0394X', 17: '\u0394Y', 24: '\u0426', 14: '\u041a',
                      15: '\u041a\u041a', 31: '\u0413\u041c' };
  var DIGITS_8 = [0, 1, 2, 3, 4, 5, 6, 7, 8, 9];
  var DIGITS_K = [0, 1, 2, 19, 4, 21, 22, 7, 8, 25];
  var STRIP_ROWS = 33;              // rows shown, the reader mark in the middle

  function $(id) { return document.getElementById(id); }
  var job = JSON.parse($('em703-job').textContent);
  var tapes = {};                   // key -> tape, parsed when first selected

  // ------------------------------------------------------------------
  // A tape: its frames, where each starts on the tape and in the run.
  function loadTape(key) {
    if (tapes[key]) return tapes[key];
    var el = $('em703-tape-' + key);
    if (!el) throw new Error('no tape ' + key + ' in this page');
    var d = JSON.parse(el.textContent);
    var f = Int32Array.from(d.f);
    var n = f.length / NF;
    var first = new Int32Array(n), start = new Float64Array(n + 1);
    var row = d.gm[0], e = 0, i;
    for (i = 0; i < n; i++) {
      row += f[i * NF + 6];
      first[i] = row;
    }
    i = 0;
    while (i < n) {
      var cyc = f[i * NF + 4];
      if (cyc >= 2 && i + 1 < n) {
        start[i] = e;
        start[i + 1] = e + 1;
        e += 2 * cyc;
        i += 2;
      } else {
        start[i] = e;
        e += 1;
        i += 1;
      }
    }
    start[n] = e;
    var rows = new Uint8Array(d.r.length);
    for (i = 0; i < d.r.length; i++) rows[i] = ALPHABET.indexOf(d.r.charAt(i));
    var t = { key: key, d: d, f: f, n: n, first: first, start: start, total: e, rows: rows,
              controlled: d.code === 'K' };
    tapes[key] = t;
    return t;
  }

  // The last row of frame i (its KK): the row before the next frame or the closing GM.
  function lastRow(t, i) { return (i + 1 < t.n ? t.first[i + 1] : t.d.gm[1]) - 1; }

  // ------------------------------------------------------------------
  // The machine: em703_sim's rules.
  function arcSweep(x0, y0, x1, y1, clockwise) {
    var a0 = Math.atan2(y0, x0), a1 = Math.atan2(y1, x1), turn, a;
    a = clockwise ? a0 - a1 : a1 - a0;
    turn = a - Math.floor(a / TWO_PI) * TWO_PI;
    if (turn <= 1e-12) turn = TWO_PI;
    return clockwise ? -turn : turn;
  }

  function hyp(x, y) {
    var s = x * x + y * y;
    return s < 9007199254740992 ? Math.sqrt(s) : Math.hypot(x, y);
  }

  // The segment frame i executes from (px, py).
  function segment(t, i, px, py) {
    var b = i * NF, f = t.f;
    var x = f[b], y = f[b + 1], dx = f[b + 2], dy = f[b + 3], k = f[b + 5];
    var s = { frame: i, k: k, x0: px, y0: py, x1: px + dx, y1: py + dy, len: 0 };
    if (k === 10 || k === 20) {
      var moves = dx !== 0 || dy !== 0;
      s.kind = k === 10 ? (moves ? LINE : DOT) : (moves ? TRAVEL : RAISE);
      if (moves) s.len = hyp(dx, dy);
    } else {
      s.kind = ARC;
      s.cx = px - x;
      s.cy = py - y;
      s.r = hyp(x, y);
      s.a0 = Math.atan2(y, x);
      if (dx !== 0 || dy !== 0) {
        s.sweep = arcSweep(x, y, x + dx, y + dy, k === 13);
      } else {
        s.x1 = px;
        s.y1 = py;
        s.sweep = k === 13 ? -TWO_PI : TWO_PI;
      }
      s.len = s.r * Math.abs(s.sweep);
    }
    return s;
  }

  function Machine(t) {
    this.t = t;
    this.reset();
  }
  Machine.prototype.reset = function () {
    this.fi = 0;          // first frame of the step being run (a frame or a cycle pair)
    this.pass = 1;        // its pass
    this.j = 0;           // its next segment (0 or 1)
    this.executed = 0;
    this.px = 0;
    this.py = 0;
    this.down = false;
    this.line = 0; this.arc = 0; this.travel = 0;        // units, steps ended
    this.pline = 0; this.parc = 0; this.ptravel = 0;     // units, the step being run
    this.stepLens = [];
    this.last = null;     // the segment executed last,
    this.lastPass = 0;    // its pass of a cycle (0: not in a cycle)
    this.lastPasses = 0;  // and the cycle's passes
  };
  Machine.prototype.done = function () { return this.executed >= this.t.total; };
  // The step at fi: its segments a pass (1 or 2) and its passes.
  Machine.prototype.shape = function () {
    var cyc = this.t.f[this.fi * NF + 4];
    return cyc >= 2 && this.fi + 1 < this.t.n ? [2, cyc] : [1, 1];
  };
  // The next segment, not executed (null at the end).
  Machine.prototype.peek = function () {
    if (this.done()) return null;
    return segment(this.t, this.fi + this.j, this.px, this.py);
  };
  // Execute one segment (one executed frame); returns it, or null at the end.
  Machine.prototype.one = function () {
    if (this.done()) return null;
    var sh = this.shape(), nseg = sh[0], reps = sh[1];
    var s = segment(this.t, this.fi + this.j, this.px, this.py);
    this.px = s.x1;
    this.py = s.y1;
    this.down = !(s.kind === TRAVEL || s.kind === RAISE);
    if (s.kind === LINE) this.pline += s.len;
    else if (s.kind === ARC) this.parc += s.len;
    else if (s.kind === TRAVEL) this.ptravel += s.len;
    if (this.pass === 1) this.stepLens.push([s.kind, s.len]);
    this.lastPass = reps > 1 ? this.pass : 0;
    this.lastPasses = reps > 1 ? reps : 0;
    this.executed += 1;
    this.j += 1;
    if (this.j === nseg) {
      this.j = 0;
      this.pass += 1;
      if (this.pass > reps) {
        // the step ends: its lengths added as em703 sim adds them
        for (var m = 0; m < this.stepLens.length; m++) {
          var kind = this.stepLens[m][0], len = this.stepLens[m][1];
          if (kind === LINE) this.line = this.line + reps * len;
          else if (kind === TRAVEL) this.travel = this.travel + reps * len;
          else if (kind === ARC) this.arc = this.arc + reps * len;
        }
        this.stepLens = [];
        this.pline = 0; this.parc = 0; this.ptravel = 0;
        this.fi += nseg;
        this.pass = 1;
      }
    }
    this.last = s;
    return s;
  };
  Machine.prototype.state = function () {
    var l = this.line + this.pline, a = this.arc + this.parc, tr = this.travel + this.ptravel;
    var s = this.last;
    return {
      tape: this.t.key,
      executed: this.executed,
      total: this.t.total,
      frame: s ? s.frame + 1 : 0,
      frames: this.t.n,
      row: s ? this.t.first[s.frame] : 0,
      x_mm: this.px / 100,
      y_mm: this.py / 100,
      tool: this.down ? 'down' : 'up',
      k: s ? s.k : 0,
      pass: this.lastPass,
      passes: this.lastPasses,
      drawn_mm: (l + a) / 100,
      line_mm: l / 100,
      arc_mm: a / 100,
      travel_mm: tr / 100,
      minutes: l / 100 / LINE_SPEED + a / 100 / ARC_SPEED + tr / 100 / TRAVEL_SPEED,
      done: this.done()
    };
  };
  // Machine minutes a segment takes.
  function segMinutes(s) {
    if (s.kind === ARC) return s.len / 100 / ARC_SPEED;
    if (s.kind === LINE) return s.len / 100 / LINE_SPEED;
    if (s.kind === TRAVEL) return s.len / 100 / TRAVEL_SPEED;
    return 0;
  }

  // ------------------------------------------------------------------
  // The field: the drawing canvas keeps what was drawn; the carriage canvas
  // is drawn again at every tick. Segments are drawn in batches (one path a
  // kind a batch), never one element per segment.
  var drawing = $('drawing'), carriage = $('carriage');
  var dctx = drawing.getContext('2d'), cctx = carriage.getContext('2d');
  var view = { s: 1, ox: 0, oy: 0, tool: 50 };
  var batch = null;

  function setView(t) {
    var b = t.d.box, tool = t.d.tool;       // box in mm, tool in units
    var x0 = Math.min(0, b[0]) * 100 - tool, x1 = Math.max(0, b[1]) * 100 + tool;
    var y0 = Math.min(0, b[2]) * 100 - tool, y1 = Math.max(0, b[3]) * 100 + tool;
    var w = Math.max(x1 - x0, 100), h = Math.max(y1 - y0, 100);
    var px = drawing.width, margin = 16;
    view.s = Math.min((px - 2 * margin) / w, (px - 2 * margin) / h);
    view.ox = margin + ((px - 2 * margin) - w * view.s) / 2 - x0 * view.s;
    view.oy = px - margin - ((px - 2 * margin) - h * view.s) / 2 + y0 * view.s;
    view.tool = tool;
  }
  function sx(x) { return view.ox + x * view.s; }
  function sy(y) { return view.oy - y * view.s; }

  function clearDrawing() {
    dctx.setTransform(1, 0, 0, 1, 0, 0);
    dctx.clearRect(0, 0, drawing.width, drawing.height);
    // the start point: a cross
    dctx.strokeStyle = '#0a58ca';
    dctx.lineWidth = 1;
    dctx.beginPath();
    dctx.moveTo(sx(0) - 8, sy(0)); dctx.lineTo(sx(0) + 8, sy(0));
    dctx.moveTo(sx(0), sy(0) - 8); dctx.lineTo(sx(0), sy(0) + 8);
    dctx.stroke();
  }

  function beginBatch() {
    batch = { down: new Path2D(), travel: new Path2D(), dots: new Path2D(), n: 0 };
  }
  function addPath(p, s) {
    if (s.kind === ARC) {
      // canvas angles run clockwise on the screen (y down): negate them
      var a0 = -s.a0, a1 = -(s.a0 + s.sweep);
      p.moveTo(sx(s.x0), sy(s.y0));
      p.arc(sx(s.cx), sy(s.cy), s.r * view.s, a0, a1, s.sweep > 0);
    } else {
      p.moveTo(sx(s.x0), sy(s.y0));
      p.lineTo(sx(s.x1), sy(s.y1));
    }
  }
  function addToBatch(s) {
    if (s.kind === RAISE) return;
    if (s.kind === TRAVEL) addPath(batch.travel, s);
    else if (s.kind === DOT) {
      var r = Math.max(view.tool * view.s / 2, 0.75);
      batch.dots.moveTo(sx(s.x0) + r, sy(s.y0));
      batch.dots.arc(sx(s.x0), sy(s.y0), r, 0, TWO_PI);
    } else addPath(batch.down, s);
    batch.n += 1;
  }
  function flushBatch() {
    if (!batch || batch.n === 0) return;
    dctx.setTransform(1, 0, 0, 1, 0, 0);
    dctx.lineCap = 'round';
    dctx.lineJoin = 'round';
    dctx.strokeStyle = '#9a9a9a';
    dctx.lineWidth = 1;
    dctx.setLineDash([4, 3]);
    dctx.stroke(batch.travel);
    dctx.setLineDash([]);
    dctx.strokeStyle = '#1a1a1a';
    dctx.lineWidth = Math.max(view.tool * view.s, 1);
    dctx.stroke(batch.down);
    dctx.fillStyle = '#1a1a1a';
    dctx.fill(batch.dots);
    beginBatch();
  }

  // The carriage at (x, y) units, with the part of the segment under way.
  function drawCarriage(x, y, partial, frac) {
    cctx.setTransform(1, 0, 0, 1, 0, 0);
    cctx.clearRect(0, 0, carriage.width, carriage.height);
    if (partial && frac > 0 && partial.kind !== RAISE && partial.kind !== DOT) {
      cctx.lineCap = 'round';
      cctx.strokeStyle = partial.kind === TRAVEL ? '#9a9a9a' : '#1a1a1a';
      cctx.lineWidth = partial.kind === TRAVEL ? 1 : Math.max(view.tool * view.s, 1);
      cctx.beginPath();
      if (partial.kind === ARC) {
        cctx.arc(sx(partial.cx), sy(partial.cy), partial.r * view.s, -partial.a0,
                 -(partial.a0 + frac * partial.sweep), partial.sweep > 0);
      } else {
        cctx.moveTo(sx(partial.x0), sy(partial.y0));
        cctx.lineTo(sx(x), sy(y));
      }
      cctx.stroke();
    }
    var X = sx(x), Y = sy(y);
    cctx.strokeStyle = '#d0021b';
    cctx.lineWidth = 2;
    cctx.beginPath();
    cctx.arc(X, Y, 6, 0, TWO_PI);
    cctx.moveTo(X - 10, Y); cctx.lineTo(X + 10, Y);
    cctx.moveTo(X, Y - 10); cctx.lineTo(X, Y + 10);
    cctx.stroke();
  }

  // ------------------------------------------------------------------
  // Text: the frame as the report writes it, the tape strip, the state.
  var cyrillic = false;
  function frameText(t, i) {
    var b = i * NF, f = t.f, s = '';
    var D = cyrillic ? '\u0394' : 'D';
    if (f[b]) s += 'X' + f[b] + ' ';
    if (f[b + 1]) s += 'Y' + f[b + 1] + ' ';
    if (f[b + 2]) s += D + 'X' + f[b + 2] + ' ';
    if (f[b + 3]) s += D + 'Y' + f[b + 3] + ' ';
    if (f[b + 4]) s += (cyrillic ? '\u0426' : 'CYC') + f[b + 4] + ' ';
    var k = cyrillic ? '\u041a' : 'K';
    return s + k + f[b + 5] + ' ' + k + k;
  }

  function meaning(t, i, v) {
    if (v === 0 && i < t.d.gm[0]) return 'leader';
    if (v === 0 && i > t.d.gm[1]) return 'trailer';
    if (cyrillic && SERVICE_CYR[v]) return SERVICE_CYR[v];
    if (SERVICE[v]) return SERVICE[v];
    var digits = t.controlled ? DIGITS_K : DIGITS_8;
    var d = digits.indexOf(v);
    return d >= 0 ? 'digit ' + d : 'not an EM-703 code';
  }

  function pad(s, n) { s = String(s); while (s.length < n) s = ' ' + s; return s; }

  // One row as em703 view draws it: number, holes 5 4 3 . 2 1, octal, meaning.
  function rowLine(t, i) {
    var v = t.rows[i - 1], holes = '';
    for (var k = 5; k >= 1; k--) {
      holes += (v >> (k - 1)) & 1 ? 'o' : ' ';
      holes += ' ';
      if (k === 3) holes += '. ';
    }
    holes += '   ';
    var oct = v.toString(8);
    while (oct.length < 3) oct = '0' + oct;
    return pad(i, 5) + ' |' + holes + '| ' + oct + '   ' + meaning(t, i, v);
  }

  function esc(s) { return s.replace(/&/g, '&amp;').replace(/</g, '&lt;'); }

  var shownRow = -1, shownFrame = -2, shownCyr = null;
  function drawStrip(t, row, fr) {
    if (row === shownRow && fr === shownFrame && shownCyr === cyrillic) return;
    shownRow = row; shownFrame = fr; shownCyr = cyrillic;
    var lo = fr >= 0 ? t.first[fr] : 0, hi = fr >= 0 ? lastRow(t, fr) : -1;
    var half = (STRIP_ROWS - 1) / 2, out = ['   row  5 4 3   2 1   code  meaning',
                                           '       +---------------+'];
    for (var i = row - half; i <= row + half; i++) {
      var mark = i === row ? '<span class="mark">&#9654;</span>' : ' ';
      var line = i >= 1 && i <= t.rows.length ? esc(rowLine(t, i)) : '      |      .        |';
      if (i >= lo && i <= hi) line = '<span class="hl">' + line + '</span>';
      out.push(mark + line);
    }
    out.push('       +---------------+');
    $('strip').innerHTML = out.join('\n');
    $('frametext').textContent = fr >= 0 ? 'frame ' + (fr + 1) + ': ' + frameText(t, fr) : '';
  }

  function fix(v, n) {                  // as em703 prints: half away from zero
    var p = Math.pow(10, n), r = Math.round(Math.abs(v) * p);
    var s = (r / p).toFixed(n);
    return v < 0 && r !== 0 ? '-' + s : s;
  }

  function drawState(st) {
    var K = cyrillic ? '\u041a' : 'K';
    var rows = [
      ['tape', st.tape + ' (' + machine.t.d.label + '), ' + machine.t.d.file],
      ['X from the start point', fix(st.x_mm, 2) + ' mm'],
      ['Y from the start point', fix(st.y_mm, 2) + ' mm'],
      ['tool', st.tool],
      ['command', st.k ? K + st.k + ' (' + ({10: 'line / dot', 20: 'travel / raise',
                   11: 'arc counter-clockwise', 13: 'arc clockwise'})[st.k] + ')' : '-'],
      ['cycle', st.passes ? 'pass ' + st.pass + ' of ' + st.passes : '-'],
      ['frames executed', st.executed + ' of ' + st.total],
      ['tape frame', st.frame + ' of ' + st.frames + ', row ' + st.row],
      ['drawn', fix(st.drawn_mm, 2) + ' mm'],
      ['travel', fix(st.travel_mm, 2) + ' mm'],
      ['machine time', fix(st.minutes, 3) + ' min'],
      ['', st.done ? 'the tape has run to its end' : '']
    ];
    var html = '';
    for (var i = 0; i < rows.length; i++) {
      html += '<tr><td>' + esc(rows[i][0]) + '</td><td>' + esc(String(rows[i][1])) + '</td></tr>';
    }
    $('state').innerHTML = html;
  }

  // ------------------------------------------------------------------
  // Running: step (synchronous), seek, play at a speed.
  var machine = null, playing = false, speed = 1000, budget = 0, lastTime = 0;

  function show(partial, frac) {
    flushBatch();
    var st = machine.state();
    var x = machine.px, y = machine.py;
    if (partial && frac > 0 && partial.kind !== ARC) {
      x = partial.x0 + (partial.x1 - partial.x0) * frac;
      y = partial.y0 + (partial.y1 - partial.y0) * frac;
    } else if (partial && frac > 0) {
      var a = partial.a0 + frac * partial.sweep;
      x = partial.cx + partial.r * Math.cos(a);
      y = partial.cy + partial.r * Math.sin(a);
    }
    drawCarriage(x, y, partial, frac);
    var fr = machine.last ? machine.last.frame : -1;
    var row = fr >= 0 ? machine.t.first[fr] : machine.t.d.gm[0];
    drawStrip(machine.t, row, fr);
    drawState(st);
    $('goto').value = st.executed;
    $('play').textContent = playing ? 'pause' : 'play';
  }

  function step(n) {
    n = n === undefined ? 1 : Math.floor(Number(n));
    for (var i = 0; i < n; i++) {
      var s = machine.one();
      if (!s) break;
      addToBatch(s);
      if (batch.n >= 20000) flushBatch();
    }
    budget = 0;
    show(null, 0);
    return machine.state();
  }

  function seek(n) {
    n = Math.max(0, Math.min(Math.floor(Number(n)) || 0, machine.t.total));
    if (n < machine.executed) {
      machine.reset();
      clearDrawing();
      beginBatch();
    }
    return step(n - machine.executed);
  }

  function select(key) {
    if (job.tapes.indexOf(key) < 0) throw new Error('no tape ' + key + ' (tapes: ' +
                                                    job.tapes.join(', ') + ')');
    pause();
    var t = loadTape(key);
    machine = new Machine(t);
    setView(t);
    clearDrawing();
    beginBatch();
    shownRow = -1;
    $('tape').value = key;
    $('goto').max = t.total;
    budget = 0;
    show(null, 0);
    return machine.state();
  }

  function tick(now) {
    if (!playing) return;
    var dt = Math.min(now - lastTime, 250);
    lastTime = now;
    budget += dt / 60000 * speed;           // machine minutes
    var next = machine.peek(), started = now;
    while (next) {
      var m = segMinutes(next);
      if (m > budget) break;
      budget -= m;
      addToBatch(machine.one());
      next = machine.peek();
      if ((machine.executed & 1023) === 0 && performance.now() - started > 30) break;
    }
    if (!next) {
      playing = false;
      budget = 0;
      show(null, 0);
      return;
    }
    var m2 = segMinutes(next);
    show(next, m2 > 0 ? Math.min(budget / m2, 1) : 0);
    requestAnimationFrame(tick);
  }

  function play(x) {
    if (x !== undefined) setSpeed(x);
    if (playing || machine.done()) return;
    playing = true;
    lastTime = performance.now();
    requestAnimationFrame(tick);
  }
  function pause() {
    playing = false;
    budget = 0;
    if (machine) show(null, 0);
  }
  function setSpeed(x) {
    x = Number(x);
    if ([1, 10, 100, 1000].indexOf(x) < 0) throw new Error('speed is 1, 10, 100 or 1000');
    speed = x;
    $('speed').value = String(x);
  }

  // ------------------------------------------------------------------
  // The page: controls, and the interface for tests and exercises.
  $('title').textContent = 'EM-703 job ' + job.name;
  $('subtitle').textContent = (job.job ? job.job + '; ' : '') + 'code ' + job.code +
    ', scale ' + job.scale + ', start point at ' + job.start[0] + ', ' + job.start[1] +
    ' mm on the field';
  $('note').textContent = 'Each tape runs alone from the start point with the tool raised, ' +
    'as em703 sim runs it. A frame with CYC n runs with the next frame n times; every pass ' +
    'counts as executed frames. Speeds: 5.5 m/min on lines and travel, 1.5 m/min on arcs.';
  var labels = { small: 'small pads', large: 'large pads', cond: 'conductors' };
  job.tapes.forEach(function (key) {
    var o = document.createElement('option');
    o.value = key;
    o.textContent = labels[key] || key;
    $('tape').appendChild(o);
  });
  $('tape').addEventListener('change', function () { select($('tape').value); });
  $('play').addEventListener('click', function () { if (playing) pause(); else play(); });
  $('fwd').addEventListener('click', function () { pause(); step(1); });
  $('back').addEventListener('click', function () { pause(); seek(machine.executed - 1); });
  $('go').addEventListener('click', function () {
    var n = $('goto').value;            // read before pause() shows the state in the box
    pause();
    seek(n);
  });
  $('reset').addEventListener('click', function () { pause(); seek(0); });
  $('speed').addEventListener('change', function () { setSpeed($('speed').value); });
  $('cyr').addEventListener('change', function () {
    cyrillic = $('cyr').checked;
    show(null, 0);
  });
  $('strip').addEventListener('click', function (ev) {
    // a click on a row: run to the first execution of the frame it belongs to
    var lines = $('strip').textContent.split('\n');
    var h = $('strip').clientHeight / lines.length;
    var line = lines[Math.floor(ev.offsetY / h)] || '';
    var r = parseInt(line.slice(1, 6), 10), t = machine.t;
    if (!(r > 0)) return;
    for (var i = 0; i < t.n; i++) {
      if (t.first[i] <= r && r <= lastRow(t, i)) { pause(); seek(t.start[i] + 1); return; }
    }
  });

  window.em703 = {
    tapes: function () { return job.tapes.slice(); },
    select: select,
    step: step,
    seek: seek,
    state: function () { return machine.state(); },
    play: play,
    pause: pause,
    playing: function () { return playing; },
    frameText: function (i) { return frameText(machine.t, i - 1); },
    setCyrillic: function (on) { cyrillic = !!on; $('cyr').checked = cyrillic; show(null, 0); }
  };
  select(job.tapes[0]);
})();
