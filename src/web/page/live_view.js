// The web edition's live figures. Every <div class="live-view" data-live="KEY"> on a page becomes a 3D view
// of a step computed in the browser by the WebAssembly core (radiosity-core.js): rotate and zoom with the
// mouse, a scrubber with play through the solver's iterations beside the residual chart, and sliders for the
// light and a surface's reflectance, which solve again (the form factors stay cached in the core).
// RT_LIVE[KEY] (the page's <lesson>-live.js) holds the step: its scene files and its settings as JSON.
/* global THREE, RadiosityCore, RT_LIVE */
(function () {
  'use strict';

  let corePromise = null;
  function core() {
    if (!corePromise) corePromise = RadiosityCore();
    return corePromise;
  }

  // The exposure that puts the brightest reflecting element at white.
  function exposureOf(B, emitting) {
    let brightest = 0;
    for (let i = 0; i < B.length / 3; ++i)
      if (!emitting[i]) brightest = Math.max(brightest, B[3 * i], B[3 * i + 1], B[3 * i + 2]);
    return brightest > 0 ? 1 / brightest : 1;
  }

  // Linear tone map at `scale`, then the display's gamma: the desktop figures' default look.
  function colours(B, triangleElements, scale, out) {
    for (let t = 0; t < triangleElements.length; ++t) {
      const e = triangleElements[t];
      for (let c = 0; c < 3; ++c) {
        const v = Math.pow(Math.min(1, Math.max(0, B[3 * e + c] * scale)), 1 / 2.2);
        for (let k = 0; k < 3; ++k) out[9 * t + 3 * k + c] = v;
      }
    }
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

  // One session per scene on a page: the views of its steps share the form factors the core caches by
  // geometry and method, so that the second view of the same mesh only solves.
  const sessions = new Map();
  function sessionFor(step, module) {
    const key = JSON.stringify(step.files) + step.scene;
    if (!sessions.has(key)) {
      const session = new module.Session();
      for (const [name, text] of Object.entries(step.files)) session.putFile(name, text);
      const problem = session.load(step.scene);
      if (problem) throw new Error(problem);
      sessions.set(key, session);
    }
    return sessions.get(key);
  }

  class LiveView {
    constructor(container, step, module) {
      this.step = step;
      this.session = sessionFor(step, module);
      this.settings = Object.assign({}, step.settings);
      this.build(container);
      this.solve();
    }

    build(container) {
      container.classList.add('live-ready');
      const view = element('div', { class: 'live-canvas' }, container);
      this.renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
      this.renderer.setPixelRatio(1);
      this.renderer.setSize(container.clientWidth || 640, Math.round((container.clientWidth || 640) * 0.75));
      view.appendChild(this.renderer.domElement);
      this.scene = new THREE.Scene();
      this.scene.background = new THREE.Color(0x202020);
      this.camera = new THREE.PerspectiveCamera(40, 4 / 3, 0.001, 1e7);
      this.controls = new THREE.OrbitControls(this.camera, this.renderer.domElement);
      this.controls.addEventListener('change', () => this.render());

      const panel = element('div', { class: 'live-panel' }, container);
      const scrub = element('div', { class: 'live-row' }, panel);
      this.play = element('button', { type: 'button', class: 'live-play', text: 'Play' }, scrub);
      this.scrubber = element('input', { type: 'range', min: '0', max: '0', value: '0', class: 'live-scrubber',
                                         'aria-label': 'iteration' }, scrub);
      this.iterationLabel = element('span', { class: 'live-iteration' }, scrub);
      this.chart = element('canvas', { width: '320', height: '150', class: 'live-chart' }, panel);
      this.sliders = {};
      const light = element('label', { class: 'live-row', text: 'Light ' }, panel);
      this.sliders.light = element('input', { type: 'range', min: '0', max: '3', step: '0.05',
                                              value: String(this.settings.lightScale || 1),
                                              class: 'live-light' }, light);
      const surface = this.step.surface;
      if (surface) {
        const rho = element('label', { class: 'live-row', text: 'Reflectance of ' + surface + ' ' }, panel);
        this.sliders.rho = element('input', { type: 'range', min: '0', max: '0.95', step: '0.05',
                                              value: String(this.step.surfaceReflectance),
                                              class: 'live-reflectance' }, rho);
      }
      this.numbers = element('div', { class: 'live-numbers' }, panel);
      this.picked = element('div', { class: 'live-picked', text: 'Click an element to see its B and its row of F.' },
                            panel);
      // A click (not a drag) picks the element under the pointer.
      const canvas = this.renderer.domElement;
      canvas.addEventListener('pointerdown', (e) => (this.down = [e.clientX, e.clientY]));
      canvas.addEventListener('pointerup', (e) => {
        if (this.down && Math.hypot(e.clientX - this.down[0], e.clientY - this.down[1]) < 4)
          this.pick(e.clientX, e.clientY);
      });
      this.scrubber.addEventListener('input', () => this.show(Number(this.scrubber.value)));
      this.play.addEventListener('click', () => this.toggle());
      for (const s of Object.values(this.sliders)) s.addEventListener('change', () => this.change());
    }

    change() {
      this.settings.lightScale = Number(this.sliders.light.value);
      if (this.sliders.rho) {
        const v = Number(this.sliders.rho.value);
        const base = this.step.surfaceColour;
        const top = Math.max(...base, 1e-9);
        this.settings.reflectance = Object.assign({}, this.settings.reflectance,
                                                  { [this.step.surface]: base.map((c) => (c / top) * v) });
      }
      this.solve();
    }

    solve() {
      const started = performance.now();
      const problem = this.session.configure(JSON.stringify(this.settings));
      if (problem) throw new Error(problem);
      const summary = JSON.parse(this.session.run());
      if (summary.error) throw new Error(summary.error);
      this.summary = summary;
      if (!this.mesh) this.makeMesh(summary);
      this.residuals = this.session.residuals();
      // This view's iterations, copied out: the session serves the other views too.
      this.history = [];
      for (let k = 0; k < summary.iterations; ++k) this.history.push(this.session.radiosity(k));
      this.final = this.session.radiosity(-1);
      this.seconds = (performance.now() - started) / 1000;
      const last = Math.max(0, summary.iterations - 1);
      this.scrubber.max = String(last);
      this.scrubber.value = String(last);
      drawChart(this.chart, this.residuals, last);
      this.show(last);
    }

    makeMesh(summary) {
      const positions = this.session.trianglePositions();
      this.triangleElements = this.session.triangleElements();
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
      this.colourArray = new Float32Array(positions.length);
      geometry.setAttribute('color', new THREE.BufferAttribute(this.colourArray, 3));
      const material = new THREE.MeshBasicMaterial({ vertexColors: THREE.VertexColors, side: THREE.FrontSide });
      this.mesh = new THREE.Mesh(geometry, material);
      this.scene.add(this.mesh);
      geometry.computeBoundingSphere();
      const { center, radius } = geometry.boundingSphere;
      const view = summary.camera;
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
      if (this.exposure === undefined) {
        // Fixed at the step's own solution, so that more light or a lighter surface shows brighter.
        const emitting = new Uint8Array(B.length / 3);
        for (const e of this.summary.emitters) emitting[e] = 1;
        this.exposure = exposureOf(this.final, emitting);
      }
      colours(B, this.triangleElements, this.exposure, this.colourArray);
      this.mesh.geometry.attributes.color.needsUpdate = true;
      this.iterationLabel.textContent = 'iteration ' + (k + 1) + ' of ' + this.summary.iterations;
      drawChart(this.chart, this.residuals, k);
      let total = 0;
      for (let i = 0; i < B.length; ++i) total += B[i];
      this.numbers.textContent =
          this.summary.elements + ' elements, ' + this.summary.solver + ': ' + this.summary.status + ' after ' +
          this.summary.iterations + ' iterations; residual ' +
          (k < this.residuals.length ? this.residuals[k].toExponential(2) : '-') +
          '; mean B ' + (total / B.length).toFixed(3) + ' W/m² (computed here in ' +
          this.seconds.toFixed(2) + ' s)';
      this.render();
    }

    // The element seen at a client position: its B in the iteration shown and its row of F.
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
      const row = this.session.formFactorRow(e);
      let text = 'Element ' + e + ': B = (' + [0, 1, 2].map((c) => B[3 * e + c].toFixed(3)).join(', ') + ') W/m²';
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
      this.renderer.render(this.scene, this.camera);
    }
  }

  async function start() {
    const containers = document.querySelectorAll('.live-view[data-live]');
    if (containers.length === 0) return;
    const module = await core();
    window.rtLiveViews = [];
    for (const container of containers) {
      const step = RT_LIVE[container.dataset.live];
      try {
        window.rtLiveViews.push(new LiveView(container, step, module));
      } catch (e) {
        element('p', { class: 'live-error', text: 'This figure could not be computed here: ' + e.message },
                container);
        console.error(e);
      }
    }
    document.body.dataset.liveReady = String(window.rtLiveViews.length);
  }

  // For the playground page (playground.js), which makes views of the reader's own scenes.
  window.rtLive = { core, LiveView };
  window.addEventListener('load', () => start());
})();
