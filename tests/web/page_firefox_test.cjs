// The page in Firefox (Debian's firefox-esr, headless), driven by
// puppeteer-core over WebDriver BiDi (Playwright cannot drive Debian's
// Firefox): opened from file://, the thesis's plate planned with a fixed
// seed and iteration count, the program saved and compared byte for byte
// with acodrill plan's; a bad file's error shown; nothing fetched.
//   node page_firefox_test.cjs PAGE.html ACODRILL SOURCE_DIR
'use strict';
const puppeteer = require('puppeteer-core');
const { execFileSync } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');

const [page_html, acodrill, root] = process.argv.slice(2);
const work = fs.mkdtempSync(path.join(os.tmpdir(), 'acodrill-firefox-'));
const downloads = path.join(work, 'downloads');
fs.mkdirSync(downloads);
let failures = 0;
function check(ok, what) {
  console.log((ok ? 'ok   ' : 'FAIL ') + what);
  if (!ok) failures++;
}
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

async function saved(name) {
  // Firefox writes through NAME.part: the file is whole when no .part is
  // left and its size holds still between two looks.
  const file = path.join(downloads, name);
  let last = -1;
  for (let k = 0; k < 600; k++) {
    await sleep(100);
    if (!fs.existsSync(file) || fs.readdirSync(downloads).some((f) => f.endsWith('.part'))) continue;
    const size = fs.statSync(file).size;
    if (size > 0 && size === last) return fs.readFileSync(file);
    last = size;
  }
  throw new Error('no download ' + name);
}

(async () => {
  const browser = await puppeteer.launch({ browser: 'firefox', executablePath: '/usr/bin/firefox-esr', headless: true });
  const context = await browser.createBrowserContext({ downloadBehavior: { policy: 'allow', downloadPath: downloads } });
  const page = await context.newPage();
  const outside = [];
  page.on('request', (r) => { if (!/^(file|data|blob):/.test(r.url())) outside.push(r.url()); });
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e.message || e)));
  await page.goto('file://' + path.resolve(page_html));
  await page.waitForSelector('body[data-ready="1"]', { timeout: 60000 });
  check(true, 'the page is ready in Firefox');

  const plate = path.join(root, 'samples', 'plate70.dxf');
  const input = await page.$('#files');
  await input.uploadFile(plate);
  for (const [id, value] of [['set-iterations', '40'], ['set-seed', '3']]) {
    await page.$eval('#' + id, (e, v) => { e.value = v; e.dispatchEvent(new Event('change', { bubbles: true })); }, value);
  }
  await page.waitForFunction(() => /70 holes/.test(document.getElementById('holes-info').textContent), { timeout: 60000 });
  await page.click('#plan');
  await page.waitForFunction(() => !document.getElementById('save-program').disabled, { timeout: 120000 });
  await page.click('#save-program');
  const program = await saved('plate70.nc');
  const cli = path.join(work, 'cli.nc');
  execFileSync(acodrill, ['plan', plate, '-o', cli, '-q', '--iterations', '40', '--seed', '3']);
  check(program.equals(fs.readFileSync(cli)), 'Firefox: the program is acodrill plan\'s, byte for byte');

  const bad = path.join(work, 'bad.csv');
  fs.writeFileSync(bad, 'x,y,diameter\n1,2,3\n4,five,3\n');
  await input.uploadFile(bad);
  await page.waitForFunction(() => !document.getElementById('error').hidden, { timeout: 60000 });
  const error = await page.$eval('#error', (e) => e.textContent);
  check(/^acodrill: error: bad\.csv:3: /.test(error), 'Firefox: a bad file is one line in Error: ' + error);

  // The layout in Firefox (issue 84): on a laptop's 1366x768 and a 390x844
  // phone, with a file of a long name open, Plan and the progress are in
  // view, the drop box holds the name, and the page is no wider than the screen.
  const longName = path.join(work, '\u043f\u043b\u0430\u0442\u0430 \u6e2c\u8a66 board v2 ' + 'a-very-long-file-name-'.repeat(6) + '.dxf');
  fs.copyFileSync(plate, longName);
  for (const [w, h] of [[1366, 768], [390, 844]]) {
    const small = await context.newPage();
    await small.setViewport({ width: w, height: h });
    await small.goto('file://' + path.resolve(page_html));
    await small.waitForSelector('body[data-ready="1"]', { timeout: 60000 });
    await (await small.$('#files')).uploadFile(longName);
    await small.waitForFunction(() => /70 holes/.test(document.getElementById('holes-info').textContent), { timeout: 60000 });
    const layout = await small.evaluate(() => {
      const inView = ['plan', 'progress-text'].every((id) => {
        const r = document.getElementById(id).getBoundingClientRect();
        return r.width > 0 && r.top >= 0 && r.bottom <= window.innerHeight && r.left >= 0 && r.right <= window.innerWidth;
      });
      const drop = document.getElementById('drop').getBoundingClientRect();
      const inside = (id) => {
        const r = document.getElementById(id).getBoundingClientRect();
        return r.right <= drop.right + 0.5 && r.left >= drop.left - 0.5;
      };
      const named = document.getElementById('files-open');
      return { inView, inDrop: inside('files') && inside('files-open') && named.scrollWidth <= named.clientWidth &&
                                /a-very-long-file-name-/.test(named.textContent),
               over: document.documentElement.scrollWidth - window.innerWidth };
    });
    check(layout.inView, 'Firefox ' + w + 'x' + h + ': Plan and the progress are in view after opening a file');
    check(layout.inDrop, 'Firefox ' + w + 'x' + h + ': a long file name stays inside the drop box');
    check(layout.over <= 0, 'Firefox ' + w + 'x' + h + ': the page is not wider than the screen (' + layout.over + ' px over)');
    await small.screenshot({ path: path.join(path.dirname(page_html), 'page-firefox-' + w + 'x' + h + '.png') });
    await small.close();
  }

  check(errors.length === 0, 'no script error: ' + errors.join('; '));
  check(outside.length === 0, 'no request leaves file:, data: or blob:: ' + outside.join(' '));
  await browser.close();
  fs.rmSync(work, { recursive: true, force: true });
  console.log(failures ? failures + ' check(s) failed' : 'acodrill: the page passes in Firefox');
  process.exit(failures ? 1 : 0);
})().catch((e) => {
  console.error(e);
  process.exit(1);
});
