// The web edition's scene playground: drop a scene (JSON, or OBJ with its MTL) on the page, and the
// WebAssembly core validates it with the desktop's messages (file, line), meshes, solves and shows it in a
// live view with the controls of a solve step; B per element downloads as the CSV `radiosity solve --output`
// writes, the form factors as CSV or NumPy .npy (the matrix writer of `radiosity formfactors --output`).
/* global rtLive */
(function () {
  'use strict';

  const status = () => document.getElementById('playground-status');
  const downloads = () => document.querySelectorAll('.playground-download');
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
    const holder = document.getElementById('playground-view');
    if (view) {
      const dropped = view;
      view = null;
      await dropped.close().catch(() => {});
    }
    holder.replaceChildren();
    const subdivide = document.getElementById('playground-subdivide').value;
    const controls = JSON.parse(document.getElementById('playground-drop').dataset.controls);
    const step = { scene, files: texts, stage: 'solve', parameters: { subdivide, solver: 'gauss-seidel' }, controls };
    try {
      view = await new rtLive.LiveView(holder, step).start();
      report(scene + ': ' + view.numbers.textContent, false);
      for (const button of downloads()) button.hidden = false;
    } catch (e) {
      view = null;
      holder.replaceChildren();
      report(e.message, true);
      for (const button of downloads()) button.hidden = true;
    }
  }

  // Hands `data` to the browser as a file named `name`.
  function download(data, name, type) {
    const url = URL.createObjectURL(new Blob([data], { type }));
    const a = document.createElement('a');
    a.href = url;
    a.download = name;
    document.body.appendChild(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(url), 1000);
  }

  // The file a download button gives: [data, name, type].
  async function file(kind) {
    const stem = view.step.scene.replace(/\.[^.]*$/, '');
    if (kind === 'csv') return [await view.request('csv', {}), stem + '-B.csv', 'text/csv'];
    const format = kind === 'F-npy' ? 'npy' : 'csv';
    const bytes = await view.request('matrix', { format });
    if (bytes.length === 0) throw new Error('this solver stores no form factors');
    return [bytes, stem + '-F.' + format, format === 'npy' ? 'application/octet-stream' : 'text/csv'];
  }

  window.addEventListener('load', () => {
    const drop = document.getElementById('playground-drop');
    drop.addEventListener('dragover', (e) => e.preventDefault());
    drop.addEventListener('drop', (e) => {
      e.preventDefault();
      open(Array.from(e.dataTransfer.files));
    });
    document.getElementById('playground-files').addEventListener('change', (e) => open(Array.from(e.target.files)));
    for (const button of downloads()) {
      button.addEventListener('click', async () => {
        if (!view) return;
        try {
          download(...(await file(button.dataset.kind)));
        } catch (e) {
          report(e.message, true);
        }
      });
    }
    window.rtPlayground = { open, file };
  });
})();
