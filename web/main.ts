/**
 * The page: wires input -> core (in the worker) -> trace -> views, in one
 * direction. Inputs change the state; a change of what is traced re-runs
 * the core (debounced); the views show the traces at the state's point.
 *
 * Modes (state.mode): trace (one algorithm), compare (two on the same move),
 * gcode (a program on a machine), experiment (Wang's random lines). Each
 * mode's inputs and results plug into the same scene, timeline, inspector and
 * charts through the RemoteTrace it produces.
 */
import { randomLinesToCsv } from './core/export.js';
import type { RandomLinesResult } from './core/index.js';
import { ComparePanel } from './compare/compare-panel.js';
import { PathCharts } from './charts/path-charts.js';
import { embedding } from './embed/embed.js';
import { download } from './export.js';
import { AlgorithmInputs } from './form/algorithm-inputs.js';
import { OptionsForm } from './form/options-form.js';
import { diagnosticText } from './form/page-advice.js';
import { formatPoint } from './format.js';
import { GcodePanel } from './gcode/gcode-panel.js';
import { TimingDiagram } from './gcode/timing-diagram.js';
import { ExperimentPanel } from './experiment/experiment-panel.js';
import type { DecisionRow } from './inspector/decision-figure.js';
import { Inspector } from './inspector/inspector.js';
import { decisionOverlay, decisionOverlayKinds } from './scene/decision-overlay.js';
import { followControl } from './scene/follow.js';
import { PALETTE } from './scene/palette.js';
import { type SceneCallbacks, SceneView } from './scene/scene-view.js';
import type { Handle } from './scene/endpoint-handles.js';
import { type AppState, type Catalogue, MODES, type Mode, randomLinesExperiment, tracedAlgorithms, traceOptions } from './state/app-state.js';
import { nextTask } from './main-thread.js';
import { loadState, persistState } from './state/persist.js';
import { markStale } from './state/stale.js';
import { Store } from './state/store.js';
import { StepReason } from './timeline/step-reason.js';
import { Timeline, handlesItsOwnKeys } from './timeline/timeline.js';
import { Cancelled, CoreCrash, InputRejected, type RemoteProgram, type RemoteTrace, type Running, TraceClient } from './worker/client.js';
import type { TraceDifference } from './worker/protocol.js';

/** Quiet time after the last keystroke before re-tracing, ms. */
const RETRACE_DELAY_MS = 250;

function byId<T extends HTMLElement>(id: string, kind: new () => T): T {
  const element = document.getElementById(id);
  if (!(element instanceof kind)) throw new Error(`the page has no <${kind.name}> #${id}`);
  return element;
}

/** One colour source for the 3D view and the page's legend and highlights. */
for (const [name, colour] of Object.entries(PALETTE)) {
  document.documentElement.style.setProperty(`--colour-${name}`, colour);
}

/** The alert banner, with one action button. */
function showAlert(message: string, actionText: string, action: () => void): void {
  byId('alert-message', HTMLParagraphElement).textContent = message;
  const button = byId('alert-action', HTMLButtonElement);
  button.textContent = actionText;
  button.onclick = action;
  byId('alert', HTMLDivElement).hidden = false;
}

function hideAlert(): void {
  byId('alert', HTMLDivElement).hidden = true;
}

/** Set once the page is running; a crash before that has no trace to drop. */
let onCoreCrash: ((message: string) => void) | undefined;

/** Set once the page is running: where the view's camera moves and handle drags go. */
let sceneEvents: SceneCallbacks | undefined;
const client = new TraceClient(
  () => new Worker(new URL('./worker/trace-worker.ts', import.meta.url), { type: 'module' }),
  (message) => onCoreCrash?.(message),
);
// Asked first, so the worker starts loading the core at once.
const catalogueLoaded = client.catalogue();

// Made before the core has started, so that the view's shaders compile
// while the worker loads the core (SceneView's warm-up); in a task of its
// own, not in the one that runs this module (both are long on a software GPU).
await nextTask();
const scene = new SceneView(byId('viewport', HTMLDivElement), {
  onCamera: (camera) => sceneEvents?.onCamera(camera),
  onHandle: (name, point) => sceneEvents?.onHandle(name, point),
});

