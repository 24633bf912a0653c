// The page (issue 65): the form, the files, the pictures and the chart on
// the main thread; the job in a worker (worker.js, started from a Blob URL:
// a file:// page may not start one from a file). Every setting means what
// the `acodrill plan` option of that name means.
'use strict';
(() => {
  const $ = (id) => document.getElementById(id);

  // The settings: [key, label, kind, choices or placeholder, help, advanced].
  const SETTINGS = [
    ['machine', 'Machine', 'select', [['', 'default (vf2; router for GRBL and Marlin)'], ['vf2', 'vf2: HAAS VF-2 vertical mill'], ['router', 'router: desktop CNC router on GRBL'], ['pcb-drill', 'pcb-drill: PCB drilling machine'], ['pcb-proto', 'pcb-proto: PCB prototyping mill']],
      'Rapids, accelerations, tool changes and travel of the machine: they set the time estimate, the generated tools\u2019 speeds and the dialect.'],
    ['dialect', 'Dialect', 'select', [['', 'the machine\u2019s'], ['haas', 'HAAS'], ['fanuc', 'Fanuc'], ['linuxcnc', 'LinuxCNC'], ['grbl', 'GRBL, grblHAL, FluidNC'], ['marlin', 'Marlin']],
      'HAAS, Fanuc and LinuxCNC drill with canned cycles (G81/G83) and change tools with M6; GRBL and Marlin get every hole as G0/G1 moves and a pause naming each drill.'],
    ['units', 'Units', 'select', [['', 'mm; a G-code program its own'], ['mm', 'mm'], ['inch', 'inch']], 'Units of the program written. By default mm, and a G-code program input keeps its own units and style.'],
    ['origin', 'Origin', 'select', [['', 'lower left of the holes; a G-code program as it has them'], ['lower-left', 'lower left of the holes'], ['center', 'centre of the holes'], ['upper-left', 'upper left of the holes'], ['drawing', 'the drawing\u2019s own zero']],
      'Program zero (X0 Y0): where the machinist sets the work offset. A G-code program input keeps its own coordinates (its work offset was set for them): leave this at the first choice.'],
    ['material', 'Material', 'select', [['', 'steel; PCB for drill files'], ['steel', 'steel'], ['aluminium', 'aluminium'], ['pcb', 'PCB']], 'Feeds and speeds of the generated tools.'],
    ['thickness', 'Thickness', 'number', 'mm', 'Part thickness in mm (default 6.35, or 1.6 for PCB): how deep each hole is drilled.'],
    ['default_diameter', 'Default diameter', 'number', 'mm', 'Diameter in mm of the holes an input gives none (CSV rows without one, TSPLIB nodes).'],
    ['drills', 'Drills owned', 'text', 'e.g. 0.6,0.8,1.0,1.2', 'The drills you own, mm, comma-separated (DIA or DIA:-MINUS:+PLUS). Each hole goes to a drill that fits it. Empty: one drill per diameter.'],
    ['end_mill', 'End mill', 'number', 'mm', 'Diameter of an end mill for the holes no owned drill fits: each is milled by a helix to its size.'],
    ['probe_plate', 'Touch plate', 'number', 'mm', 'Thickness of a touch plate: after each tool change GRBL, Marlin and LinuxCNC programs probe Z on it.'],
    ['side', 'Side', 'select', [['front', 'front'], ['back', 'back (mirrored)']], 'Drill the board from its back: the holes mirrored about the vertical line through their centre.'],
    ['alignment_pins', 'Alignment pins', 'number', 'mm', 'Two pin holes of this diameter on the mirror line, drilled first, to register the board when it is turned over.'],
    ['dxf_units', 'DXF units', 'select', [['', 'as the DXF says ($INSUNITS; mm if it does not)'], ['mm', 'mm'], ['cm', 'cm'], ['m', 'm'], ['inch', 'inch'], ['feet', 'feet']],
      'The unit a DXF is drawn in, whatever its header says (Onshape and some Fusion exports say inch for a drawing made in mm).'],
    ['round_contours', 'Round contours', 'checkbox', '', 'Also drill round closed contours drawn without a CIRCLE (a circle of LINEs, ARCs, a SPLINE or a polyline) as holes of their size.'],
    ['processes', 'Processes', 'file', '.json', 'A process table (JSON, the one acodrill plan\u2019s processes option takes): which hole features of a drawing are spotted, drilled, reamed, countersunk, counterbored or tapped, and with what.'],
    ['panel', 'Panel', 'text', 'e.g. 3x2', 'Drill copies of the board as one job: COLSxROWS, with the pitch.'],
    ['pitch', 'Pitch', 'text', 'e.g. 60,40', 'DX,DY in mm between panel copies.'],
    ['time_limit', 'Time limit', 'number', 'seconds', 'The plan ends within about this many seconds after the files are read, outputs included: the colony stops in time to write them (empty: it stops by itself).'],
    ['iterations', 'Iterations', 'number', 'default', 'Colony iterations per tool (empty: until the time limit, or the size\u2019s default). With a fixed count and seed, the program is the one acodrill plan writes.'],
    ['seed', 'Seed', 'number', '1', 'Random seed: the same files, settings and seed give the same program.'],
    ['algorithm', 'Algorithm', 'select', [['focused', 'focused (default)'], ['acs', 'ACS'], ['mmas', 'MAX-MIN'], ['as', 'Ant System (the thesis)']], 'The colony\u2019s algorithm.', true],
    ['alpha', 'Alpha', 'number', '1', 'Pheromone weight.', true],
    ['beta', 'Beta', 'number', 'default', 'Distance weight (Ant System 4, the others 2).', true],
    ['ants', 'Ants', 'number', 'default', 'Ants per iteration (empty = the default).', true],
  ];
  const STORE = 'acodrill.settings.v1';
  const EXT = { haas: 'nc', fanuc: 'nc', linuxcnc: 'ngc', grbl: 'nc', marlin: 'gcode' };
  // 24 colours a tool, told apart (issue 84: with 10, T1 and T11 were both red); beyond, the table's swatch and number say which.
  const COLOURS = ['#1f77b4', '#d62728', '#2ca02c', '#9467bd', '#ff7f0e', '#17becf', '#8c564b', '#e377c2', '#7f7f7f', '#bcbd22',
                   '#393b79', '#ad494a', '#637939', '#7b4173', '#8c6d31', '#3182bd', '#e6550d', '#31a354', '#756bb1', '#636363',
                   '#843c39', '#6baed6', '#fd8d3c', '#74c476'];

  function buildForm() {
    for (const [key, label, kind, choices, help, advanced] of SETTINGS) {
      const box = document.createElement('div');
      box.className = 'setting';
      const id = 'set-' + key;
      const l = document.createElement('label');
      l.htmlFor = id;
      l.textContent = label;
      let input;
      if (kind === 'select') {
        input = document.createElement('select');
        for (const [value, text] of choices) {
          const o = document.createElement('option');
          o.value = value;
          o.textContent = text;
          input.appendChild(o);
        }
      } else if (kind === 'file') {
        // A file's text, read when chosen: the settings hold its name and text.
        input = document.createElement('input');
        input.type = 'file';
        input.accept = choices;
        input.addEventListener('change', async (e) => {
          e.stopPropagation();
          const f = input.files[0];
          fileSettings[key] = f ? { name: f.name, text: await f.text() } : null;
          if (files.length && !planning) preview();
        });
      } else if (kind === 'checkbox') {
        input = document.createElement('input');
        input.type = 'checkbox';
      } else {
        input = document.createElement('input');
        input.type = kind === 'number' ? 'number' : 'text';
        if (kind === 'number') input.step = 'any';
        input.placeholder = choices;
      }
      input.id = id;
      input.name = key;
      const h = document.createElement('p');
      h.className = 'help';
      h.id = id + '-help';
      h.textContent = help;
      input.setAttribute('aria-describedby', h.id);
      box.append(l, input, h);
      $(advanced ? 'settings-advanced' : 'settings-main').appendChild(box);
    }
  }

  const fileSettings = {};  // key -> {name, text} of a file setting chosen
  function settings() {
    const s = {};
    for (const [key, , kind] of SETTINGS) {
      if (kind === 'checkbox') s[key] = $('set-' + key).checked ? 'on' : '';
      else if (kind !== 'file') s[key] = $('set-' + key).value.trim();
      else if (fileSettings[key]) s[key] = fileSettings[key].text, s[key + '_name'] = fileSettings[key].name;
    }
    return s;
  }
  function saveSettings() {
    const kept = settings();
    for (const [key, , kind] of SETTINGS) if (kind === 'file') delete kept[key], delete kept[key + '_name'];
    try { localStorage.setItem(STORE, JSON.stringify(kept)); } catch (e) { /* storage off: settings last this visit */ }
  }
  function loadSettings() {
    let s = null;
    try { s = JSON.parse(localStorage.getItem(STORE) || 'null'); } catch (e) { s = null; }
    if (!s) return;
    for (const [key, , kind] of SETTINGS) {
      if (kind === 'checkbox') $('set-' + key).checked = s[key] === 'on';
      else if (kind !== 'file' && typeof s[key] === 'string') $('set-' + key).value = s[key];
    }
  }

  // --- the worker -------------------------------------------------------
  let worker = null, workerReady = false, nextId = 1, planId = 0;
  const pending = new Map();
  function startWorker() {
    const src = document.getElementById('worker-source').textContent;
    const url = URL.createObjectURL(new Blob([src], { type: 'text/javascript' }));
    worker = new Worker(url);
    workerReady = false;
    worker.onmessage = (e) => onWorker(e.data);
    worker.onerror = (e) => onWorker({ cmd: 'crashed', message: e.message || 'the worker stopped' });
  }
  function send(msg, transfer) {
    msg.id = nextId++;
    worker.postMessage(msg, transfer || []);
    return msg.id;
  }

  // --- state -----------------------------------------------------------
  let files = [];        // [{name, bytes: ArrayBuffer}]
  let view = null;       // what aco_open said: holes, tools, ...
  let routes = null;     // each tool's route as it stands
  let result = null;     // what aco_finish said
  let chart = null, chartData = null, chartTools = 0;
  let chartPoints = [];  // the points each tool's series has (non-null), for its markers
  let planned = null;    // the job the results are of: its name, files and machine, taken at Plan
  // The settings (JSON) the holes shown were read with, and each open's: a
  // plan of the same files and settings reads the same holes, which are not
  // drawn again (at 2*10^5 holes a 100-200 ms task of the page's thread).
  let viewKey = null, planShowsView = false;
  const openKeys = new Map();

  // acodrill's messages name its command-line options; here each is the
  // control of this page that means the same (issue 84), and an option the
  // page has no control for is named as the command line's.
  const CONTROL_OF_OPTION = {
    'probe-plate': 'Touch plate', drills: 'Drills owned', 'end-mill': 'End mill', machine: 'Machine', dialect: 'Dialect',
    units: 'Units', origin: 'Origin', material: 'Material', thickness: 'Thickness', 'default-diameter': 'Default diameter',
    side: 'Side', 'alignment-pins': 'Alignment pins', processes: 'Processes', panel: 'Panel', pitch: 'Pitch',
    'time-limit': 'Time limit', iterations: 'Iterations', seed: 'Seed', algorithm: 'Algorithm', alpha: 'Alpha',
    beta: 'Beta', ants: 'Ants', 'round-contours': 'Round contours', 'dxf-units': 'DXF units',
  };
  function inPageTerms(message) {
    return String(message).replace(/--([a-z][a-z0-9-]*)/g, (all, option) => CONTROL_OF_OPTION[option]
      ? '\u201c' + CONTROL_OF_OPTION[option] + '\u201d' : 'the command line\u2019s \u201c' + option + '\u201d option');
  }
  function showError(text) {
    const e = $('error');
    e.textContent = text ? 'acodrill: error: ' + inPageTerms(text) : '';
    e.hidden = !text;
  }
  function status(text) { $('status').textContent = text; }
  const DIALECT_NAMES = { haas: 'HAAS', fanuc: 'Fanuc', linuxcnc: 'LinuxCNC', grbl: 'GRBL', marlin: 'Marlin' };
  function dialectName(d) { return DIALECT_NAMES[d] || d || 'HAAS'; }
  function stem(name) { return name.replace(/^.*[\\/]/, '').replace(/\.[^.]*$/, '') || 'job'; }
  function jobName() { return files.map((f) => stem(f.name)).join('+') || 'job'; }

  function setFiles(list) {
    if (planning) return;  // (the controls are disabled; a drop is refused in its handler)
    files = list;
    // What is open, said in the box: the file control is cleared after each
    // choice (so that a file chosen again is read again) and names nothing.
    $('files-open').textContent = 'Open: ' + list.map((f) => f.name).join(', ');
    view = null;
    viewKey = null;
    $('plan').disabled = true;  // until the files read
    resetChart();
    $('progress-text').textContent = 'No run yet.';
    result = null;
    routes = null;
    enableSaves(false);
    showError('');
    $('results-body').innerHTML = '<p>The times, the tools and the route before and after appear here once a plan is made.</p>';
    preview();
  }
  function preview() {
    if (!files.length || !workerReady) return;
    status('Reading ' + files.map((f) => f.name).join(', ') + '\u2026');
    const copies = files.map((f) => ({ name: f.name, bytes: f.bytes.slice(0) }));
    const s = settings();
    openKeys.set(send({ cmd: 'open', files: copies, settings: s }, copies.map((c) => c.bytes)), viewKeyOf(s));
  }
  // The colony's settings change the routes, not the holes and tools read:
  // a change of one is checked, not read again (at 10^6 holes a reading
  // takes seconds, and Plan waited behind it; issue 84).
  const COLONY_SETTINGS = ['time_limit', 'iterations', 'seed', 'algorithm', 'alpha', 'beta', 'ants'];
  function viewKeyOf(s) {
    const rest = { ...s };
    for (const k of COLONY_SETTINGS) delete rest[k];
    return JSON.stringify(rest);
  }
  let checkedError = false;  // the error shown is a colony setting's, from a check
  function settingChanged(e) {
    saveSettings();
    const key = e && e.target && e.target.id ? e.target.id.replace(/^set-/, '') : '';
    if (COLONY_SETTINGS.includes(key)) {
      if (workerReady) send({ cmd: 'check', settings: settings() });
    } else if (files.length && !planning) {
      preview();
    }
  }

  function onWorker(msg) {
    if (msg.cmd === 'ready') {
      workerReady = true;
      $('plan').disabled = !planReady();
      document.body.dataset.ready = '1';
      status('Ready.');
      preview();
      return;
    }
    if (msg.cmd === 'checked') {
      // A colony setting: its refusal shown, or the refusal it caused gone.
      if (msg.error) {
        showError(msg.error);
        checkedError = true;
      } else if (checkedError) {
        showError('');
        checkedError = false;
      }
      return;
    }
    if (msg.cmd === 'crashed') {
      // The module cannot be trusted after a fault (memory, an abort): a new worker.
      showError(msg.message || 'the worker stopped');
      running(false);
      worker.terminate();
      startWorker();
      return;
    }
    if (msg.cmd === 'opened') {
      if (msg.result.error) {
        view = null;
        showError(msg.result.error);
        drawHoles();
        $('holes-info').textContent = '';
        status('');
        running(false);
        return;
      }
      showError('');
      const shown = msg.planning && planShowsView && routes === null;  // (no route of a last plan drawn over them)
      view = msg.result;
      viewKey = msg.planning ? viewKey : openKeys.get(msg.id) || null;
      openKeys.delete(msg.id);
      routes = null;
      if (!planning) $('plan').disabled = !planReady();
      if (!shown) {
        drawHoles();
        describeHoles();
      }
      status(msg.planning ? 'Planning\u2026' + (liveRoutes() ? '' : ' (the routes are drawn when the plan ends)') : 'Read ' + (view.holes.length / 3 - operationsOf(view)) + ' holes.');
      return;
    }
    if (msg.cmd === 'progress' && msg.id === planId) {
      for (const p of msg.progress) addProgress(p);
      if (msg.routes && liveRoutes()) {
        routes = msg.routes;
        scheduleDraw();
      }
      return;
    }
    if (msg.cmd === 'stopping' && msg.id === planId) {
      // Routing ended by Stop: the plan is over; its outputs follow.
      $('stop').disabled = true;
      document.body.dataset.routing = 'stopped';
      status('Stopped: writing the program from the best routes so far\u2026');
      return;
    }
    if (msg.cmd === 'finished' && msg.id === planId) {
      running(false);
      if (msg.result.error) {
        showError(msg.result.error);
        status('');
        return;
      }
      result = msg.result;
      view = result;
      routes = result.routes;
      drawHoles();
      describeHoles();
      showResults();
      enableSaves(true);
      if (result.no_time_for_colony) {
        status('Done. The time limit left no time for the colony after reading the files and before writing the ' +
               'outputs: each tool\u2019s holes are in nearest-neighbour order. A longer Time limit lets the colony shorten them.');
      } else {
        status((result.stopped ? 'Stopped: the best routes so far. ' : 'Done. ') + result.iterations + ' iterations in ' +
               result.solver_wall_s.toFixed(2) + ' s.');
      }
      // The progress line ends with what was planned, not a value from the middle of the run.
      $('progress-text').textContent = (result.stopped ? 'Stopped' : 'Done') + ': ' + result.iterations + ' iterations in ' +
        result.solver_wall_s.toFixed(2) + ' s; route ' + result.optimized.travel_mm.toFixed(1) + ' mm of travel.';
    }
  }

  // One job at a time (issue 84): while a plan runs, nothing that changes
  // the job can be changed; what is saved is the job the results show.
  let planning = false;
  // Plan only with holes open: files read without an error, no plan running.
  function planReady() { return workerReady && files.length > 0 && view !== null && !planning; }
  function jobControls() {
    return [$('files'), $('sample'), $('random'), $('random-holes'), $('reset'),
            ...SETTINGS.map(([key]) => $('set-' + key))];
  }
  function running(on) {
    const hadFocus = document.activeElement;
    planning = on;
    $('plan').disabled = on || !planReady();
    $('stop').disabled = !on;
    for (const el of jobControls()) el.disabled = on;
    $('drop').classList.toggle('locked', on);
    document.body.dataset.planning = on ? '1' : '';
    // Keep the keyboard where the user is: from Plan to Stop and back.
    if (on && (hadFocus === $('plan') || hadFocus === document.body)) $('stop').focus();
    if (!on && (hadFocus === $('stop') || hadFocus === document.body || !hadFocus)) $('plan').focus();
  }

  function plan() {
    if (!files.length) {
      showError('open a file, or take the sample or a random plate, first');
      return;
    }
    saveSettings();
    showError('');
    result = null;
    enableSaves(false);
    resetChart();
    running(true);
    document.body.dataset.routing = 'yes';
    const s = settings();
    planShowsView = view !== null && viewKey === viewKeyOf(s);
    s.program_name = jobName() + '.' + (EXT[s.dialect] || 'nc');
    const machineSelect = $('set-machine');
    // The machine as plan resolves an empty choice: the router for GRBL and Marlin, else the VF-2.
    const machine = s.machine || (s.dialect === 'grbl' || s.dialect === 'marlin' ? 'router' : 'vf2');
    planned = { name: jobName(), files: files.map((f) => f.name).join(', '),
                machine: [...machineSelect.options].find((o) => o.value === machine).text.replace(/: (.*)$/, ' ($1)') };
    const copies = files.map((f) => ({ name: f.name, bytes: f.bytes.slice(0) }));
    planId = send({ cmd: 'plan', files: copies, settings: s, liveRoutes: liveRoutes() }, copies.map((c) => c.bytes));
    $('progress-text').textContent = 'Reading the files\u2026';
  }

  // --- progress and the chart --------------------------------------------
  function resetChart() {
    chartTools = 0;
    chartData = [[]];
    chartPoints = [0];
    if (chart) { chart.destroy(); chart = null; }
    $('chart').textContent = '';
  }
  function addProgress(p) {
    $('progress-text').textContent = 'Tool ' + (p.tool + 1) + ' of ' + p.tools + ' (T' + p.tool_number + '), iteration ' +
      p.iteration + (p.iterations < 2147483647 ? ' of ' + p.iterations : '') + ', ' + p.elapsed_s.toFixed(1) +
      ' s, best route ' + p.best.toFixed(1) + ' mm';
    if (typeof uPlot === 'undefined') return;
    while (chartTools < p.tools) {
      chartData.push(chartData[0].map(() => null));
      chartPoints.push(0);
      chartTools++;
    }
    chartData[0].push(p.elapsed_s);
    chartPoints[p.tool + 1]++;
    for (let t = 1; t <= chartTools; t++) chartData[t].push(t - 1 === p.tool ? p.best : null);
    if (!chart) {
      const series = [{ label: 'seconds' }];
      for (let t = 0; t < chartTools; t++) {
        // Markers on a tool with few points: one routed within a slice is a
        // single point, which a line alone would not show. (uPlot's own rule
        // counts every tool's points together and hides it on a long run.)
        series.push({ label: 'tool ' + (t + 1), stroke: COLOURS[t % COLOURS.length], spanGaps: false,
                      points: { size: 5, show: (u, si) => chartPoints[si] <= 30 } });
      }
      const width = Math.max(260, Math.min(860, $('chart').clientWidth || 600));
      const narrow = window.matchMedia('(max-width: 900px)').matches;  // in the bar at the bottom of a phone's screen
      chart = new uPlot({ title: narrow ? 'Best route (mm) by time (s)' : 'Best route of each tool (mm) against time (s)', width, height: narrow ? 110 : 200, series, legend: { live: false, show: !narrow },
        axes: [{ label: 's' }, { label: 'mm' }], scales: { x: { time: false } } }, chartData, $('chart'));
    } else {
      chart.setData(chartData);
    }
  }

  // --- drawing -------------------------------------------------------------
  // The routes are drawn as they improve up to this many holes; above it,
  // once the plan ends: drawing 20 000 holes' routes took the page's thread
  // 150-250 ms a time (issue 84: no task over 100 ms while it plans).
  const LIVE_ROUTES_UP_TO = 10000;
  function liveRoutes() { return view !== null && view.holes.length / 3 <= LIVE_ROUTES_UP_TO; }
  let drawQueued = false;
  function scheduleDraw() {
    if (drawQueued) return;
    drawQueued = true;
    requestAnimationFrame(() => { drawQueued = false; drawHoles(); });
  }
  // The holes' extent, radii included, so that a large hole at the edge is
  // drawn whole: into `box` ({x0, y0, x1, y1}), yielding when `due()` says.
  function* extent(xyd, box, due) {
    let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    for (let i = 0; i < xyd.length; i += 3) {
      const r = 0.5 * (xyd[i + 2] || 0);
      x0 = Math.min(x0, xyd[i] - r); x1 = Math.max(x1, xyd[i] + r);
      y0 = Math.min(y0, xyd[i + 1] - r); y1 = Math.max(y1, xyd[i + 1] + r);
      if (i % 3072 === 0 && due()) yield;
    }
    Object.assign(box, { x0, y0, x1, y1 });
  }
  function fit(canvas, xyd) {
    const box = {};
    for (const _ of extent(xyd, box, () => false)) { /* never yields */ }
    return framed(canvas, box);
  }
  function framed(canvas, { x0, y0, x1, y1 }) {
    const pad = 12, w = canvas.width - 2 * pad, h = canvas.height - 2 * pad;
    const k = Math.min(w / Math.max(1e-9, x1 - x0), h / Math.max(1e-9, y1 - y0));
    // Centred in the canvas, Y up as on the machine.
    const ox = pad + (w - (x1 - x0) * k) / 2, oy = pad + (h - (y1 - y0) * k) / 2;
    return { k, X: (x) => ox + (x - x0) * k, Y: (y) => canvas.height - oy - (y - y0) * k };
  }
  // A drawing of many holes runs in pieces of about 40 ms of the page's
  // thread (at 10^6 holes the plate took it 0.9 s in one task and the input
  // order's picture 2.8 s; issue 84), its extent and each hole's tool too
  // (65 ms there), and begins in a task of its own; a newer drawing of a
  // canvas ends an older one.
  const drawings = new WeakMap();
  function draw(canvas, v, orders) {
    const g = canvas.getContext('2d');
    const token = {};
    drawings.set(canvas, token);
    g.clearRect(0, 0, canvas.width, canvas.height);
    if (!v || !v.holes.length) return;
    const xyd = v.holes, n = xyd.length / 3;
    let f = null;  // the fit, once the extent is known
    const toolOf = new Int32Array(n);
    if (n <= LIVE_ROUTES_UP_TO) {
      f = fit(canvas, xyd);
      v.tools.forEach((t, k) => { for (const h of t.holes) toolOf[h] = k; });
    }
    // Holes drilled are discs; a hole feature's other operations (issue 82)
    // are drawn over them as a drawing shows them: a counterbore or a reamer
    // a ring, a countersink a dashed ring, a tap three quarters of a ring, a
    // spot a small cross.
    const opOf = (i) => (v.tools.length && v.tools[toolOf[i]].operation) || 'drill';
    // A tool's holes in one colour, set once: a colour set a hole cost most
    // of a 100 000-hole drawing, a main-thread task over 100 ms (issue 84).
    const groups = v.tools.length ? v.tools.map((t, k) => ({ colour: COLOURS[k % COLOURS.length], holes: t.holes }))
                                  : [{ colour: '#333', holes: Array.from({ length: n }, (_, i) => i) }];
    const operations = () => {
      g.lineWidth = 1.5;
      for (let i = 0; i < n; i++) {
        const op = opOf(i);
        if (op === 'drill') continue;
        const x = f.X(xyd[3 * i]), y = f.Y(xyd[3 * i + 1]), r = Math.max(2, 0.5 * xyd[3 * i + 2] * f.k);
        g.strokeStyle = COLOURS[toolOf[i] % COLOURS.length];
        g.setLineDash(op === 'countersink' ? [3, 2] : []);
        g.beginPath();
        if (op === 'spot') { g.moveTo(x - 3, y); g.lineTo(x + 3, y); g.moveTo(x, y - 3); g.lineTo(x, y + 3); }
        else if (op === 'tap') g.arc(x, y, r, 0, 1.5 * Math.PI);
        else g.arc(x, y, r, 0, 2 * Math.PI);
        g.stroke();
      }
      g.setLineDash([]);
    };
    if (n <= LIVE_ROUTES_UP_TO) {
      if (orders) {
        g.lineWidth = 1;
        g.globalAlpha = 0.6;
        orders.forEach((order, k) => {
          if (!order.length) return;
          g.strokeStyle = COLOURS[k % COLOURS.length];
          g.beginPath();
          g.moveTo(f.X(xyd[3 * order[0]]), f.Y(xyd[3 * order[0] + 1]));
          for (let i = 1; i < order.length; i++) g.lineTo(f.X(xyd[3 * order[i]]), f.Y(xyd[3 * order[i] + 1]));
          g.stroke();
        });
        g.globalAlpha = 1;
      }
      for (const { colour, holes } of groups) {
        const path = new Path2D();  // one fill a tool
        for (const i of holes) {
          if (opOf(i) !== 'drill') continue;
          const r = Math.max(1, 0.5 * xyd[3 * i + 2] * f.k), x = f.X(xyd[3 * i]), y = f.Y(xyd[3 * i + 1]);
          if (r < 2) path.rect(x - r, y - r, 2 * r, 2 * r);
          else { path.moveTo(x + r, y); path.arc(x, y, r, 0, 2 * Math.PI); }
        }
        g.fillStyle = colour;
        g.fill(path);
      }
      operations();
      return;
    }
    // Many holes: routes and holes set pixel by pixel into a layer put once.
    // The canvas's own fill of 200 000 squares took the page's thread over
    // 500 ms to render, its stroke of 100 000 legs 300 ms, and three
    // drawings of 20 000 holes with their routes 360 ms.
    const layer = document.createElement('canvas');
    layer.width = canvas.width;
    layer.height = canvas.height;
    const image = layer.getContext('2d').createImageData(layer.width, layer.height);
    const px = new Uint32Array(image.data.buffer);
    const w = canvas.width, h = canvas.height;
    // A colour as the layer's pixel: little-endian ABGR.
    const pixel = (colour, alpha) => {
      const c = parseInt(colour.slice(1), 16);
      return ((alpha << 24) | (c & 0xff) << 16 | (c & 0xff00) | (c >> 16)) >>> 0;
    };
    // A piece ends at the first look at the clock after 40 ms (every 256
    // legs or holes, 1024 holes of the extent): counted in legs alone, a
    // piece of a random plate's input order took 80 ms.
    let pieceEnd = 0;
    const due = () => performance.now() >= pieceEnd;
    function* paint() {
      const box = {};
      yield* extent(xyd, box, due);
      f = framed(canvas, box);
      for (const [k, t] of v.tools.entries()) {
        for (let j = 0; j < t.holes.length; j++) {
          toolOf[t.holes[j]] = k;
          if ((j & 255) === 0 && due()) yield;
        }
      }
      for (const [k, order] of (orders || []).entries()) {
        if (!order.length) continue;
        const c = pixel(COLOURS[k % COLOURS.length], 153);  // 0.6 opaque, as the strokes of few holes
        // Bresenham's lines, in whole pixels: a random plate's input order
        // at 10^6 holes is 10^8 pixels of legs.
        let x0 = Math.round(f.X(xyd[3 * order[0]])), y0 = Math.round(f.Y(xyd[3 * order[0] + 1]));
        for (let i = 1; i < order.length; i++) {
          const x1 = Math.round(f.X(xyd[3 * order[i]])), y1 = Math.round(f.Y(xyd[3 * order[i] + 1]));
          const dx = Math.abs(x1 - x0), dy = -Math.abs(y1 - y0), sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
          let x = x0, y = y0, err = dx + dy;
          for (;;) {
            if (x >= 0 && x < w && y >= 0 && y < h) px[y * w + x] = c;
            if (x === x1 && y === y1) break;
            const e2 = 2 * err;
            if (e2 >= dy) { err += dy; x += sx; }
            if (e2 <= dx) { err += dx; y += sy; }
          }
          x0 = x1;
          y0 = y1;
          if ((i & 255) === 0 && due()) yield;
        }
      }
      // Squares over the routes, opaque.
      for (const { colour, holes } of groups) {
        const abgr = pixel(colour, 255);
        for (let j = 0; j < holes.length; j++) {
          const i = holes[j];
          if (opOf(i) !== 'drill') continue;
          const r = Math.max(1, Math.round(0.5 * xyd[3 * i + 2] * f.k));
          const x = Math.round(f.X(xyd[3 * i])), y = Math.round(f.Y(xyd[3 * i + 1]));
          for (let yy = Math.max(0, y - r); yy < Math.min(h, y + r); yy++) {
            for (let xx = Math.max(0, x - r); xx < Math.min(w, x + r); xx++) px[yy * w + xx] = abgr;
          }
          if ((j & 255) === 0 && due()) yield;
        }
      }
    }
    const steps = paint();
    const run = () => {
      if (drawings.get(canvas) !== token) return;
      pieceEnd = performance.now() + 40;
      if (!steps.next().done) {
        setTimeout(run, 0);
        return;
      }
      layer.getContext('2d').putImageData(image, 0, 0);
      g.drawImage(layer, 0, 0);
      operations();
    };
    setTimeout(run, 0);
  }
  function drawHoles() { draw($('holes-canvas'), view, routes); }

  function text(tag, content) { const e = document.createElement(tag); e.textContent = content; return e; }
  function table(head, rows, caption) {
    const t = document.createElement('table');
    if (caption) t.appendChild(text('caption', caption));
    const tr = document.createElement('tr');
    for (const h of head) { const th = text('th', h); th.scope = 'col'; tr.appendChild(th); }
    t.appendChild(tr);
    for (const r of rows) {
      const row = document.createElement('tr');
      r.forEach((c, i) => row.appendChild(text(i ? 'td' : 'th', c)));
      t.appendChild(row);
    }
    return t;
  }
  // A hole feature's operations other than its drill (taps, counterbores, ...): holes of the view that are no holes to a user.
  function operationsOf(v) { return v.tools.reduce((n, t) => n + ((t.operation || 'drill') !== 'drill' ? t.holes.length : 0), 0); }
  function describeHoles() {
    const box = $('holes-info');
    box.textContent = '';
    if (!view) return;
    const e = view.extent;
    const operations = operationsOf(view);
    box.appendChild(text('p', (view.holes.length / 3 - operations) + ' holes' + (operations ? ' and ' + operations + ' operations at them' : '') +
      ', ' + view.tools.length + ' tool(s); holes X ' + e[0].toFixed(3) +
      '..' + e[2].toFixed(3) + ', Y ' + e[1].toFixed(3) + '..' + e[3].toFixed(3) + ' mm (program coordinates)'));
    const tools = table(['Tool', 'Diameter mm', 'Holes'], view.tools.map((t) => ['T' + t.number + ' ' + (t.name || ''),
      t.diameter_mm ? t.diameter_mm.toFixed(3) + (t.end_mill ? ' end mill' : '') : 'not said', String(t.holes.length)]), 'Tools (colours as drawn)');
    tools.querySelectorAll('tr').forEach((tr, k) => {
      if (k === 0) return;
      const swatch = document.createElement('span');
      swatch.className = 'swatch';
      swatch.style.background = COLOURS[(k - 1) % COLOURS.length];
      swatch.setAttribute('aria-hidden', 'true');
      tr.firstChild.prepend(swatch);
    });
    box.appendChild(tools);
    const ops = new Set(view.tools.map((t) => t.operation || 'drill'));
    if (ops.size > 1 || !ops.has('drill')) {
      const legend = {
        drill: 'disc: drilled', spot: 'cross: spotted', ream: 'ring: reamed', countersink: 'dashed ring: countersunk',
        counterbore: 'ring: counterbored', tap: 'three-quarter ring: tapped (as a drawing shows a thread)',
      };
      const p = text('p', 'Legend: ' + ['drill', 'spot', 'ream', 'countersink', 'counterbore', 'tap'].filter((k) => ops.has(k)).map((k) => legend[k]).join('; ') + '.');
      p.id = 'holes-legend';
      box.appendChild(p);
    }
    const notes = [];
    for (const i of view.inputs) {
      // As the command line's summary says it (issue 84): duplicates removed, slots drilled or milled.
      notes.push(i.file + ': ' + i.holes + ' holes from ' + i.format +
                 (i.duplicates_removed ? ', ' + i.duplicates_removed + ' duplicates removed' : '') +
                 (i.slots_drilled ? ', ' + i.slots_drilled + ' slot(s) drilled as ' + i.slot_holes + ' holes' : '') +
                 (i.slots_milled ? ', ' + i.slots_milled + ' slot(s) milled along their length' : '') +
                 (i.description ? '; ' + i.description : '') + (i.features ? '; hole features: ' + i.features : ''));
      for (const a of i.assumptions) notes.push(i.file + ': assumed ' + a);
      for (const w of i.warnings) notes.push(i.file + (w.line ? ':' + w.line : '') + ': warning: ' + w.what);
      for (const s of i.not_drilled) notes.push(i.file + (s.line ? ':' + s.line : '') + ': not made: ' + s.what);
    }
    for (const d of view.drill_map || []) notes.push(d.toLowerCase());
    const ul = document.createElement('ul');
    for (const n of notes.slice(0, 50)) ul.appendChild(text('li', inPageTerms(n)));
    if (notes.length > 50) ul.appendChild(text('li', (notes.length - 50) + ' more (see the report)'));
    box.appendChild(ul);
  }
  function showResults() {
    const body = $('results-body');
    body.textContent = '';
    const heading = text('h3', 'Results: ' + planned.files + ' on ' + planned.machine + ', ' +
                                  (result.kept_style ? 'in the input program\u2019s own style' : dialectName(result.dialect)));
    heading.id = 'results-heading';
    body.appendChild(heading);
    const min = (s) => (s / 60).toFixed(2);
    const row = (label, st) => [label, st.travel_mm.toFixed(1), min(st.moves_s), min(st.drilling_s), min(st.tool_changes_s), min(st.pauses_s), min(st.time_s)];
    // In a box of its own that scrolls sideways on a narrow screen, never widening the page.
    const times = document.createElement('div');
    times.className = 'scroll';
    times.appendChild(table(['Order', 'Travel mm', 'Moves min', 'Drilling min', 'Tool changes min', 'Pauses min', 'Total min'],
      [row(result.program_input ? 'input program' : 'input order', result.input_order), row('nearest neighbour', result.nearest_neighbor),
       row('optimized', result.optimized)], 'Where the time goes'));
    body.appendChild(times);
    const saved = result.input_order.time_s > 0 ? (100 * (result.input_order.time_s - result.optimized.time_s) / result.input_order.time_s) : 0;
    body.appendChild(text('p', 'Saved against the input order: ' + (result.input_order.travel_mm - result.optimized.travel_mm).toFixed(1) +
      ' mm of travel, ' + saved.toFixed(1) + ' % of the time.'));
    const pics = document.createElement('div');
    pics.className = 'pictures';
    for (const [label, orders] of [['Input order', result.input_routes], ['Optimized', result.routes]]) {
      const fig = document.createElement('figure');
      const c = document.createElement('canvas');
      c.width = 420; c.height = 280;
      c.setAttribute('role', 'img');
      c.setAttribute('aria-label', 'The route in ' + label.toLowerCase());
      fig.append(c, text('figcaption', label));
      pics.appendChild(fig);
      setTimeout(() => draw(c, result, orders), 0);  // each picture a task of its own
    }
    body.appendChild(pics);
  }

  // --- saving --------------------------------------------------------------
  function enableSaves(on) {
    for (const id of ['save-program', 'save-report', 'save-setup', 'save-picture', 'save-excellon']) $(id).disabled = !on;
  }
  function download(name, content, type) {
    const a = document.createElement('a');
    a.href = URL.createObjectURL(new Blob([content], { type }));
    a.download = name;
    document.body.appendChild(a);
    a.click();
    setTimeout(() => { URL.revokeObjectURL(a.href); a.remove(); }, 1000);
  }

  // --- plates of our own ----------------------------------------------------
  function sampleFile() {
    const text = JSON.parse(document.getElementById('sample-plate').textContent);
    return { name: 'plate70.dxf', bytes: new TextEncoder().encode(text).buffer };
  }
  function randomFile(n) {
    // A plate of 300 x 200 mm with three diameters, the same for the same N.
    let seed = (12345 + n) >>> 0;
    const rnd = () => {  // mulberry32: 32-bit integer steps, exact in JavaScript
      seed = (seed + 0x6d2b79f5) >>> 0;
      let t = seed;
      t = Math.imul(t ^ (t >>> 15), t | 1);
      t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
      return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
    };
    const d = [3.0, 5.0, 6.35];
    let csv = 'x,y,diameter\n';
    for (let i = 0; i < n; i++) csv += (rnd() * 300).toFixed(3) + ',' + (rnd() * 200).toFixed(3) + ',' + d[Math.floor(rnd() * 3)] + '\n';
    return { name: 'random-' + n + '.csv', bytes: new TextEncoder().encode(csv).buffer };
  }

  // --- wiring ---------------------------------------------------------------
  buildForm();
  loadSettings();
  $('settings').addEventListener('change', settingChanged);
  $('reset').addEventListener('click', () => {
    if (planning) return;
    try { localStorage.removeItem(STORE); } catch (e) { /* nothing kept */ }
    for (const [key] of SETTINGS) {
      const el = $('set-' + key);
      if (el.type === 'checkbox') el.checked = false;
      else el.value = el.tagName === 'SELECT' ? el.options[0].value : '';
      fileSettings[key] = null;
    }
    preview();
  });
  $('files').addEventListener('change', async (e) => {
    const list = [];
    for (const f of e.target.files) list.push({ name: f.name, bytes: await f.arrayBuffer() });
    // Cleared, so that choosing the same file again (changed on disk) reads it again.
    e.target.value = '';
    if (list.length) setFiles(list);
  });
  document.addEventListener('dragover', (e) => e.preventDefault());
  document.addEventListener('drop', async (e) => {
    e.preventDefault();
    if (planning) {
      status('A plan is running: Stop it before opening other files.');
      return;
    }
    const list = [];
    for (const f of e.dataTransfer.files) list.push({ name: f.name, bytes: await f.arrayBuffer() });
    if (list.length) setFiles(list);
  });
  $('sample').addEventListener('click', () => setFiles([sampleFile()]));
  $('random').addEventListener('click', () => {
    const asked = parseInt($('random-holes').value, 10);
    if (!(asked >= 2 && asked <= 200000)) {
      showError('Random holes: from 2 to 200 000 (got ' + ($('random-holes').value || 'nothing') + ')');
      return;
    }
    setFiles([randomFile(asked)]);
  });
  $('plan').addEventListener('click', plan);
  $('stop').addEventListener('click', () => { worker.postMessage({ cmd: 'stop' }); status('Stopping\u2026'); });
  // What is saved is the job the results show, named as it was at Plan.
  const dialect = () => result.dialect || 'haas';
  $('save-program').addEventListener('click', () => download(planned.name + '.' + (EXT[dialect()] || 'nc'), result.files.program, 'text/plain'));
  $('save-report').addEventListener('click', () => download(planned.name + '.json', result.files.report, 'application/json'));
  $('save-setup').addEventListener('click', () => download(planned.name + '-setup.html', result.files.setup_sheet, 'text/html'));
  $('save-picture').addEventListener('click', () => download(planned.name + '-route.svg', result.files.route_svg, 'image/svg+xml'));
  $('save-excellon').addEventListener('click', () => download(planned.name + '-optimized.drl', result.files.excellon, 'text/plain'));
  startWorker();
})();
