// The web edition's worker (live_view.js starts it): the WebAssembly core's sessions run in a Web Worker made
// from a Blob, which a page opened from file:// may start (a worker script from a file URL it may not). The
// worker's text is this file's workerMain and workerScript with the core's module factory; it answers the
// page's requests one at a time and, for a large F whose rows are independent, spreads the rows over helpers
// of its own. window.rtLiveWorkerScript() gives the text to start it from.
/* global RadiosityCore */
(function () {
  'use strict';
  // ---- The worker: this function's source and the core's run in a Web Worker made from a Blob, which a
  // page opened from file:// may start (a worker script from a file URL it may not).
  function workerMain() {
    /* global RadiosityCore, workerScript */
    // The module compiled, kept to hand to helpers: a helper instantiates it instead of decoding and compiling
    // the WebAssembly again, and runs the code this worker's engine has already optimised.
    let compiled = null;
    let ready = null;
    function start(given) {
      if (ready) return ready;
      if (given) {
        compiled = given;
        ready = RadiosityCore({ instantiateWasm: (imports, receive) => {
          WebAssembly.instantiate(given, imports).then((instance) => receive(instance, given));
          return {};
        } });
        return ready;
      }
      const instantiate = WebAssembly.instantiate;
      WebAssembly.instantiate = (source, imports) => instantiate.call(WebAssembly, source, imports).then((result) => {
        if (result && result.module instanceof WebAssembly.Module) compiled = result.module;
        return result;
      });
      ready = RadiosityCore().finally(() => (WebAssembly.instantiate = instantiate));
      return ready;
    }
    const sessions = new Map();
    // Below this many elements one worker computes F in well under a second: helpers would cost more to
    // start than they save.
    const kSpreadFrom = 2000;
    // The rows this worker computes between reading the helpers' answers (about 40 ms of the hemicube's).
    const kOwnBlock = 48;

    function sessionFor(module, a) {
      if (!sessions.has(a.sessionKey)) {
        const session = new module.Session();
        for (const [name, text] of Object.entries(a.files)) session.putFile(name, text);
        const problem = session.load(a.scene);
        if (problem) {
          session.delete();
          throw new Error(problem);
        }
        sessions.set(a.sessionKey, { session, ran: null, configured: null });
      }
      return sessions.get(a.sessionKey);
    }

    // A session's memory back to the module's allocator (F alone is 200 MB at 5,000 elements), in this worker
    // and in its helpers.
    function closeSession(key) {
      const s = sessions.get(key);
      if (s) s.session.delete();
      sessions.delete(key);
      for (const ask of helpers) ask('close', { sessionKey: key }).catch(() => {});
    }

    function configure(s, step) {
      const text = JSON.stringify(step);
      if (s.configured === text) return;
      s.configured = null;
      const problem = s.session.configureStep(text);
      if (problem) throw new Error(problem);
      s.configured = text;
    }

    // Helpers: workers of this same script, each with its own module and session, that compute blocks of
    // rows of F. Pages opened from file:// have no shared memory, so the rows come back as transferables and
    // are copied into this worker's F.
    const helpers = [];
    function helper() {
      const worker = new Worker(URL.createObjectURL(new Blob([workerScript()], { type: 'text/javascript' })));
      if (compiled) {
        try {
          worker.postMessage({ module: compiled });
        } catch (error) {
          // An engine that cannot pass a module to a worker: the helper compiles its own.
        }
      }
      const waiting = new Map();
      let next = 0;
      worker.onmessage = (e) => {
        const request = waiting.get(e.data.id);
        if (!request || 'progress' in e.data) return;
        waiting.delete(e.data.id);
        if ('error' in e.data) request.reject(new Error(e.data.error));
        else request.resolve(e.data.result);
      };
      return (op, args) => new Promise((resolve, reject) => {
        const id = ++next;
        waiting.set(id, { resolve, reject });
        worker.postMessage({ id, op, args });
      });
    }

    // How many workers compute a large F's rows: this one and its helpers.
    const workerCount = (a) => Math.min(Math.max(1, Math.floor(a.workers || 1)), 16);
    // The helpers, started and each asked to instantiate the module. Called once a solve has answered too,
    // so that a change that needs them later (a finer mesh) does not wait for their start.
    function startHelpers(a) {
      while (helpers.length < workerCount(a) - 1) {
        const ask = helper();
        helpers.push(ask);
        ask('ready', {}).catch(() => {});
      }
    }

    // F's rows spread over `a.workers` workers, this one and helpers, when the step needs new form factors
    // whose rows are independent (the hemicube's: the session's rowPlan) on a mesh large enough. This worker
    // computes small blocks straight into F and reads the helpers' answers between them; a helper always has
    // two blocks asked of it, so that it computes on meanwhile, and its rows come back as transferables to be
    // copied in. Blocks are a share of the rows left, so that all workers finish together (and this one
    // computes from the start, while the helpers start up). The progress bar counts the rows in.
    // The rows are those one worker computes, bit for bit, so the solve that follows is too.
    async function spreadRows(s, a, report) {
      const count = workerCount(a);
      const n = count > 1 ? s.session.rowPlan() : 0;
      if (n < kSpreadFrom) return;
      startHelpers(a);
      const stage = 'form factors (' + count + ' workers)';
      let next = 0, done = 0;
      const take = (most) => {
        if (next >= n) return null;
        const begin = next, share = Math.max(kOwnBlock, Math.ceil((n - begin) / (3 * count)));
        next = Math.min(n, begin + Math.min(most, share));
        return [begin, next];
      };
      const stored = (begin, end) => {
        done += end - begin;
        report(done / n, stage);
      };
      report(0, stage);
      const request = { sessionKey: a.sessionKey, files: a.files, scene: a.scene, step: a.step };
      const helperWork = async (ask) => {
        const asked = [];
        const askFor = () => {
          const range = take(n);
          if (!range) return;
          const answer = ask('rows', Object.assign({ begin: range[0], end: range[1] }, request))
            .then((rows) => [range, rows]);
          answer.catch(() => {});  // awaited in order below
          asked.push(answer);
        };
        askFor();
        askFor();
        while (asked.length) {
          const [[begin, end], rows] = await asked.shift();
          if (!s.session.putFormFactorRows(begin, end, rows)) throw new Error('rows ' + begin + '-' + end + ' are not this mesh\'s');
          stored(begin, end);
          askFor();
        }
      };
      const ownWork = async () => {
        for (let range; (range = take(kOwnBlock));) {
          if (!s.session.fillFormFactorRows(range[0], range[1])) throw new Error('rows ' + range[0] + '-' + range[1] + ' could not be computed');
          stored(range[0], range[1]);
          await answersIn();
        }
      };
      await Promise.all([ownWork(), ...helpers.slice(0, count - 1).map(helperWork)]);
    }

    // Lets the messages waiting for this worker in (a message to itself queues behind them; a timer would
    // wait milliseconds).
    const channel = new MessageChannel();
    function answersIn() {
      return new Promise((resolve) => {
        channel.port1.onmessage = () => resolve();
        channel.port2.postMessage(0);
      });
    }

    // The views of one scene share its session: before reading F, make sure it holds this view's run.
    async function runStep(s, a, report) {
      configure(s, a.step);
      await spreadRows(s, a, report);
      const summary = JSON.parse(s.session.runWithProgress(report));
      s.configured = null;  // a run takes the plan of rows with it
      if (summary.error) throw new Error(summary.error);
      s.ran = JSON.stringify(a.step);
      return summary;
    }

    // The solve and what the view shows of it: every iteration's B as colours through the app's display
    // pipeline (exposure, tone map and gamma as the step sets them; `exposure` kept from the view's first
    // solve, so that more light shows brighter).
    async function solve(s, a, id) {
      const started = performance.now();
      const summary = await runStep(s, a, (fraction, stage) => self.postMessage({ id, progress: fraction, stage }));
      const p = a.step.parameters;
      const toneMap = p['tone-map'] || 'linear', gamma = p.gamma !== 'false';
      const exposure = a.exposure || s.session.displayExposure(Number(p.exposure || 0), toneMap);
      const ran = performance.now();
      const history = [], colours = [];
      for (let k = 0; k < summary.iterations; ++k) {
        history.push(s.session.radiosity(k));
        colours.push(s.session.displayColours(k, exposure, toneMap, gamma));
      }
      const result = { summary, history, colours, exposure, final: s.session.radiosity(-1),
                       finalColours: s.session.displayColours(-1, exposure, toneMap, gamma),
                       residuals: s.session.residuals(), positions: s.session.trianglePositions(),
                       triangleElements: s.session.triangleElements() };
      // Where the time went (the page adds the transfer and the repaint): the core's run and the copies out.
      result.phases = { run: (ran - started) / 1000, copies: (performance.now() - ran) / 1000 };
      const buffers = [result.final, result.finalColours, result.residuals, result.positions, result.triangleElements,
                       ...history, ...colours];
      return [result, buffers.map((b) => b.buffer)];
    }

    async function handle(module, id, op, a) {
      if (op === 'ready') return [true];
      if (op === 'close') {
        closeSession(a.sessionKey);
        return [true];
      }
      if (op === 'sessions') return [sessions.size];
      if (op === 'controls') return [JSON.parse(module.controlRows(JSON.stringify(a.keys)))];
      const s = sessionFor(module, a);
      if (op === 'solve') return solve(s, a, id);
      if (op === 'rows') {  // a helper's block of rows
        configure(s, a.step);
        const rows = s.session.formFactorRows(a.begin, a.end);
        return [rows, [rows.buffer]];
      }
      if (s.ran !== JSON.stringify(a.step)) await runStep(s, a, () => {});
      if (op === 'row') return [s.session.formFactorRow(a.element)];
      if (op === 'hemicube') return [s.session.hemicubeFigure(a.element, a.resolution, a.width, a.height)];
      if (op === 'csv') return [s.session.csv()];
      if (op === 'matrix') return [s.session.formFactorFile(a.format)];
      throw new Error('unknown request ' + op);
    }

    // One request at a time, in the order asked: a request that waits for helpers must not let another run
    // on its session meanwhile.
    let queue = Promise.resolve();
    self.onmessage = (e) => {
      if (e.data.module) return void start(e.data.module);
      const { id, op, args } = e.data;
      queue = queue.then(async () => {
        try {
          const [result, transfer] = await handle(await start(), id, op, args);
          self.postMessage({ id, result }, transfer || []);
          if (op === 'solve') startHelpers(args);
        } catch (error) {
          self.postMessage({ id, error: String((error && error.message) || error) });
        }
      });
    };
  }

  // The worker's script: the module factory, workerMain and this function, so that a worker can start
  // helpers of its own from the same text. RadiosityCore (radiosity-core.js, loaded by the page) is
  // Emscripten's module factory; it reads one variable of its wrapper, the script's folder, which a module
  // with the WebAssembly embedded never uses.
  function workerScript() {
    return 'var _scriptDir;\nvar RadiosityCore = (' + RadiosityCore.toString() + ');\n' + workerMain.toString() +
           '\n' + workerScript.toString() + '\nworkerMain();\n';
  }

  window.rtLiveWorkerScript = workerScript;
})();
