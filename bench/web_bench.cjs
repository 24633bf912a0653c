// The page against the native program (issue 65), not a test: colony
// iterations per second in the page (WebAssembly, one thread) and in
// `acodrill plan --threads 1`, same instance, seed and time limit; and the
// time from opening the page to its being ready; Stop's latency and the time
// limit's overrun by size (ACO_STOP_SIZES, default 3038,20000,100000,1000000).
// Run by `scripts/web --bench`.
//   node web_bench.cjs PAGE.html ACODRILL TSPLIB_DIR [SECONDS]
'use strict';
const { chromium } = require('playwright-core');
const { execFileSync } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');

const [page_html, acodrill, tsplib, seconds = '20'] = process.argv.slice(2);
const url = 'file://' + path.resolve(page_html);
const median = (v) => { const s = [...v].sort((a, b) => a - b); const m = s.length >> 1; return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2; };

(async () => {
  const work = fs.mkdtempSync(path.join(os.tmpdir(), 'acodrill-web-bench-'));
  const browser = await chromium.launch({ executablePath: '/usr/lib/chromium/chromium', args: ['--no-sandbox', '--disable-dev-shm-usage'] });
  const page = await browser.newPage();
  const ready = [];
  for (let k = 0; k < 6; k++) {
    const t0 = Date.now();
    await page.goto(url);
    await page.waitForSelector('body[data-ready="1"]', { timeout: 30000 });
    ready.push(Date.now() - t0);
  }
  console.log('page ready after opening (ms, 6 loads, the first in a fresh browser): ' + ready.join(' ') +
              '; median ' + median(ready) + ' ms');
  console.log('instance,holes,seconds,native_iterations,native_s,page_iterations,page_s,ratio');
  // ACO_BENCH_ITERATIONS=0: the Stop and time-limit table alone (pcb3038's holes are still written for it).
  for (const name of ['pcb3038', 'd15112']) {
    const iterationsToo = process.env.ACO_BENCH_ITERATIONS !== '0';
    // The instance as a plate the default machine travels (700 x 380 mm), one 1 mm drill:
    // the same holes, scaled, for both; an iteration's work does not depend on the scale.
    const text = fs.readFileSync(path.join(tsplib, name + '.tsp'), 'utf8');
    const nodes = text.split('NODE_COORD_SECTION')[1].split(/\r?\n/).map((l) => l.trim().split(/\s+/))
      .filter((f) => f.length >= 3 && !isNaN(Number(f[1]))).map((f) => [Number(f[1]), Number(f[2])]);
    const xs = nodes.map((p) => p[0]), ys = nodes.map((p) => p[1]);
    const x0 = Math.min(...xs), y0 = Math.min(...ys);
    const k = Math.min(700 / (Math.max(...xs) - x0), 380 / (Math.max(...ys) - y0));
    const tsp = path.join(work, name + '.csv');
    fs.writeFileSync(tsp, 'x,y,diameter\n' + nodes.map((p) => ((p[0] - x0) * k).toFixed(4) + ',' + ((p[1] - y0) * k).toFixed(4) + ',1').join('\n') + '\n');
    if (!iterationsToo) continue;
    const report = path.join(work, name + '.json');
    execFileSync(acodrill, ['plan', tsp, '-o', path.join(work, name + '.nc'), '-q', '--threads', '1', '--seed', '1',
                            '--time-limit', seconds, '--report', report]);
    const native = JSON.parse(fs.readFileSync(report)).solver;
    await page.getByRole('button', { name: 'Reset settings' }).click();
    for (const [label, value] of [['Time limit', seconds], ['Seed', '1']]) {
      await page.getByLabel(label, { exact: true }).fill(value);
    }
    await page.getByLabel('Input files', { exact: true }).setInputFiles(tsp);
    await page.getByRole('button', { name: 'Plan', exact: true }).click();
    await page.waitForFunction(() => /^(Done|Stopped)/.test(document.getElementById('status').textContent) ||
                                     !document.getElementById('error').hidden, null, { timeout: 1000 * (Number(seconds) + 120) });
    const status = await page.locator('#status').textContent();
    const m = /(\d+) iterations in ([\d.]+) s/.exec(status);
    if (!m) throw new Error('the page says: ' + status + ' ' + (await page.locator('#error').textContent()));
    const it = Number(m[1]), s = Number(m[2]);
    const ratio = (it / s) / (native.iterations / native.wall_s);
    const holes = nodes.length;
    console.log([name, holes, seconds, native.iterations, native.wall_s.toFixed(2), it, s.toFixed(2), ratio.toFixed(2)].join(','));
  }
  // Stop and the time limit by size (issue 84): random plates of three
  // diameters on 300 x 200 mm (pcb3038's holes first). Stop is pressed 3 s
  // after Plan (in the set-up of a large job, in the iterations of a small
  // one) and timed until the routing ends and until the outputs can be
  // saved; the time limit (10 s) is timed from Plan to the outputs, reading
  // the files again included; the longest task of the page's thread is the
  // long-task observer's, before Stop and with the results drawn.
  // ACO_STOP_AFTER=2.5,3,4: Stop pressed at each of those seconds after Plan,
  // a plan each (the set-up of 10^6 holes spans seconds); ACO_STOP_DIAMETERS=3.0:
  // the same plates with one tool (the holes at the same places).
  const sizes = (process.env.ACO_STOP_SIZES || '3038,20000,100000,1000000').split(',').map(Number);
  const stopAfters = (process.env.ACO_STOP_AFTER || '3').split(',').map(Number);
  const diameters = (process.env.ACO_STOP_DIAMETERS || '3.0,5.0,6.35').split(',').map(Number);
  console.log('holes,holes_read,stop_pressed_after_s,stop_to_routing_ended_s,stop_to_outputs_s,longest_task_planning_ms,longest_task_with_results_ms,time_limit_s,plan_to_done_s,solver_s');
  for (const n of sizes) {
    let csv;
    if (n === 3038) {
      csv = path.join(work, 'pcb3038.csv');
    } else {
      csv = path.join(work, 'random-' + n + '.csv');
      // The page's own random plate (mulberry32: 32-bit integer steps, exact in JavaScript).
      let seed = (12345 + n) >>> 0;
      const rnd = () => {
        seed = (seed + 0x6d2b79f5) >>> 0;
        let t = seed;
        t = Math.imul(t ^ (t >>> 15), t | 1);
        t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
        return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
      };
      const lines = ['x,y,diameter'];
      for (let i = 0; i < n; i++) {
        lines.push((rnd() * 300).toFixed(3) + ',' + (rnd() * 200).toFixed(3) + ',' + diameters[Math.floor(rnd() * 3) % diameters.length]);
      }
      fs.writeFileSync(csv, lines.join('\n') + '\n');
    }
    const fresh = await browser.newPage();
    await fresh.goto(url);
    await fresh.waitForSelector('body[data-ready="1"]', { timeout: 30000 });
    await fresh.evaluate(() => {
      window.longest = 0;
      new PerformanceObserver((l) => { for (const e of l.getEntries()) window.longest = Math.max(window.longest, e.duration); })
        .observe({ type: 'longtask' });
    });
    await fresh.getByLabel('Input files', { exact: true }).setInputFiles(csv);
    await fresh.waitForFunction(() => !document.getElementById('plan').disabled || !document.getElementById('error').hidden, null,
                                { timeout: 600000 });
    // The holes read (duplicates removed), so that a size is what it says.
    const read = Number((/^(\d+) holes/.exec(await fresh.locator('#holes-info p').first().textContent()) || [0, 0])[1]);
    // Ended: the outputs are there to save (or the error is shown).
    const ended = () => fresh.waitForFunction(() => !document.getElementById('save-program').disabled ||
                                                    !document.getElementById('error').hidden, null, { timeout: 900000 });
    const stops = [];
    for (const after of stopAfters) {
      await fresh.evaluate(() => { window.longest = 0; });
      await fresh.getByRole('button', { name: 'Plan', exact: true }).click();
      await fresh.waitForTimeout(after * 1000);
      const longestPlanning = await fresh.evaluate(() => window.longest);  // while it plans, before Stop
      const pressed = Date.now();
      await fresh.getByRole('button', { name: 'Stop', exact: true }).click();
      await fresh.waitForFunction(() => document.body.dataset.routing === 'stopped' ||
                                        /^(Done|Stopped)/.test(document.getElementById('status').textContent), null, { timeout: 900000 });
      const routingS = (Date.now() - pressed) / 1000;
      await ended();
      const stopS = (Date.now() - pressed) / 1000;
      const longest = await fresh.evaluate(() => window.longest);  // Stop and the results drawn included
      stops.push([after, routingS.toFixed(2), stopS.toFixed(2), Math.round(longestPlanning), Math.round(longest)]);
    }
    await fresh.getByLabel('Time limit', { exact: true }).fill('10');
    await fresh.getByLabel('Time limit', { exact: true }).dispatchEvent('change');
    await fresh.waitForFunction(() => !document.getElementById('plan').disabled, null, { timeout: 600000 });
    const t0 = Date.now();
    await fresh.getByRole('button', { name: 'Plan', exact: true }).click();
    await ended();
    const planS = (Date.now() - t0) / 1000;
    const status = await fresh.locator('#status').textContent();
    const m = /iterations in ([\d.]+) s/.exec(status);
    for (const row of stops) console.log([n, read, ...row, 10, planS.toFixed(2), m ? m[1] : status].join(','));
    await fresh.close();
  }
  await browser.close();
  fs.rmSync(work, { recursive: true, force: true });
})().catch((e) => { console.error(e); process.exit(1); });
