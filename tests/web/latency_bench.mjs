// The web edition's control-change latency, measured in node on the WebAssembly core (docs/benchmarks.md):
// for meshes of about 1,000 and 5,000 elements, the first run (mesh, form factors, solve) and a change of the
// light (the form factors kept: solve only). Usage: node latency_bench.mjs <radiosity-core.js> <repository>
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
  const settings = { maxEdge, method, solver: 'gauss-seidel' };
  session.configure(JSON.stringify(settings));
  let t = performance.now();
  const first = JSON.parse(session.run());
  const firstSeconds = (performance.now() - t) / 1000;
  session.configure(JSON.stringify({ ...settings, lightScale: 2 }));
  t = performance.now();
  const again = JSON.parse(session.run());
  const changeSeconds = (performance.now() - t) / 1000;
  console.log(`${first.elements} elements, ${method}: first run ${firstSeconds.toFixed(2)} s, light change ` +
              `${changeSeconds.toFixed(3)} s (form factors reused: ${again.formFactorsReused})`);
  session.delete();
}
