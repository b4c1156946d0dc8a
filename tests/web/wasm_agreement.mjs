// The WebAssembly core against the native program on the same steps: the same element count, and B equal to
// 1e-12 relative for the deterministic methods and solvers (the target is 1e-9). Usage:
//   node wasm_agreement.mjs <radiosity-core.js> <radiosity executable> <repository> <scratch folder>
// Exits 77 (ctest: skipped) when the module has not been built, unless RT_REQUIRE_WEB=1 asks for it.
import { execFileSync } from 'node:child_process';
import { createRequire } from 'node:module';
import fs from 'node:fs';
import path from 'node:path';

const [modulePath, cli, repo, scratch] = process.argv.slice(2);
if (!fs.existsSync(modulePath)) {
  const message = `${modulePath} is not built (cmake --preset wasm && cmake --build --preset wasm)`;
  if (process.env.RT_REQUIRE_WEB === '1') {
    console.error(`FAILED: ${message}`);
    process.exit(1);
  }
  console.log(`skipped: ${message}`);
  process.exit(77);
}
const RadiosityCore = createRequire(import.meta.url)(path.resolve(modulePath));
const core = await RadiosityCore();

// [scene file, web settings, the same as radiosity solve's options, relative tolerance on B]. The two
// builds compute the same numbers to rounding on every step, the adaptive quadrature included: its
// occluders come in the order of a tree built the same with every standard library (box_tree.cpp) and its
// rules split equally rated cells in the same order (core/portable_heap.h). Each tolerance is a little above
// the agreement measured (docs/benchmarks.md): a difference past it is a new cause to find.
const steps = [
  ['cornell-box.json', { subdivide: 3, method: 'analytic', solver: 'gauss-seidel' }, 1e-12],
  ['cornell-box.json', { subdivide: 2, method: 'quadrature', solver: 'jacobi' }, 1e-12],
  ['cornell-box.json', { maxEdge: 100, method: 'quadrature', solver: 'gauss-seidel' }, 1e-12],
  ['cornell-box.json', { maxEdge: 150, method: 'hemicube', solver: 'southwell' }, 1e-12],
  ['cornell-box.json', { subdivide: 3, method: 'hemicube', solver: 'bounces' }, 1e-12],
  ['occluded-plates.json', { subdivide: 4, method: 'quadrature', solver: 'direct' }, 1e-12],
  ['cornell-box.json', { subdivide: 2, method: 'raycast', solver: 'gauss-seidel', seed: 3 }, 1e-12],
];

function cliArguments(settings) {
  const names = { subdivide: '--subdivide', maxEdge: '--max-edge', method: '--method', solver: '--solver',
                  seed: '--seed', tolerance: '--tolerance' };
  return Object.entries(settings).flatMap(([key, value]) => [names[key], String(value)]);
}

function readCsvB(text) {
  return text.trim().split('\n').slice(1).map((line) => line.split(',').slice(4, 7).map(Number));
}

fs.mkdirSync(scratch, { recursive: true });
let passed = 0, failed = 0;
for (const [file, settings, tolerance] of steps) {
  const label = `${file} ${JSON.stringify(settings)}`;
  const csv = path.join(scratch, `native-${passed + failed}.csv`);
  const scenePath = path.join(repo, 'scenes', file);
  execFileSync(cli, ['solve', scenePath, ...cliArguments(settings), '--output', csv], { stdio: 'pipe' });
  const native = readCsvB(fs.readFileSync(csv, 'utf8'));

  const session = new core.Session();
  session.putFile(file, fs.readFileSync(scenePath, 'utf8'));
  const problems = [session.load(file), session.configure(JSON.stringify(settings))].filter((p) => p !== '');
  const started = performance.now();
  const summary = problems.length ? { error: problems.join('; ') } : JSON.parse(session.run());
  const seconds = (performance.now() - started) / 1000;
  const web = session.radiosity(-1);
  const webCsv = session.csv();
  session.delete();
  if (summary.error) {
    console.log(`FAILED ${label}: ${summary.error}`);
    ++failed;
    continue;
  }
  let largest = 0;
  for (const row of native) largest = Math.max(largest, ...row.map(Math.abs));
  let worst = 0;
  for (let i = 0; i < native.length; ++i)
    for (let c = 0; c < 3; ++c) {
      const n = native[i][c], w = web[3 * i + c];
      worst = Math.max(worst, Math.abs(w - n) / Math.max(Math.abs(n), 1e-12 * largest));
    }
  const sameCount = summary.elements === native.length && web.length === 3 * native.length;
  const sameRows = readCsvB(webCsv).length === native.length;
  const ok = sameCount && sameRows && worst <= tolerance;
  console.log(`${ok ? 'ok' : 'FAILED'} ${label}: ${summary.elements} elements (native ${native.length}), ` +
              `${summary.iterations} iterations, max relative dB ${worst.toExponential(2)}, wasm ${seconds.toFixed(2)} s`);
  ok ? ++passed : ++failed;
}
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed === 0 ? 0 : 1);
