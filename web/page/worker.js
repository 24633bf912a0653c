// The page's worker: the C++ job (WebAssembly, createAcodrill above this
// script in the same Blob) run in slices of 100 ms. A worker busy in C++
// reads no message, so after each slice it posts the progress and yields
// (setTimeout), and a "stop" that came meanwhile ends the run with the best
// routes so far.
'use strict';
let M = null;
let stopAsked = false;
let routesSent = 0;  // when routes were last sent (ms)
let liveRoutes = true;  // the page draws the routes while it plans (small jobs)
const ready = createAcodrill().then((m) => {
  M = m;
  postMessage({ cmd: 'ready' });
}, (e) => postMessage({ cmd: 'crashed', message: String(e) }));

function cString(s) {
  const n = M.lengthBytesUTF8(s) + 1;
  const p = M._malloc(n);
  M.stringToUTF8(s, p, n);
  return p;
}

// An answer of the job: its JSON, with the large parts the JSON only points
// at ({"$f64": [address, count]}, "$i32", "$text": wasm_api.cpp) copied out of
// the module's memory now, before the next call frees them. A text stays its
// UTF-8 bytes, which are what a Blob saves: decoded to a string, the outputs
// of 10^6 holes (an 80 MB picture among them) cost this thread seconds and
// the page's a task of 0.3 s to receive (issue 84).
function answer(pointer) {
  const unpack = (v) => {
    if (Array.isArray(v)) return v.map(unpack);
    if (v === null || typeof v !== 'object') return v;
    if (v.$f64) return M.HEAPF64.slice(v.$f64[0] / 8, v.$f64[0] / 8 + v.$f64[1]);
    if (v.$i32) return M.HEAP32.slice(v.$i32[0] / 4, v.$i32[0] / 4 + v.$i32[1]);
    if (v.$text) return M.HEAPU8.slice(v.$text[0], v.$text[0] + v.$text[1]);
    for (const k of Object.keys(v)) v[k] = unpack(v[k]);
    return v;
  };
  return unpack(JSON.parse(M.UTF8ToString(pointer)));
}

// The large lists of an answer (typed arrays, as answer() copies them out)
// handed to the page with their buffers rather than copied number by number:
// a plain array of 3 x 10^5 numbers took the page's thread a task of over
// 100 ms to receive (issue 84).
function packed(out) {
  const transfer = [];
  const typed = (list) => {
    transfer.push(list.buffer);
    return list;
  };
  if (out.holes) out.holes = typed(out.holes);
  for (const key of Object.keys(out.files || {})) {
    if (ArrayBuffer.isView(out.files[key])) out.files[key] = typed(out.files[key]);
  }
  for (const t of out.tools || []) t.holes = typed(t.holes);
  for (const key of ['routes', 'input_routes']) {
    if (Array.isArray(out[key])) out[key] = out[key].map(typed);
  }
  return { out, transfer };
}

function open(files, settings) {
  for (const f of files) {
    const bytes = new Uint8Array(f.bytes);
    const data = M._malloc(Math.max(1, bytes.length));
    M.writeArrayToMemory(bytes, data);
    const name = cString(f.name);
    M._aco_add_file(name, data, bytes.length);
    M._free(name);
    M._free(data);
  }
  const s = cString(JSON.stringify(settings));
  const out = answer(M._aco_open(s));
  M._free(s);
  return out;
}

function slice(id) {
  try {
    if (stopAsked) {
      // The routing ends here, with the best routes so far: said before the
      // outputs are written (seconds on 10^5 holes), so the page answers at once.
      postMessage({ cmd: 'stopping', id });
      return setTimeout(() => finish(id), 0);
    }
    const out = answer(M._aco_advance(0, 0.1, liveRoutes ? 1 : 0));
    // Routes (10^5 numbers on a large job, copied to the page and drawn
    // there) at most twice a second: each costs the page's thread a task.
    const now = Date.now();
    const routes = out.routes && liveRoutes && now - routesSent >= 500 ? packed({ routes: out.routes }) : null;
    if (routes) routesSent = now;
    postMessage({ cmd: 'progress', id, progress: out.progress, routes: routes ? routes.out.routes : null }, routes ? routes.transfer : []);
    if (out.done) return finish(id);
    setTimeout(() => slice(id), 0);
  } catch (e) {
    postMessage({ cmd: 'crashed', id, message: String(e && e.message ? e.message : e) });
  }
}

function finish(id) {
  const { out, transfer } = packed(answer(M._aco_finish()));
  postMessage({ cmd: 'finished', id, result: out }, transfer);
}

onmessage = async (e) => {
  const msg = e.data;
  if (msg.cmd === 'stop') {
    stopAsked = true;
    return;
  }
  await ready;
  try {
    if (msg.cmd === 'check') {
      const settings = cString(JSON.stringify(msg.settings));
      const out = answer(M._aco_check(settings));
      M._free(settings);
      postMessage({ cmd: 'checked', error: out.error || '' });
    } else if (msg.cmd === 'open') {
      const { out, transfer } = packed(open(msg.files, msg.settings));
      postMessage({ cmd: 'opened', id: msg.id, result: out }, transfer);
    } else if (msg.cmd === 'plan') {
      stopAsked = false;
      liveRoutes = msg.liveRoutes !== false;
      const opened = open(msg.files, msg.settings);
      const { out, transfer } = packed(opened);
      postMessage({ cmd: 'opened', id: msg.id, result: out, planning: !opened.error }, transfer);
      if (!opened.error) slice(msg.id);
    }
  } catch (e) {
    postMessage({ cmd: 'crashed', id: msg.id, message: String(e && e.message ? e.message : e) });
  }
};
