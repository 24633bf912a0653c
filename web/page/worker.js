// The page's worker: the C++ job (WebAssembly, createAcodrill above this
// script in the same Blob) run in slices of 100 ms. A worker busy in C++
// reads no message, so after each slice it posts the progress and yields
// (setTimeout), and a "stop" that came meanwhile ends the run with the best
// routes so far.
'use strict';
let M = null;
let stopAsked = false;
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

function answer(pointer) {
  return JSON.parse(M.UTF8ToString(pointer));
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
    if (stopAsked) return finish(id);
    const out = answer(M._aco_advance(0, 0.1));
    postMessage({ cmd: 'progress', id, progress: out.progress, routes: out.routes || null });
    if (out.done) return finish(id);
    setTimeout(() => slice(id), 0);
  } catch (e) {
    postMessage({ cmd: 'crashed', id, message: String(e && e.message ? e.message : e) });
  }
}

function finish(id) {
  postMessage({ cmd: 'finished', id, result: answer(M._aco_finish()) });
}

onmessage = async (e) => {
  const msg = e.data;
  if (msg.cmd === 'stop') {
    stopAsked = true;
    return;
  }
  await ready;
  try {
    if (msg.cmd === 'open') {
      postMessage({ cmd: 'opened', id: msg.id, result: open(msg.files, msg.settings) });
    } else if (msg.cmd === 'plan') {
      stopAsked = false;
      const opened = open(msg.files, msg.settings);
      postMessage({ cmd: 'opened', id: msg.id, result: opened, planning: !opened.error });
      if (!opened.error) slice(msg.id);
    }
  } catch (e) {
    postMessage({ cmd: 'crashed', id: msg.id, message: String(e && e.message ? e.message : e) });
  }
};
