// The web edition's scene playground: drop a scene (JSON, or OBJ with its MTL) on the page, and the
// WebAssembly core validates it with the desktop's messages (file, line), meshes, solves and shows it in a
// live view; B per element downloads as the CSV `radiosity solve --output` writes.
/* global rtLive */
(function () {
  'use strict';

  const status = () => document.getElementById('playground-status');
  let view = null;

  function report(text, isError) {
    status().textContent = text;
    status().className = isError ? 'live-error' : '';
  }

  async function open(files) {
    const texts = {};
    for (const f of files) texts[f.name] = await f.text();
    const scene = Object.keys(texts).find((n) => /\.(json|obj)$/i.test(n));
    if (!scene) {
      report('Drop a scene: a .json file, or an .obj with its .mtl.', true);
      return;
    }
    const module = await rtLive.core();
    const holder = document.getElementById('playground-view');
    holder.replaceChildren();
    const subdivide = Number(document.getElementById('playground-subdivide').value);
    const step = { scene, files: texts, settings: { subdivide, solver: 'gauss-seidel' } };
    try {
      view = new rtLive.LiveView(holder, step, module);
      report(scene + ': ' + view.numbers.textContent, false);
      document.getElementById('playground-csv').hidden = false;
    } catch (e) {
      view = null;
      holder.replaceChildren();
      report(e.message, true);
      document.getElementById('playground-csv').hidden = true;
    }
  }

  window.addEventListener('load', () => {
    const drop = document.getElementById('playground-drop');
    drop.addEventListener('dragover', (e) => e.preventDefault());
    drop.addEventListener('drop', (e) => {
      e.preventDefault();
      open(Array.from(e.dataTransfer.files));
    });
    document.getElementById('playground-files').addEventListener('change', (e) => open(Array.from(e.target.files)));
    document.getElementById('playground-csv').addEventListener('click', () => {
      if (!view) return;
      const url = URL.createObjectURL(new Blob([view.session.csv()], { type: 'text/csv' }));
      const a = document.createElement('a');
      a.href = url;
      a.download = view.step.scene.replace(/\.[^.]*$/, '') + '-B.csv';
      a.click();
      URL.revokeObjectURL(url);
    });
    window.rtPlayground = { open };
  });
})();
