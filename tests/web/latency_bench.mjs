// The web edition's control-change latency, measured in node on the WebAssembly core (docs/benchmarks.md):
// for meshes of about 1,000 and 5,000 elements, the first run (mesh, form factors, solve: the core's own
// seconds for the form factors and the solve) and then a change of the light, of a reflectance and of the
// solver, each with the form factors kept (solve only; through the settings JSON a light change solves again,
// where the pages' steps scale the last solution). The pages add the copies out
// of the core, the transfer from the worker and the repaint (tests/browser measures those).
// Usage: node latency_bench.mjs <radiosity-core.js> <repository>
import { createRequire } from 'node:module';
import fs from 'node:fs';
import path from 'node:path';

const [modulePath, repo] = process.argv.slice(2);
const core = await createRequire(import.meta.url)(path.resolve(modulePath))();
const scene = fs.readFileSync(path.join(repo, 'scenes/cornell-box.json'), 'utf8');
for (const [maxEdge, method] of [[65, 'quadrature'], [65, 'hemicube'], [28, 'hemicube']]) {
  const session = new core.Session();
  session.putFile('cornell-box.json', scene);
  session.load('cornell-box.json');
  const base = { maxEdge, method, solver: 'gauss-seidel' };
  const timed = (settings) => {
    session.configure(JSON.stringify(settings));
    const t = performance.now();
    const summary = JSON.parse(session.run());
    return { summary, seconds: (performance.now() - t) / 1000 };
  };
  const first = timed(base);
  const light = timed({ ...base, lightScale: 2 });
  const reflectance = timed({ ...base, lightScale: 2, reflectance: { floor: [0.5, 0.5, 0.5] } });
  const solver = timed({ ...base, lightScale: 2, reflectance: { floor: [0.5, 0.5, 0.5] }, solver: 'jacobi' });
  const s = first.summary;
  console.log(`${s.elements} elements, ${method}: first run ${first.seconds.toFixed(2)} s (form factors ` +
              `${s.formFactorSeconds.toFixed(2)} s, solve ${s.seconds.toFixed(2)} s), light change ` +
              `${light.seconds.toFixed(3)} s, reflectance change ${reflectance.seconds.toFixed(3)} s ` +
              `(${reflectance.summary.iterations} sweeps), solver change ${solver.seconds.toFixed(3)} s ` +
              `(jacobi, ${solver.summary.iterations} sweeps; form factors reused: ${solver.summary.formFactorsReused})`);
  session.delete();
}
