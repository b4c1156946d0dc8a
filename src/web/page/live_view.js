// The web edition's live figures. Every <div class="live-view" data-live="KEY"> on a page becomes a 3D view
// of a step computed in the browser by the WebAssembly core (radiosity-core.js): rotate and zoom with the
// mouse, a scrubber with play through the solver's iterations beside the residual chart, and one widget per
// control of the step, built from the rows of the lesson layer's table of step keys that the core hands out
// (the app's parameter panel builds its widgets from the same rows), and compare mode: the step beside itself
// with another method or solver from those rows. A change solves again in a Web Worker (live_worker.js), so
// that the page stays responsive, with a progress bar; the form factors stay cached in the core when only
// the light or a reflectance changed.
// RT_LIVE[KEY] (the page's <lesson>-live.js) holds the step: its scene files, its stage, its parameters as
// the lesson writes them and the keys it offers as controls.
/* global THREE, RT_LIVE */
(function () {
  'use strict';

  // ---- The page's side of the worker: requests answered by promises, progress reported on the way.
  const live = {};  // window.rtLive
  let worker = null;
  let nextId = 0;
  const pending = new Map();
  function ask(op, args, onProgress) {
    if (!worker) {
      worker = new Worker(URL.createObjectURL(new Blob([window.rtLiveWorkerScript()], { type: 'text/javascript' })));
      worker.onmessage = (e) => {
        const request = pending.get(e.data.id);
        if (!request) return;
        if ('progress' in e.data) {
          if (request.onProgress) request.onProgress(e.data.progress, e.data.stage);
          return;
        }
        pending.delete(e.data.id);
        if ('error' in e.data) request.reject(new Error(e.data.error));
        else request.resolve(e.data.result);
      };
    }
    return new Promise((resolve, reject) => {
      const id = ++nextId;
      pending.set(id, { resolve, reject, onProgress });
      worker.postMessage({ id, op, args });
    });
  }

  // The colours of the elements (8-bit, n x 3) spread over their triangles' vertices.
  function colours(rgb8, triangleElements, out) {
    for (let t = 0; t < triangleElements.length; ++t) {
      const e = triangleElements[t];
      for (let c = 0; c < 3; ++c) {
        const v = rgb8[3 * e + c] / 255;
        for (let k = 0; k < 3; ++k) out[9 * t + 3 * k + c] = v;
      }
    }
  }

  // A 2D figure of the core's viz layer (polygons, lines and text in pixels, origin bottom-left; the module
  // hands it out as JSON) painted on a canvas.
  function paintDrawing(canvas, d) {
    canvas.width = d.width;
    canvas.height = d.height;
    const g = canvas.getContext('2d');
    const rgb = (c) => 'rgb(' + c.join(',') + ')';
    g.fillStyle = rgb(d.background);
    g.fillRect(0, 0, d.width, d.height);
    const align = ['left', 'center', 'right'], baseline = ['bottom', 'middle', 'top'];
    for (const shape of d.shapes) {
      const points = shape.points.map(([x, y]) => [x, d.height - y]);
      if (shape.kind === 'text') {
        g.save();
        g.translate(points[0][0], points[0][1]);
        g.rotate((-shape.angle * Math.PI) / 180);
        g.font = (shape.bold ? 'bold ' : '') + shape.fontSize + 'px sans-serif';
        g.textAlign = align[shape.hAlign];
        g.textBaseline = baseline[shape.vAlign];
        g.fillStyle = rgb(shape.fill);
        g.fillText(shape.text, 0, 0);
        g.restore();
        continue;
      }
      g.beginPath();
      points.forEach(([x, y], k) => (k ? g.lineTo(x, y) : g.moveTo(x, y)));
      if (shape.kind === 'polygon') g.closePath();
      if (shape.kind === 'polygon' && shape.filled) {
        g.fillStyle = rgb(shape.fill);
        g.fill();
        // Neighbouring pixels of a face share their edges: a hairline of their colour hides the seam.
        if (!(shape.strokeWidth > 0)) {
          g.strokeStyle = g.fillStyle;
          g.lineWidth = 0.5;
          g.stroke();
        }
      }
      if (shape.strokeWidth > 0) {
        g.strokeStyle = rgb(shape.stroke);
        g.lineWidth = shape.strokeWidth;
        g.stroke();
      }
    }
  }

  // The drawing buffer at the size the canvas is shown (half the width in compare mode): a buffer larger than
  // its box would be shown scaled down at best, and cropped by some compositors.
  function fitToCanvas(renderer) {
    const canvas = renderer.domElement;
    const width = canvas.clientWidth;
    if (width > 0 && canvas.width !== width) renderer.setSize(width, Math.round(width * 0.75), false);
  }

  function element(tag, attributes, parent) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attributes || {})) {
      if (k === 'text') e.textContent = v;
      else e.setAttribute(k, v);
    }
    if (parent) parent.appendChild(e);
    return e;
  }

  function drawChart(canvas, residuals, current) {
    const g = canvas.getContext('2d');
    const w = canvas.width, h = canvas.height, pad = 28;
    g.fillStyle = '#fff';
    g.fillRect(0, 0, w, h);
    g.strokeStyle = '#888';
    g.strokeRect(pad, 4, w - pad - 4, h - pad);
    const logs = Array.from(residuals, (r) => Math.log10(Math.max(r, 1e-300)));
    if (logs.length === 0) return;
    const top = Math.ceil(Math.max(...logs)), bottom = Math.floor(Math.min(...logs, top - 1));
    const x = (k) => pad + (w - pad - 4) * (logs.length > 1 ? k / (logs.length - 1) : 0.5);
    const y = (v) => 4 + (h - pad - 4) * (top - v) / (top - bottom);
    g.fillStyle = '#333';
    g.font = '10px sans-serif';
    g.fillText('1e' + top, 0, 12);
    g.fillText('1e' + bottom, 0, h - pad);
    g.fillText('iteration', w / 2 - 20, h - 6);
    g.strokeStyle = '#1f5fbf';
    g.beginPath();
    logs.forEach((v, k) => (k ? g.lineTo(x(k), y(v)) : g.moveTo(x(k), y(v))));
    g.stroke();
    g.fillStyle = '#c0392b';
    g.beginPath();
    g.arc(x(Math.min(current, logs.length - 1)), y(logs[Math.min(current, logs.length - 1)]), 4, 0, 2 * Math.PI);
    g.fill();
  }

  // One widget for a row of the step-key table (the app's panel: a spin box, a check box, a list, a typed
  // field). The light and a surface's reflectance are sliders, to drag.
  function widget(row, value, surface) {
    if (row.name === 'light-scale' || row.name === 'reflectance') {
      const top = row.name === 'light-scale' ? Math.max(3, 2 * Number(value)) : 0.95;
      return element('input', { type: 'range', min: String(row.min), max: String(Math.min(row.max, top)),
                                step: '0.05', value: String(value) });
    }
    if (row.type === 'choice') {
      const select = element('select');
      for (const choice of row.choices) element('option', { value: choice, text: choice }, select);
      select.value = value;
      return select;
    }
    if (row.type === 'bool') {
      const box = element('input', { type: 'checkbox' });
      box.checked = value === 'true';
      return box;
    }
    if ((row.type === 'int' || row.type === 'double') && !row.logScale) {
      const input = element('input', { type: 'number', min: String(row.min), max: String(Math.min(row.max, 1e6)),
                                       step: String(row.type === 'int' ? Math.max(1, row.step) : row.step),
                                       value: String(value) });
      if (row.zeroText) input.title = '0: ' + row.zeroText;
      return input;
    }
    return element('input', { type: 'text', size: '8', value: String(value), placeholder: row.zeroText || '' });
  }

  // The text of a widget as a lesson would write the key's value.
  function widgetText(row, input) {
    if (row.type === 'bool') return input.checked ? 'true' : 'false';
    if (row.name === 'reflectance') return String(input.value);
    return String(input.value).trim();
  }

  class LiveView {
    constructor(container, step) {
      this.step = step;
      this.sessionKey = JSON.stringify(step.files) + step.scene;
      this.parameters = Object.assign({}, step.parameters);
      this.build(container);
    }

    // The widgets, then the first solve; resolves when the view shows it.
    async start() {
      this.rows = await ask('controls', { keys: this.step.controls || [] });
      this.buildControls();
      await this.solve();
      return this;
    }

    // For a page that replaces its view of a scene (the playground, when another scene is dropped): the
    // view's WebGL contexts and its scene's session in the worker (F, the mesh, every iterate) are freed. A
    // view of the same scene asked anything later starts a session of its own again.
    close() {
      for (const renderer of [this.renderer, this.compareRenderer]) {
        if (!renderer) continue;
        renderer.dispose();
        renderer.forceContextLoss();
      }
      this.renderer = this.compareRenderer = null;
      return ask('close', { sessionKey: this.sessionKey });
    }

    request(op, args, onProgress) {
      return ask(op, Object.assign({ sessionKey: this.sessionKey, files: this.step.files, scene: this.step.scene,
                                     step: this.stepNow(), workers: live.formFactorWorkers }, args), onProgress);
    }

    stepNow() {
      return { stage: this.step.stage || 'solve', parameters: this.parameters };
    }

    build(container) {
      container.classList.add('live-ready');
      // The view, and beside it (compare mode) the same step with another method or solver.
      const views = element('div', { class: 'live-canvases' }, container);
      const view = element('div', { class: 'live-canvas' }, views);
      this.caption = element('div', { class: 'live-caption' }, view);
      this.renderer = this.makeRenderer(container, view);
      this.scene = new THREE.Scene();
      this.scene.background = new THREE.Color(0x202020);
      this.camera = new THREE.PerspectiveCamera(40, 4 / 3, 0.001, 1e7);
      this.controls = new THREE.OrbitControls(this.camera, this.renderer.domElement);
      this.controls.addEventListener('change', () => this.render());
      this.compareView = element('div', { class: 'live-canvas live-compare-canvas' }, views);
      this.compareView.hidden = true;
      this.compareCaption = element('div', { class: 'live-caption' }, this.compareView);

      const panel = element('div', { class: 'live-panel' }, container);
      const scrub = element('div', { class: 'live-row' }, panel);
      this.play = element('button', { type: 'button', class: 'live-play', text: 'Play' }, scrub);
      this.scrubber = element('input', { type: 'range', min: '0', max: '0', value: '0', class: 'live-scrubber',
                                         'aria-label': 'iteration' }, scrub);
      this.iterationLabel = element('span', { class: 'live-iteration' }, scrub);
      this.chart = element('canvas', { width: '320', height: '150', class: 'live-chart' }, panel);
      this.widgets = {};
      this.form = element('div', { class: 'live-controls' }, panel);
      const busy = element('div', { class: 'live-row live-busy' }, panel);
      this.progress = element('progress', { max: '1', value: '0' }, busy);
      this.progressLabel = element('span', { class: 'live-progress-label' }, busy);
      this.busy = busy;
      busy.hidden = true;
      this.refusal = element('div', { class: 'live-error live-refusal' }, panel);
      this.numbers = element('div', { class: 'live-numbers' }, panel);
      this.compareNumbers = element('div', { class: 'live-numbers live-compare-numbers' }, panel);
      this.picked = element('div', { class: 'live-picked', text: 'Click an element to see its B and its row of F.' },
                            panel);
      // A step that shows an element's hemicube: its five faces unfolded, the lesson's figure drawn live by the
      // core, from the element chosen here at the step's resolution.
      if (this.step.hemicube) {
        const holder = element('div', { class: 'live-hemicube' }, container);
        const label = element('label', { class: 'live-row', text: 'Hemicube of element ' }, holder);
        this.hemicubeFrom = element('input', { type: 'number', min: '0', step: '1', class: 'live-hemicube-from',
                                               value: String(this.step.hemicube.from) }, label);
        this.hemicubeCanvas = element('canvas', { class: 'live-hemicube-faces' }, holder);
        this.hemicubeFrom.addEventListener('change', () => this.drawHemicube());
      }
      // A click (not a drag) picks the element under the pointer.
      const canvas = this.renderer.domElement;
      canvas.addEventListener('pointerdown', (e) => (this.down = [e.clientX, e.clientY]));
      canvas.addEventListener('pointerup', (e) => {
        if (this.down && Math.hypot(e.clientX - this.down[0], e.clientY - this.down[1]) < 4)
          this.pick(e.clientX, e.clientY);
      });
      this.scrubber.addEventListener('input', () => this.show(Number(this.scrubber.value)));
      this.play.addEventListener('click', () => this.toggle());
    }

    makeRenderer(container, holder) {
      const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
      renderer.setPixelRatio(1);
      // The drawing buffer's size only: the style sheet sizes the canvas, one or two to the width.
      renderer.setSize(container.clientWidth || 640, Math.round((container.clientWidth || 640) * 0.75), false);
      holder.appendChild(renderer.domElement);
      return renderer;
    }

    buildControls() {
      this.shown = [];
      for (const row of this.rows) {
        const surface = row.name === 'reflectance' ? this.step.surface : null;
        if (row.name === 'reflectance' && !surface) continue;
        const key = surface ? 'reflectance.' + surface : row.name;
        const label = element('label', { class: 'live-row', title: row.tooltip,
                                         text: (surface ? 'Reflectance of ' + surface : row.label) + ' ' }, this.form);
        const input = widget(row, this.valueOf(row, key), surface);
        input.classList.add('live-control-' + row.name);
        label.appendChild(input);
        this.widgets[row.name] = input;
        this.shown.push([row, key, input]);
        input.addEventListener('change', () => this.edited(row, key, input));
      }
      this.buildCompare();
    }

    // Compare mode: the step again with another form-factor method or solver, the choices those of the same
    // rows of the step-key table as the widgets (the app's compare mode sets two methods or solvers side by
    // side), both computed in the worker and coloured at one exposure, so that brighter means more light.
    buildCompare() {
      const rows = this.rows.filter((row) => (row.name === 'method' || row.name === 'solver') && row.choices);
      if (rows.length === 0) return;
      const label = element('label', { class: 'live-row', text: 'Compare with ',
                                       title: 'The same step beside this one, with another method or solver' },
                            this.form);
      const select = element('select', { class: 'live-compare' }, label);
      element('option', { value: '', text: 'nothing' }, select);
      for (const row of rows)
        for (const choice of row.choices)
          element('option', { value: row.name + '=' + choice, text: row.label + ': ' + choice }, select);
      this.compareSelect = select;
      select.addEventListener('change', () => this.compare(select.value));
    }

    // Shows the step with `choice` ("solver=jacobi", "method=analytic") beside this view; '' ends it.
    async compare(choice) {
      this.compareWith = choice;
      this.compareSelect.value = choice;
      if (!choice) {
        this.compareView.hidden = true;
        this.compareResult = null;
        this.compareNumbers.textContent = '';
        this.caption.textContent = '';
        return;
      }
      return this.solve();
    }

    // The compared step's parameters: this view's, with the chosen key's value.
    compareParameters() {
      const [key, value] = this.compareWith.split('=');
      return Object.assign({}, this.parameters, { [key]: value });
    }

    async solveCompare() {
      const parameters = this.compareParameters();
      const result = await this.request('solve', { exposure: this.exposure,
                                                   step: { stage: this.step.stage || 'solve', parameters } });
      if (!this.compareRenderer) {
        this.compareRenderer = this.makeRenderer(this.renderer.domElement.closest('.live-view'), this.compareView);
        this.compareScene = new THREE.Scene();
        this.compareScene.background = this.scene.background;
        this.compareMesh = new THREE.Mesh(new THREE.BufferGeometry(), this.mesh.material);
        this.compareScene.add(this.compareMesh);
        // Either view turns both: one camera, two controls on its target.
        const controls = new THREE.OrbitControls(this.camera, this.compareRenderer.domElement);
        // Made, the controls turn the camera towards their own target (the origin); point it back at the view's.
        controls.target = this.controls.target;
        controls.update();
        controls.addEventListener('change', () => this.render());
      }
      const geometry = this.compareMesh.geometry;
      geometry.setAttribute('position', new THREE.BufferAttribute(result.positions, 3));
      this.compareColours = new Float32Array(result.positions.length);
      geometry.setAttribute('color', new THREE.BufferAttribute(this.compareColours, 3));
      geometry.computeBoundingSphere();
      this.compareResult = result;
      this.compareView.hidden = false;
    }

    // The faces from the element the widget names (kept within the mesh) at the step's resolution.
    async drawHemicube() {
      const last = Math.max(0, this.summary.elements - 1);
      const from = Math.min(last, Math.max(0, Math.round(Number(this.hemicubeFrom.value) || 0)));
      this.hemicubeFrom.max = String(last);
      this.hemicubeFrom.value = String(from);
      const resolution = Number(this.parameters.resolution || this.step.hemicube.resolution);
      const figure = await this.request('hemicube', { element: from, resolution, width: 880, height: 800 });
      if (figure) paintDrawing(this.hemicubeCanvas, JSON.parse(figure));
    }

    // What a view's step computes with, for its caption.
    describe(summary, parameters) {
      return (summary.method ? summary.method + ', ' : '') + summary.solver +
             (parameters.subdivide ? ', subdivide ' + parameters.subdivide : '');
    }

    // What a widget shows: the step's value, or the default the method or solver then uses (as the app).
    valueOf(row, key) {
      if (row.name === 'reflectance') {
        const written = this.parameters[key];
        return written === undefined ? this.step.surfaceReflectance : Math.max(...written.split(' ').map(Number));
      }
      return this.parameters[key] !== undefined ? this.parameters[key] : row.default;
    }

    showValues() {
      for (const [row, key, input] of this.shown) {
        if (row.type === 'bool') input.checked = this.valueOf(row, key) === 'true';
        else input.value = String(this.valueOf(row, key));
      }
    }

    // A widget's new value becomes the step's parameter (the two ways of meshing exclude each other: the one
    // touched wins, as in the app), and the step is solved again.
    edited(row, key, input) {
      const text = widgetText(row, input);
      if (row.name === 'reflectance') {
        // The surface keeps its hue: the slider sets its largest channel.
        const base = this.step.surfaceColour;
        const top = Math.max(...base, 1e-9);
        this.parameters[key] = base.map((c) => String((c / top) * Number(text))).join(' ');
      } else if (text === '') {
        delete this.parameters[key];
      } else {
        this.parameters[key] = text;
      }
      if (row.name === 'subdivide') delete this.parameters['max-edge'];
      if (row.name === 'max-edge') delete this.parameters.subdivide;
      return this.solve();
    }

    // Solves the step as the widgets set it; a value the core refuses is shown, and the view keeps its last
    // solution. Changes made while a solve runs are taken by one more solve after it.
    async solve() {
      if (this.running) {
        this.again = true;
        return this.running;
      }
      const started = performance.now();
      this.busy.hidden = false;
      this.progress.value = 0;
      this.progressLabel.textContent = 'computing…';
      const tried = Object.assign({}, this.parameters);
      this.progressReports = 0;
      this.running = this.request('solve', { exposure: this.exposure }, (fraction, stage) => {
        ++this.progressReports;
        this.progress.value = fraction;
        this.progressLabel.textContent = stage + ' ' + Math.round(100 * fraction) + ' %';
      }).then(async (result) => {
        this.refusal.textContent = '';
        this.good = tried;
        this.exposure = this.exposure || result.exposure;
        if (this.compareWith) {
          try {
            await this.solveCompare();
          } catch (error) {
            // The view keeps its own solution; the text says why nothing stands beside it.
            this.compareView.hidden = true;
            this.compareResult = null;
            this.compareNumbers.textContent = 'Not compared: ' + error.message;
          }
        }
        this.take(result, (performance.now() - started) / 1000);
        if (this.hemicubeCanvas) await this.drawHemicube();
        this.phases = Object.assign({ total: (performance.now() - started) / 1000 }, result.phases);
      }, (error) => {
        this.refusal.textContent = 'Not applied: ' + error.message;
        if (!this.good) throw error;
        this.parameters = Object.assign({}, this.good);
        this.showValues();
      });
      try {
        await this.running;
      } finally {
        this.running = null;
        this.busy.hidden = true;
      }
      if (this.again) {
        this.again = false;
        await this.solve();
      }
    }

    take(result, seconds) {
      Object.assign(this, { summary: result.summary, history: result.history, final: result.final, seconds,
                            historyColours: result.colours, finalColours: result.finalColours,
                            exposure: result.exposure, residuals: result.residuals });
      this.makeMesh(result);
      const last = Math.max(0, this.summary.iterations - 1);
      this.scrubber.max = String(last);
      this.scrubber.value = String(last);
      this.show(last);
    }

    makeMesh(result) {
      const first = !this.mesh;
      if (first) {
        const material = new THREE.MeshBasicMaterial({ vertexColors: THREE.VertexColors, side: THREE.FrontSide });
        this.mesh = new THREE.Mesh(new THREE.BufferGeometry(), material);
        this.scene.add(this.mesh);
      }
      const geometry = this.mesh.geometry;
      this.triangleElements = result.triangleElements;
      geometry.setAttribute('position', new THREE.BufferAttribute(result.positions, 3));
      this.colourArray = new Float32Array(result.positions.length);
      geometry.setAttribute('color', new THREE.BufferAttribute(this.colourArray, 3));
      geometry.computeBoundingSphere();
      if (!first) return;
      const { center, radius } = geometry.boundingSphere;
      const view = this.summary.camera;
      if (view) {
        this.camera.position.set(...view.position);
        this.controls.target.set(...view.target);
        this.camera.up.set(...view.up);
        this.camera.fov = view.fov;
      } else {
        this.camera.position.set(center.x, center.y, center.z + 2.6 * radius);
        this.controls.target.copy(center);
      }
      this.camera.near = radius / 100;
      this.camera.far = radius * 100;
      this.camera.updateProjectionMatrix();
      this.controls.update();
    }

    show(k) {
      const B = k < this.history.length ? this.history[k] : this.final;
      colours(k < this.history.length ? this.historyColours[k] : this.finalColours, this.triangleElements,
              this.colourArray);
      this.mesh.geometry.attributes.color.needsUpdate = true;
      this.iterationLabel.textContent = 'iteration ' + (k + 1) + ' of ' + this.summary.iterations;
      drawChart(this.chart, this.residuals, k);
      let total = 0;
      for (let i = 0; i < B.length; ++i) total += B[i];
      this.numbers.textContent =
          this.summary.elements + ' elements, ' + (this.summary.method ? this.summary.method + ' form factors, ' : '') +
          this.summary.solver +
          ': ' + this.summary.status + ' after ' + this.summary.iterations + ' iterations; residual ' +
          (k < this.residuals.length ? this.residuals[k].toExponential(2) : '-') +
          '; mean B ' + (total / B.length).toFixed(3) + ' W/m² (computed here in ' +
          this.seconds.toFixed(2) + ' s)';
      this.showCompare(k, B);
      this.render();
    }

    // The compared step at the same iteration (or its last), and how far its B is from this view's.
    showCompare(k, B) {
      const r = this.compareResult;
      if (!r || this.compareView.hidden) return;
      const iterations = r.summary.iterations;
      const j = Math.min(k, iterations - 1);
      const other = j >= 0 && j < r.history.length ? r.history[j] : r.final;
      colours(j >= 0 && j < r.colours.length ? r.colours[j] : r.finalColours,
              r.triangleElements, this.compareColours);
      this.compareMesh.geometry.attributes.color.needsUpdate = true;
      this.caption.textContent = this.describe(this.summary, this.parameters);
      this.compareCaption.textContent = this.describe(r.summary, this.compareParameters());
      let total = 0, largest = 0, top = 0;
      for (let i = 0; i < other.length; ++i) total += other[i];
      if (other.length === B.length) {
        for (let i = 0; i < B.length; ++i) {
          largest = Math.max(largest, Math.abs(other[i] - B[i]));
          top = Math.max(top, Math.abs(B[i]));
        }
      }
      this.compareNumbers.textContent =
          'Beside it, ' + this.describe(r.summary, this.compareParameters()) + ': ' + r.summary.status + ' after ' +
          iterations + ' iterations; iteration ' + (j + 1) + ' shown, residual ' +
          (j >= 0 && j < r.residuals.length ? r.residuals[j].toExponential(2) : '-') + '; mean B ' +
          (total / other.length).toFixed(3) + ' W/m²' +
          (other.length === B.length ? '; largest |ΔB| ' + (top > 0 ? (100 * largest / top).toPrecision(3) : '0') +
                                       ' % of the largest B'
                                     : ' (another mesh)');
    }

    // The element seen at a client position (-1 for none); its B in the iteration shown and its row of F
    // follow in the text below the view.
    pick(clientX, clientY) {
      const r = this.renderer.domElement.getBoundingClientRect();
      const ndc = new THREE.Vector2(((clientX - r.left) / r.width) * 2 - 1, -((clientY - r.top) / r.height) * 2 + 1);
      const ray = new THREE.Raycaster();
      ray.setFromCamera(ndc, this.camera);
      const hit = ray.intersectObject(this.mesh)[0];
      if (!hit) return -1;
      const e = this.triangleElements[hit.faceIndex];
      const k = Number(this.scrubber.value);
      const B = k < this.history.length ? this.history[k] : this.final;
      let text = 'Element ' + e + ': B = (' + [0, 1, 2].map((c) => B[3 * e + c].toFixed(3)).join(', ') + ') W/m²';
      this.picked.textContent = text;
      this.picking = this.request('row', { element: e }).then((row) => {
        if (row.length) {
          let sum = 0;
          const largest = [];
          row.forEach((f, j) => {
            sum += f;
            largest.push([f, j]);
          });
          largest.sort((a, b) => b[0] - a[0]);
          text += '; its row of F sums to ' + sum.toFixed(4) + ', largest ' +
                  largest.slice(0, 3).map(([f, j]) => 'F(' + e + ',' + j + ') = ' + f.toFixed(4)).join(', ');
        }
        this.picked.textContent = text;
      });
      return e;
    }

    toggle() {
      if (this.timer) {
        clearInterval(this.timer);
        this.timer = null;
        this.play.textContent = 'Play';
        return;
      }
      this.play.textContent = 'Pause';
      let k = Number(this.scrubber.value) >= Number(this.scrubber.max) ? 0 : Number(this.scrubber.value);
      this.timer = setInterval(() => {
        this.scrubber.value = String(k);
        this.show(k);
        if (++k > Number(this.scrubber.max)) this.toggle();
      }, 250);
    }

    render() {
      fitToCanvas(this.renderer);
      this.renderer.render(this.scene, this.camera);
      if (this.compareRenderer && !this.compareView.hidden) {
        fitToCanvas(this.compareRenderer);
        this.compareRenderer.render(this.compareScene, this.camera);
      }
    }
  }

  async function start() {
    const containers = document.querySelectorAll('.live-view[data-live]');
    if (containers.length === 0) return;
    window.rtLiveViews = [];
    const started = [];
    for (const container of containers) {
      const view = new LiveView(container, RT_LIVE[container.dataset.live]);
      started.push(view.start().then(() => window.rtLiveViews.push(view), (e) => {
        view.renderer.domElement.remove();
        element('p', { class: 'live-error', text: 'This figure could not be computed here: ' + e.message }, container);
        console.error(e);
      }));
    }
    await Promise.all(started);
    // In the page's order, whichever view finished first.
    const order = Array.from(containers);
    window.rtLiveViews.sort((a, b) => order.indexOf(a.renderer.domElement.closest('.live-view')) -
                                      order.indexOf(b.renderer.domElement.closest('.live-view')));
    document.body.dataset.liveReady = String(window.rtLiveViews.length);
  }

  // For the playground page (playground.js), which makes views of the reader's own scenes.
  // formFactorWorkers: how many workers (the page's worker and its helpers) compute the rows of a large F (one
  // per core; tests set it to compare).
  Object.assign(live, { LiveView, ask, formFactorWorkers: navigator.hardwareConcurrency || 1 });
  window.rtLive = live;
  window.addEventListener('load', () => start());
})();
