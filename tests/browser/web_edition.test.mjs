// The web edition in a real browser: Debian's headless Chromium driven through the DevTools protocol by
// puppeteer-core (which never downloads a browser). For every page of the site with live views:
// no console errors; every view's canvas is not blank; a drag rotates the view; the light and reflectance
// sliders change the numbers and the picture; the scrubber changes the colours. Screenshots go to
// <site>/screenshots. Usage: node web_edition.test.mjs <radiosity> <radiosity-core.js> <site folder> [lesson...]
// writes the site with `radiosity book --web` (the Cornell box lesson unless lessons are named) and tests it.
// Exits 77 (ctest: skipped) when the WebAssembly core, Chromium or puppeteer-core is missing, unless
// RT_REQUIRE_WEB=1 asks for them.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const [cli, wasm, siteArgument, ...lessons] = process.argv.slice(2);
const site = path.resolve(siteArgument || '');
const chromium = process.env.RT_CHROMIUM || '/usr/bin/chromium';
function unavailable(message) {
  if (process.env.RT_REQUIRE_WEB === '1') {
    console.error(`FAILED: ${message}`);
    process.exit(1);
  }
  console.log(`skipped: ${message}`);
  process.exit(77);
}
if (!fs.existsSync(wasm)) unavailable(`${wasm} is not built (cmake --preset wasm && cmake --build --preset wasm)`);
if (!fs.existsSync(chromium)) unavailable(`${chromium} not found (./install-deps.sh installs chromium)`);
let puppeteer;
try {
  puppeteer = (await import('puppeteer-core')).default;
} catch {
  unavailable('puppeteer-core is not installed (npm ci in tests/browser)');
}
fs.rmSync(site, { recursive: true, force: true });
const started = Date.now();
execFileSync(cli, ['book', '--web', '--quick', '--no-pdf', '--wasm', wasm, '--output', site,
                   ...(lessons.length ? lessons : ['cornell-box'])], { stdio: 'inherit' });
let bytes = 0;
const walk = (dir) => fs.readdirSync(dir, { withFileTypes: true }).forEach((e) =>
  e.isDirectory() ? walk(path.join(dir, e.name)) : (bytes += fs.statSync(path.join(dir, e.name)).size));
walk(site);
console.log(`site written in ${((Date.now() - started) / 1000).toFixed(1)} s: ${(bytes / 1e6).toFixed(1)} MB`);
const pages = fs.existsSync(site)
  ? fs.readdirSync(site).filter((f) => f.endsWith('.html') && fs.readFileSync(path.join(site, f), 'utf8').includes('data-live="'))
  : [];
if (pages.length === 0) {
  console.error(`FAILED: no page with a live view in ${site}`);
  process.exit(1);
}
const shots = path.join(site, 'screenshots');
fs.mkdirSync(shots, { recursive: true });

const browser = await puppeteer.launch({
  executablePath: chromium,
  headless: true,
  args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--window-size=1200,1000'],
});

let passed = 0, failed = 0;
function check(ok, label, detail = '') {
  console.log(`${ok ? 'ok' : 'FAILED'} ${label}${detail ? ': ' + detail : ''}`);
  ok ? ++passed : ++failed;
}

// The view's pixels: how many differ from the background, and a checksum of all of them.
async function pixels(page, k) {
  return page.evaluate((k) => {
    const view = window.rtLiveViews[k];
    view.render();
    const source = view.renderer.domElement;
    const copy = document.createElement('canvas');
    copy.width = source.width;
    copy.height = source.height;
    const g = copy.getContext('2d');
    g.drawImage(source, 0, 0);
    const data = g.getImageData(0, 0, copy.width, copy.height).data;
    let lit = 0, sum = 0;
    for (let i = 0; i < data.length; i += 4) {
      if (Math.abs(data[i] - 32) + Math.abs(data[i + 1] - 32) + Math.abs(data[i + 2] - 32) > 6) ++lit;
      sum = (sum * 31 + data[i] + 3 * data[i + 1] + 7 * data[i + 2]) % 1000000007;
    }
    return { lit: lit / (data.length / 4), sum };
  }, k);
}

async function setSlider(page, k, cls, value) {
  await page.evaluate((k, cls, value) => {
    const slider = window.rtLiveViews[k].sliders[cls];
    slider.value = String(value);
    slider.dispatchEvent(new Event('change'));
  }, k, cls, value);
}

const numbers = (page, k) => page.evaluate((k) => window.rtLiveViews[k].numbers.textContent, k);

