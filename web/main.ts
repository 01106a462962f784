/**
 * The page: wires input -> core (in the worker) -> trace -> views, in one
 * direction. The form and the timeline change the state; a change of options
 * re-traces (debounced); the scene, timeline and inspector show the trace at
 * the state's point.
 */
import type { AlgorithmInfo } from './core/types.js';
import { OptionsForm } from './form/options-form.js';
import { formatPoint } from './format.js';
import { Inspector } from './inspector/inspector.js';
import { PALETTE } from './scene/palette.js';
import { SceneView } from './scene/scene-view.js';
import { type AppState, traceOptions } from './state/app-state.js';
import { loadState, persistState } from './state/persist.js';
import { Store } from './state/store.js';
import { Timeline } from './timeline/timeline.js';
import { CoreCrash, InputRejected, type RemoteTrace, TraceClient } from './worker/client.js';

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

const client = new TraceClient(
  () => new Worker(new URL('./worker/trace-worker.ts', import.meta.url), { type: 'module' }),
  (message) => onCoreCrash?.(message),
);

function run(catalogue: AlgorithmInfo[]): void {
  const store = new Store<AppState>(loadState(catalogue));
  persistState(store);
  const info = catalogue.find((a) => a.id === store.state.algorithm)!;
  byId('algorithm-title', HTMLElement).textContent = info.title;
  byId('algorithm-citation', HTMLElement).textContent = info.citation;

  const status = byId('trace-status', HTMLParagraphElement);
  const form = new OptionsForm(byId('option-fields', HTMLDivElement), byId('form-error', HTMLParagraphElement), info, store.state.options, (name, value) => {
    const options = { ...store.state.options };
    if (value === undefined) delete options[name];
    else options[name] = value;
    store.update({ options });
  });
  const scene = new SceneView(byId('viewport', HTMLDivElement));
  byId('reset-view', HTMLButtonElement).addEventListener('click', () => scene.resetView());
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
    },
    store,
  );
  const inspector = new Inspector({
    point: byId('inspector-point', HTMLElement),
    deviation: byId('inspector-deviation', HTMLElement),
    decisionHeading: byId('decision-heading', HTMLHeadingElement),
    decisions: byId('decision-values', HTMLElement),
    explanation: byId('explanation', HTMLParagraphElement),
    columnDocs: byId('column-docs', HTMLElement),
    setupNote: byId('setup-note', HTMLParagraphElement),
  });

  /** The trace on screen; the worker holds it until it is replaced. */
  let shown: RemoteTrace | undefined;
  /** Counts trace requests, so only the latest one's answer is shown. */
  let latestRequest = 0;

  function show(trace: RemoteTrace | undefined): void {
    shown?.free();
    shown = trace;
    const pointIndex = trace ? Math.min(store.state.pointIndex, trace.steps) : 0;
    scene.setTrace(trace, pointIndex);
    inspector.setTrace(trace, pointIndex);
    timeline.setSteps(trace?.steps);
  }

  async function retrace(): Promise<void> {
    const request = ++latestRequest;
    status.textContent = 'Tracing…';
    try {
      const trace = await client.trace(traceOptions(store.state));
      if (request !== latestRequest) {
        trace.free();
        return;
      }
      hideAlert();
      form.showCoreError(undefined);
      show(trace);
      const m = trace.metrics;
      status.textContent =
        `${trace.steps} steps from ${formatPoint(trace.start)} to ${formatPoint(trace.end)}; ` +
        `largest distance from the ideal path ${m.maxDeviation.toFixed(3)}; ${m.ties} ${m.ties === 1 ? 'tie' : 'ties'}.`;
    } catch (error) {
      if (request !== latestRequest || error instanceof CoreCrash) return;
      if (error instanceof InputRejected) {
        form.showCoreError(error);
        status.textContent = shown ? 'Not traced: see the message above. The view still shows the last valid path.' : 'Not traced: see the message above.';
      } else {
        // Not the input's fault: a bug in the page's request, reported as one.
        console.error(error);
        status.textContent = `Not traced, because of a bug in voxpath: ${String(error)}`;
      }
    }
  }

  onCoreCrash = (message) => {
    // The trace died with its worker: drop it rather than show values that can no longer be explained.
    show(undefined);
    status.textContent = '';
    showAlert(`The core stopped with an internal error, a bug in voxpath: ${message}. It has been restarted.`, 'Trace again', () => {
      hideAlert();
      void retrace();
    });
  };

  let retraceTimer: ReturnType<typeof setTimeout> | undefined;
  store.subscribe((state, previous) => {
    if (state.options !== previous.options || state.algorithm !== previous.algorithm) {
      clearTimeout(retraceTimer);
      retraceTimer = setTimeout(() => void retrace(), RETRACE_DELAY_MS);
    }
    if (shown && state.pointIndex !== previous.pointIndex) {
      scene.showPoint(state.pointIndex);
      inspector.show(state.pointIndex);
    }
  });
  void retrace();
}

client.catalogue().then(run, (error: unknown) => {
  showAlert(`The core could not start: ${String(error)}`, 'Reload the page', () => window.location.reload());
});