/** What is on screen: the traces the worker holds for the current mode. */
interface Shown {
  a?: RemoteTrace;
  b?: RemoteTrace;
  program?: RemoteProgram;
  difference?: TraceDifference;
  experiment?: RandomLinesResult;
}

/** The state's keys whose change means the core must run again, by mode. */
const INPUT_KEYS: Record<Mode, (keyof AppState)[]> = {
  trace: ['algorithm', 'options'],
  compare: ['algorithm', 'other', 'options'],
  gcode: ['gcode', 'machine'],
  experiment: ['algorithm', 'experiment'],
};

function run(catalogue: Catalogue): void {
  const store = new Store<AppState>(loadState(catalogue));
  persistState(store);
  document.body.classList.toggle('embed', store.state.embed);
  embedding(store, catalogue, {
    open: byId('open-full', HTMLAnchorElement),
    button: byId('embed-open', HTMLButtonElement),
    dialog: byId('embed', HTMLDialogElement),
    snippet: byId('embed-snippet', HTMLTextAreaElement),
    note: byId('embed-note', HTMLParagraphElement),
    copy: byId('embed-copy', HTMLButtonElement),
    copied: byId('embed-copied', HTMLSpanElement),
  });
  const status = byId('trace-status', HTMLParagraphElement);
  const formError = byId('form-error', HTMLParagraphElement);
  const staleNote = byId('stale-note', HTMLParagraphElement);

  // Mode tabs and the parts each mode shows.
  const modeButtons = [...document.querySelectorAll<HTMLButtonElement>('.modes button')];
  for (const button of modeButtons) {
    button.addEventListener('click', () => {
      const mode = MODES.find((m) => m === button.dataset.mode);
      if (mode && mode !== store.state.mode) inputs.switchMode(mode);
    });
  }
  function renderMode(): void {
    const { mode, layout } = store.state;
    document.body.dataset.mode = mode;
    for (const part of document.querySelectorAll<HTMLElement>('.mode-part')) part.hidden = !(part.dataset.modes ?? '').split(' ').includes(mode);
    for (const button of modeButtons) button.setAttribute('aria-pressed', String(button.dataset.mode === mode));
    byId('viewport-b', HTMLDivElement).hidden = !(mode === 'compare' && layout === 'side');
    byId('inputs-heading', HTMLHeadingElement).textContent = { trace: 'Path', compare: 'Two algorithms, one move', gcode: 'G-code program', experiment: 'Random lines' }[mode];
    byId('export-png', HTMLButtonElement).hidden = mode === 'experiment';
    byId('export-json', HTMLButtonElement).hidden = mode === 'experiment';
  }
  renderMode();

  const inputs = new AlgorithmInputs(
    {
      algorithm: byId('algorithm', HTMLSelectElement),
      title: byId('algorithm-title', HTMLElement),
      citation: byId('algorithm-citation', HTMLElement),
      teaching: byId('algorithm-teaching', HTMLParagraphElement),
      errata: byId('algorithm-errata', HTMLUListElement),
      errataBox: byId('algorithm-errata-box', HTMLDetailsElement),
      other: byId('other', HTMLSelectElement),
      otherCitation: byId('other-citation', HTMLElement),
      layout: [...document.querySelectorAll<HTMLInputElement>('input[name=layout]')],
      axes: byId('axes', HTMLSelectElement),
      axesField: byId('axes-field', HTMLDivElement),
      axesHint: byId('axes-hint', HTMLParagraphElement),
      fields: byId('option-fields', HTMLDivElement),
      formError,
    },
    catalogue,
    store,
  );

  const experimentSpecs = randomLinesExperiment(catalogue)?.options ?? [];
  const experimentForm = new OptionsForm(byId('experiment-fields', HTMLDivElement), formError, experimentSpecs, 3, store.state.experiment, (name, value) => {
    const experiment = { ...store.state.experiment };
    if (value === undefined) delete experiment[name];
    else experiment[name] = value;
    store.update({ experiment });
  }, 'experiment');

  const events: SceneCallbacks = {
    onCamera: (camera) => store.update({ camera }),
    onHandle: (name, point) => store.update({ options: { ...store.state.options, [name]: point } }),
  };
  sceneEvents = events;
  let sceneB: SceneView | undefined;
  const view2d = byId('view-2d', HTMLInputElement);
  view2d.addEventListener('change', () => store.update({ projection: view2d.checked ? '2d' : '3d', camera: null }));
  byId('reset-view', HTMLButtonElement).addEventListener('click', () => store.update({ camera: null }));
  followControl(store, byId('follow', HTMLInputElement), () => [scene, sceneB]);
  const decision3d = byId('decision-3d', HTMLInputElement);
  decision3d.addEventListener('change', () => store.update({ decision3d: decision3d.checked }));

  const timeline = new Timeline(
    {
      first: byId('first', HTMLButtonElement),
      previous: byId('previous', HTMLButtonElement),
      play: byId('play', HTMLButtonElement),
      playLabel: byId('play-label', HTMLSpanElement),
      next: byId('next', HTMLButtonElement),
      last: byId('last', HTMLButtonElement),
      scrubber: byId('scrubber', HTMLInputElement),
      counter: byId('step-counter', HTMLOutputElement),
      speed: byId('speed', HTMLSelectElement),
      jump: byId('jump', HTMLFormElement),
      jumpInput: byId('jump-input', HTMLInputElement),
    },
    store,
  );
  const stepReason = new StepReason(byId('step-reason', HTMLParagraphElement));
  /** The decision the inspector shows: the view's decision overlay is drawn from the same values. */
  let decision: { trace: RemoteTrace; pointIndex: number; row: DecisionRow | undefined } | undefined;
  /** The shown decision in the view, when asked for and its step has an overlay. */
  function drawDecision(): void {
    const d = decision;
    scene.setOverlay(store.state.decision3d && d ? decisionOverlay(d.trace, d.pointIndex, d.row) : undefined);
  }
  const inspector = new Inspector({
    point: byId('inspector-point', HTMLElement),
    deviation: byId('inspector-deviation', HTMLElement),
    decisionHeading: byId('decision-heading', HTMLHeadingElement),
    decisions: byId('decision-values', HTMLElement),
    explanation: byId('explanation', HTMLParagraphElement),
    figure: byId('decision-figure', HTMLDivElement),
    columnDocs: byId('column-docs', HTMLElement),
    setupNote: byId('setup-note', HTMLParagraphElement),
  }, (trace, pointIndex, row) => {
    decision = { trace, pointIndex, row };
    drawDecision();
  });
  const goTo = (pointIndex: number) => store.update({ pointIndex, playing: false });
  const charts = new PathCharts(byId('charts', HTMLDivElement), goTo);
  const comparePanel = new ComparePanel(byId('comparison', HTMLDivElement), goTo);
  const timing = new TimingDiagram(byId('timing', HTMLDivElement), goTo);
  const experimentPanel = new ExperimentPanel(byId('experiment-view', HTMLDivElement), store, catalogue);

  let shown: Shown = {};
  /** Counts runs of the core, so only the latest one's answer is shown. */
  let latestRun = 0;
  let running: Running<RemoteProgram> | undefined;

  const gcodePanel = new GcodePanel(
    {
      sample: byId('sample', HTMLSelectElement),
      text: byId('gcode-text', HTMLTextAreaElement),
      listing: byId('gcode-listing', HTMLDivElement),
      longNote: byId('gcode-long', HTMLParagraphElement),
      editAnyway: byId('gcode-edit-anyway', HTMLButtonElement),
      gutter: byId('gcode-gutter', HTMLPreElement),
      problems: byId('gcode-problems', HTMLDivElement),
      backdrop: byId('gcode-backdrop', HTMLPreElement),
      machine: byId('machine-fields', HTMLDivElement),
      formError,
      run: byId('gcode-run', HTMLButtonElement),
      progress: byId('gcode-progress', HTMLProgressElement),
      cancel: byId('gcode-cancel', HTMLButtonElement),
      moves: byId('moves', HTMLDivElement),
    },
    catalogue,
    store,
    {
      onPick: (_line, steps) => {
        const program = shown.program;
        if (!program) return;
        const cells = program.points.subarray((steps.firstStep + 1) * program.dims, (steps.firstStep + steps.steps + 1) * program.dims);
        scene.setHighlights([{ cells, dims: program.dims, colour: PALETTE.onlyFirst }]);
        goTo(steps.steps > 0 ? steps.firstStep + steps.steps : steps.pointBefore);
      },
      onColumns: (names) => inspector.showColumns(names),
      onRun: () => void retrace(),
      onCancel: () => running?.cancel(),
    },
  );

  /** Handles on the move's points: the point options the traced algorithms take (from, to, center). */
  function handles(): Handle[] {
    const { mode, options } = store.state;
    if (mode !== 'trace' && mode !== 'compare') return [];
    const names = new Set(tracedAlgorithms(store.state, catalogue.algorithms).flatMap((a) => a.options.filter((o) => o.kind.type === 'point').map((o) => o.name)));
    return [...names].flatMap((name) => {
      const point = options[name];
      return Array.isArray(point) && point.every(Number.isFinite) ? [{ name, point }] : [];
    });
  }

  /** Builds the views for what is now shown. */
  function present(): void {
    const state = store.state;
    const { a, b, program, difference } = shown;
    const main = program ?? a;
    const steps = Math.max(main?.steps ?? 0, b?.steps ?? 0);
    const pointIndex = Math.min(state.pointIndex, steps);
    const side = state.mode === 'compare' && state.layout === 'side';
    scene.setTrace(main, Math.min(pointIndex, main?.steps ?? 0), state.projection, state.camera);
    if (state.mode === 'compare' && !side) scene.setSecond(b);
    if (side) {
      sceneB ??= new SceneView(byId('viewport-b', HTMLDivElement), events, 'second path view', PALETTE.second);
      sceneB.setTrace(b, Math.min(pointIndex, b?.steps ?? 0), state.projection, state.camera);
    } else {
      sceneB?.setTrace(undefined, 0, state.projection, null);
    }
    if (difference && a && b) {
      const onlyA = { cells: difference.onlyInA, dims: a.dims, colour: PALETTE.onlyFirst };
      const onlyB = { cells: difference.onlyInB, dims: b.dims, colour: PALETTE.onlySecond };
      if (side) {
        scene.setHighlights([onlyA]);
        sceneB?.setHighlights([onlyB]);
      } else {
        scene.setHighlights([onlyA, onlyB]);
      }
    }
    view2d.checked = state.projection === '2d' && scene.planar;
    view2d.disabled = !scene.planar;
    view2d.parentElement!.title = scene.planar ? 'Orthographic view of the path\'s plane, with the pixel grid' : 'The path is not in one plane';
    const overlays = decisionOverlayKinds(main?.columns ?? []);
    decision3d.checked = state.decision3d;
    decision3d.disabled = overlays.length === 0;
    byId('decision-3d-label', HTMLLabelElement).title =
      overlays.length > 0
        ? `The current step's decision in the view: ${overlays.join('; or ')}.`
        : "This algorithm's decisions have no 3D picture: only the discriminate regions' exit face and the circle's candidates do";
    scene.setHandles(handles());
    decision = undefined;
    inspector.setTrace(main, Math.min(pointIndex, main?.steps ?? 0));
    stepReason.setTraces(state.mode === 'compare' ? [a, b] : [main], pointIndex);
    void charts.setTrace(main);
    comparePanel.show(a, b, difference);
    gcodePanel.setProgram(program);
    timing.setTrace(program, pointIndex);
    if (program) void gcodePanel.showPoint(pointIndex);
    // Last: it may clamp the step to a shorter path, and every view must hold the new traces by then.
    timeline.setSteps(main || b ? steps : undefined);
    // Compared, the inspector follows the first path only: say which.
    byId('inspector-heading', HTMLHeadingElement).textContent = state.mode === 'compare' ? `Current point of ${a?.algorithm ?? 'the first'}` : 'Current point';
    byId('legend-visited', HTMLSpanElement).textContent = state.mode === 'compare' ? `visited by ${a?.algorithm ?? 'the first'}` : 'visited';
    byId('legend-second-name', HTMLSpanElement).textContent = `${b?.algorithm ?? 'second'}${side ? ' (right view)' : ''}`;
    byId('legend-only-first', HTMLSpanElement).textContent = `only ${a?.algorithm ?? 'first'} visits`;
    byId('legend-only-second', HTMLSpanElement).textContent = `only ${b?.algorithm ?? 'second'} visits`;
  }

  function freeShown(): void {
    shown.a?.free();
    shown.b?.free();
    shown.program?.free();
    shown = {};
  }

  function statusOf(trace: RemoteTrace): string {
    const m = trace.metrics;
    const bound = trace.deviationBound;
    return (
      `${trace.algorithm}: ${trace.steps} steps from ${formatPoint(trace.start)} to ${formatPoint(trace.end)}; ` +
      `largest distance from the ideal path ${m.maxDeviation.toFixed(3)}` +
      (bound ? ` (the rule keeps it within ${bound.value.toFixed(3)}: ${bound.why})` : '') +
      `; ${m.ties} ${m.ties === 1 ? 'tie' : 'ties'}.`
    );
  }

  async function retrace(): Promise<void> {
    const run = ++latestRun;
    const state = store.state;
    running?.cancel();
    running = undefined;
    gcodePanel.setProgress(undefined);
    status.textContent = state.mode === 'experiment' ? 'Tracing the lines…' : 'Tracing…';
    try {
      let next: Shown;
      if (state.mode === 'trace') {
        const [info] = tracedAlgorithms(state, catalogue.algorithms);
        next = { a: await client.trace(traceOptions(state, info!)) };
      } else if (state.mode === 'compare') {
        const [infoA, infoB] = tracedAlgorithms(state, catalogue.algorithms);
        const [a, b] = await Promise.all([client.trace(traceOptions(state, infoA!)), client.trace(traceOptions(state, infoB!))]);
        next = { a, b, difference: await client.difference(a, b) };
      } else if (state.mode === 'gcode') {
        const started = client.runGcode(state.gcode, state.machine, (progress) => {
          if (run === latestRun) {
            gcodePanel.setProgress(progress);
            status.textContent = `Running: line ${progress.linesDone} of ${progress.lines}, ${progress.steps} steps so far…`;
          }
        });
        running = started;
        next = { program: await started.result };
      } else {
        next = { experiment: await client.randomLines({ algorithm: state.algorithm, ...state.experiment }) };
      }
      if (run !== latestRun) {
        for (const t of [next.a, next.b, next.program]) t?.free();
        return;
      }
      hideAlert();
      inputs.showCoreError(undefined);
      gcodePanel.showCoreError(undefined);
      experimentForm.showCoreError(undefined);
      markStale(staleNote, undefined);
      freeShown();
      shown = next;
      if (next.experiment) {
        experimentPanel.show(next.experiment);
        status.textContent = `${next.experiment.lines.length} lines traced with ${next.experiment.algorithm}.`;
        return;
      }
      present();
      if (next.program) {
        const p = next.program.program;
        status.textContent =
          `${p.lines} lines, ${p.moveCount} moves, ${p.steps} steps at ${p.stepsPerMm.join(' / ')} steps/mm` +
          `${p.errors.length ? `; stopped at line ${p.stoppedAtLine}: ${diagnosticText(p.errors[0]!)}` : ''}` +
          `${p.warnings.length ? `; ${p.warnings.length + p.warningsOmitted} warnings` : ''}.`;
      } else {
        status.textContent = [next.a, next.b].filter((t) => t !== undefined).map(statusOf).join(' ');
      }
    } catch (error) {
      if (run !== latestRun || error instanceof CoreCrash) return;
      if (error instanceof Cancelled) {
        status.textContent = 'Cancelled. The view still shows the last program that ran.';
        if (shown.program) markStale(staleNote, 'cancelled');
      } else if (error instanceof InputRejected) {
        if (Object.keys(shown).length > 0) markStale(staleNote, 'rejected');
        if (state.mode === 'gcode') gcodePanel.showCoreError(error);
        else if (state.mode === 'experiment') experimentForm.showCoreError(error);
        else inputs.showCoreError(error);
        status.textContent = shown.a || shown.program ? 'Not traced: see the message above. The view still shows the last valid path.' : 'Not traced: see the message above.';
      } else {
        // Not the input's fault: a bug in the page's request, reported as one.
        console.error(error);
        status.textContent = `Not traced, because of a bug in voxpath: ${String(error)}`;
      }
    } finally {
      if (run === latestRun) {
        running = undefined;
        gcodePanel.setProgress(undefined);
      }
    }
  }

  onCoreCrash = (message) => {
    // The traces died with their worker: drop them rather than show values that can no longer be explained.
    shown = {};
    present();
    status.textContent = '';
    showAlert(`The core stopped with an internal error, a bug in voxpath: ${message}. It has been restarted.`, 'Trace again', () => {
      hideAlert();
      void retrace();
    });
  };

  // Exports: the trace on screen as the CLI writes it, the view as a PNG.
  const exportName = () => (store.state.mode === 'gcode' ? 'program' : store.state.algorithm);
  /** The traces on screen and their file names: the program, or the trace, or both compared ones, each under its algorithm's id. */
  const exported = (): [RemoteTrace, string][] => {
    if (shown.program) return [[shown.program, 'program']];
    return [shown.a, shown.b].filter((t) => t !== undefined).map((t) => [t, t.algorithm]);
  };
  byId('export-csv', HTMLButtonElement).addEventListener('click', async () => {
    if (shown.experiment) return download(`random-lines-${shown.experiment.algorithm}.csv`, new Blob([randomLinesToCsv(shown.experiment)], { type: 'text/csv' }));
    for (const [trace, name] of exported()) download(`${name}-steps.csv`, new Blob([await trace.exportAs('csv')], { type: 'text/csv' }));
  });
  byId('export-json', HTMLButtonElement).addEventListener('click', async () => {
    for (const [trace, name] of exported()) download(`${name}-steps.json`, new Blob([await trace.exportAs('json')], { type: 'application/json' }));
  });
  byId('export-png', HTMLButtonElement).addEventListener('click', async () => {
    download(`${exportName()}-view.png`, await scene.toPng());
  });

  // The keyboard help: '?' or the button opens it, Escape (the dialog's own) closes it.
  const help = byId('help', HTMLDialogElement);
  byId('help-open', HTMLButtonElement).addEventListener('click', () => help.showModal());
  document.addEventListener('keydown', (event) => {
    if (event.key === '?' && !handlesItsOwnKeys(event.target, event.key) && !help.open) {
      event.preventDefault();
      help.showModal();
    }
  });

  let retraceTimer: ReturnType<typeof setTimeout> | undefined;
  store.subscribe((state, previous) => {
    if (state.mode !== previous.mode || state.layout !== previous.layout) renderMode();
    const inputsChanged = state.mode !== previous.mode || INPUT_KEYS[state.mode].some((k) => state[k] !== previous[k]);
    if (inputsChanged) {
      clearTimeout(retraceTimer);
      retraceTimer = setTimeout(() => void retrace(), RETRACE_DELAY_MS);
      if (state.options !== previous.options) scene.setHandles(handles());
    } else if (state.layout !== previous.layout || state.projection !== previous.projection || (state.camera === null && previous.camera !== null)) {
      present();
    } else if (state.camera && state.camera !== previous.camera) {
      scene.setCamera(state.camera);
      sceneB?.setCamera(state.camera);
    }
    if (state.decision3d !== previous.decision3d) {
      decision3d.checked = state.decision3d;
      drawDecision();
    }
    if (state.mode === 'gcode') gcodePanel.render();
    experimentForm.setValues(state.experiment);
    if (state.pointIndex !== previous.pointIndex) {
      const k = state.pointIndex;
      const main = shown.program ?? shown.a;
      scene.showPoint(Math.min(k, main?.steps ?? 0));
      sceneB?.showPoint(Math.min(k, shown.b?.steps ?? 0));
      if (main) inspector.show(Math.min(k, main.steps));
      stepReason.show(k);
      charts.showPoint(k);
      timing.showPoint(k);
      if (shown.program) void gcodePanel.showPoint(k);
    }
  });
  void retrace();
}

catalogueLoaded.then(run, (error: unknown) => {
  showAlert(`The core could not start: ${String(error)}`, 'Reload the page', () => window.location.reload());
});