for (const file of pages) {
  const page = await browser.newPage();
  await page.setViewport({ width: 1200, height: 1000 });
  const errors = [];
  page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
  page.on('pageerror', (e) => errors.push(String(e)));
  const started = Date.now();
  await page.goto(pathToFileURL(path.join(site, file)).href, { waitUntil: 'load' });
  await page.waitForSelector('body[data-live-ready]', { timeout: 60000 });
  const loadSeconds = (Date.now() - started) / 1000;
  const views = await page.evaluate(() => document.querySelectorAll('.live-view').length);
  const ready = await page.evaluate(() => window.rtLiveViews.length);
  check(ready === views, `${file}: every live view computed`, `${ready} of ${views}, interactive ${loadSeconds.toFixed(2)} s after navigation`);
  for (let k = 0; k < ready; ++k) {
    const label = `${file} view ${k + 1}`;
    const handle = await page.evaluateHandle((k) => window.rtLiveViews[k].renderer.domElement, k);
    await handle.scrollIntoView();
    const before = await pixels(page, k);
    check(before.lit > 0.05, `${label}: the canvas is not blank`, `${(100 * before.lit).toFixed(1)} % lit`);
    await handle.screenshot({ path: path.join(shots, `${path.basename(file, '.html')}-${k + 1}-start.png`) });

    const box = await handle.boundingBox();
    const cx = box.x + box.width / 2, cy = box.y + box.height / 2;
    await page.mouse.move(cx, cy);
    await page.mouse.down();
    await page.mouse.move(cx + 120, cy + 30, { steps: 8 });
    await page.mouse.up();
    const dragged = await pixels(page, k);
    check(dragged.sum !== before.sum, `${label}: a drag rotates the view`);
    await handle.screenshot({ path: path.join(shots, `${path.basename(file, '.html')}-${k + 1}-dragged.png`) });

    const picked = await page.evaluate((k, x, y) => {
      const view = window.rtLiveViews[k];
      const e = view.pick(x, y);
      return [e, view.picked.textContent];
    }, k, cx, cy);
    check(picked[0] >= 0 && /row of F sums to/.test(picked[1]), `${label}: a click picks an element and shows its B and row of F`,
          picked[1].slice(0, 110));
    const text = await numbers(page, k);
    const t0 = Date.now();
    await setSlider(page, k, 'light', 2);
    const lightSeconds = (Date.now() - t0) / 1000;
    const lit = await pixels(page, k);
    check((await numbers(page, k)) !== text && lit.sum !== dragged.sum, `${label}: the light slider changes the numbers and the picture`,
          `recomputed and repainted in ${lightSeconds.toFixed(3)} s`);
    const hasRho = await page.evaluate((k) => Boolean(window.rtLiveViews[k].sliders.rho), k);
    if (hasRho) {
      const text2 = await numbers(page, k);
      await setSlider(page, k, 'rho', 0.2);
      const darker = await pixels(page, k);
      check((await numbers(page, k)) !== text2 && darker.sum !== lit.sum, `${label}: the reflectance slider changes the numbers and the picture`);
    }
    await handle.screenshot({ path: path.join(shots, `${path.basename(file, '.html')}-${k + 1}-sliders.png`) });

    const last = await page.evaluate((k) => Number(window.rtLiveViews[k].scrubber.max), k);
    if (last > 0) {
      const end = await pixels(page, k);
      await page.evaluate((k) => {
        const s = window.rtLiveViews[k].scrubber;
        s.value = '0';
        s.dispatchEvent(new Event('input'));
      }, k);
      const first = await pixels(page, k);
      check(first.sum !== end.sum, `${label}: the scrubber changes the colours`, `iterations 1 and ${last + 1}`);
      await handle.screenshot({ path: path.join(shots, `${path.basename(file, '.html')}-${k + 1}-iteration-1.png`) });
    }
  }
  check(errors.length === 0, `${file}: no console errors`, errors.slice(0, 3).join(' | '));
  await page.screenshot({ path: path.join(shots, `${path.basename(file, '.html')}-page.png`), fullPage: false });
  await page.close();
}
// The playground: a dropped OBJ with its MTL is solved and shown; a bad OBJ is reported with its line.
{
  const page = await browser.newPage();
  await page.setViewport({ width: 1200, height: 1000 });
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(pathToFileURL(path.join(site, 'playground.html')).href, { waitUntil: 'load' });
  await page.waitForFunction(() => window.rtPlayground !== undefined);
  const repo = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..');
  const drop = (files) => page.evaluate(async (files) => {
    await window.rtPlayground.open(files.map(([name, text]) => new File([text], name)));
    return document.getElementById('playground-status').textContent;
  }, files);
  const obj = fs.readFileSync(path.join(repo, 'scenes/cornell-box.obj'), 'utf8');
  const mtl = fs.readFileSync(path.join(repo, 'scenes/cornell-box.mtl'), 'utf8');
  const solved = await drop([['cornell-box.obj', obj], ['cornell-box.mtl', mtl]]);
  check(/elements/.test(solved) && !/error/i.test(solved), 'playground: a dropped OBJ and MTL are solved', solved.slice(0, 100));
  await page.screenshot({ path: path.join(shots, 'playground.png') });
  const bad = await drop([['bad.obj', 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n']]);
  check(bad.includes('bad.obj:4'), 'playground: a bad OBJ is reported with its line', bad.slice(0, 120));
  check(errors.length === 0, 'playground: no page errors', errors.slice(0, 3).join(' | '));
  await page.close();
}
await browser.close();
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed === 0 ? 0 : 1);
