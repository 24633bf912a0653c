// The page against the native program (issue 65), not a test: colony
// iterations per second in the page (WebAssembly, one thread) and in
// `acodrill plan --threads 1`, same instance, seed and time limit; and the
// time from opening the page to its being ready. Run by `scripts/web --bench`.
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
  for (const name of ['pcb3038', 'd15112']) {
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
  await browser.close();
  fs.rmSync(work, { recursive: true, force: true });
})().catch((e) => { console.error(e); process.exit(1); });
