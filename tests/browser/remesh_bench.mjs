// Benchmark (docs/benchmarks.md): a change that meshes anew in the browser. The playground's Cornell box at
// `max-edge` 65 (about 1,000 elements), changed to each given `max-edge` (28: 4,513 elements, 27.2: 5,010),
// hemicube and Gauss-Seidel, F's rows on 2 workers, in a session of its own each time so that no F is cached.
// Prints the time from the change to the repaint, split into the core's form factors and solve.
// Usage: node remesh_bench.mjs <radiosity> <radiosity-core.js> <site folder> [max-edge...] [--runs N]
// Writes the Cornell box lesson's site first (`radiosity book --web`), as the browser suite does.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import puppeteer from 'puppeteer-core';

const args = process.argv.slice(2);
const runsAt = args.indexOf('--runs');
const runs = runsAt >= 0 ? Number(args.splice(runsAt, 2)[1]) : 2;
const [cli, wasm, siteArgument, ...edges] = args;
if (!cli || !wasm || !siteArgument) {
  console.error('usage: node remesh_bench.mjs <radiosity> <radiosity-core.js> <site folder> [max-edge...] [--runs N]');
  process.exit(2);
}
const site = path.resolve(siteArgument);
const repository = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
fs.rmSync(site, { recursive: true, force: true });
execFileSync(cli, ['book', '--web', '--quick', '--no-pdf', '--wasm', wasm, '--output', site, 'cornell-box'],
             { stdio: 'ignore' });
const box = fs.readFileSync(path.join(repository, 'scenes/cornell-box.json'), 'utf8');
const browser = await puppeteer.launch({ executablePath: process.env.RT_CHROMIUM || '/usr/bin/chromium', headless: true,
  args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--window-size=1200,1000'] });
const page = await browser.newPage();
await page.goto(pathToFileURL(path.join(site, 'playground.html')).href);
await page.waitForFunction(() => window.rtLive);
let session = 0;
for (const edge of edges.length ? edges : ['28', '27.2']) {
  for (let k = 0; k < runs; ++k) {
    const r = await page.evaluate(async (scene, edge, name) => {
      window.rtLive.formFactorWorkers = 2;
      const holder = document.getElementById('playground-view');
      holder.replaceChildren();
      const step = { scene: name, files: { [name]: scene }, stage: 'solve', controls: ['max-edge'],
                     parameters: { 'max-edge': '65', method: 'hemicube', solver: 'gauss-seidel' } };
      const view = await new window.rtLive.LiveView(holder, step).start();
      await new Promise((resolve) => setTimeout(resolve, 1000));  // a reader looks before changing
      const started = performance.now();
      view.widgets['max-edge'].value = edge;
      view.widgets['max-edge'].dispatchEvent(new Event('change'));
      while (view.running) await view.running.catch(() => {});
      const seconds = (performance.now() - started) / 1000;
      await view.close();  // as the playground does when another scene comes: the next run starts alone
      return { seconds, elements: view.summary.elements,
               formFactors: view.summary.formFactorSeconds, solve: view.summary.seconds,
               sweeps: view.summary.iterations };
    }, box, edge, `box-${++session}.json`);
    console.log(`max-edge ${edge}: ${r.elements} elements, change to repaint ${r.seconds.toFixed(2)} s (form factors ` +
                `${r.formFactors.toFixed(2)} s, solve ${r.solve.toFixed(2)} s, ${r.sweeps} sweeps)`);
  }
}
await browser.close();
