/**
 * The page's entry: it finds the page's elements, makes the parts that show
 * and edit them, and wires them to one another. What runs the core and
 * feeds the views is the orchestrator (page/orchestrator.ts); the status
 * line, the exports and the keyboard help have modules of their own (page/).
 */
import { PathCharts } from './charts/path-charts.js';
import { CheckPanel } from './check/check-panel.js';
import { ComparePanel } from './compare/compare-panel.js';
import { embedding } from './embed/embed.js';
import { ExperimentPanel } from './experiment/experiment-panel.js';
import { AlgorithmInputs } from './form/algorithm-inputs.js';
import { OptionsForm } from './form/options-form.js';
import { RunProgress } from './form/run-progress.js';
import { grouped, sentence } from './format.js';
import { GcodePanel } from './gcode/gcode-panel.js';
import { TimingDiagram } from './gcode/timing-diagram.js';
import { TimeViews } from './page/time-views.js';
import { Inspector } from './inspector/inspector.js';
import { nextTask } from './main-thread.js';
import { showAlert } from './page/alert.js';
import { byId } from './page/dom.js';
import { wireExports } from './page/export.js';
import { wireHelp } from './page/help.js';
import { ModeTabs } from './page/mode-tabs.js';
import { Orchestrator } from './page/orchestrator.js';
import { PathViews } from './page/path-views.js';
import { Status } from './page/status.js';
import { lightDrawingCells } from './scene/cells.js';
import { followControl } from './scene/follow.js';
import { PALETTE } from './scene/palette.js';
import { SceneView } from './scene/scene-view.js';
import { SAMPLED_POINTS } from './scene/voxel-path.js';
import { type AppState, type Catalogue, randomLinesExperiment } from './state/app-state.js';
import { loadState, persistState } from './state/persist.js';
import type { LinkNotes } from './state/query.js';
import { Store } from './state/store.js';
import { StepReason } from './timeline/step-reason.js';
import { Timeline } from './timeline/timeline.js';
import { TraceClient } from './worker/client.js';

/** One colour source for the 3D view and the page's legend and highlights. */
for (const [name, colour] of Object.entries(PALETTE)) {
  document.documentElement.style.setProperty(`--colour-${name}`, colour);
}

/** Set once the page runs; a crash before that has no trace to drop, and no camera move or handle drag happens before a path is drawn. */
let orchestrator: Orchestrator | undefined;
let views: PathViews | undefined;

const client = new TraceClient(
  () => new Worker(new URL('./worker/trace-worker.ts', import.meta.url), { type: 'module' }),
  (message) => orchestrator?.coreCrashed(message),
  // The points the 3D view draws of a path: a short one's every cell, a long one's sample.
  () => ({ allBelow: lightDrawingCells(), sampled: SAMPLED_POINTS }),
);
// Asked first, so the worker starts loading the core at once.
const catalogueLoaded = client.catalogue();

// Made before the core has started, so that the view's shaders compile
// while the worker loads the core (SceneView's warm-up); in a task of its
// own, not in the one that runs this module (both are long on a software GPU).
await nextTask();
const scene = new SceneView(byId('viewport', HTMLDivElement), {
  onCamera: (camera) => views?.events.onCamera(camera),
  onHandle: (name, point) => views?.events.onHandle(name, point),
});

function run(catalogue: Catalogue): void {
  const notes: LinkNotes = { unread: [], fitted: [] };
  const store = new Store<AppState>(loadState(catalogue, notes));
  // A link's values the page cannot read were taken as their defaults, a key it gives twice by its first value, its points fitted to the axes shown, and (said once traced: firstPaths) its step past the path's end shown at the end, without a word.
  const linkNote = byId('link-note', HTMLParagraphElement);
  const unread = notes.unread.length > 0 ? [`Not understood in this link, so left at their defaults: ${notes.unread.join(', ')}.`] : [];
  const repeated = notes.repeated ? [`Given more than once in this link, so read by its first value: ${notes.repeated.join(', ')}.`] : [];
  const linkSentences = [...unread, ...repeated, ...notes.fitted.map(sentence)];
  const showLinkNote = () => {
    linkNote.textContent = linkSentences.join(' ');
    linkNote.hidden = linkSentences.length === 0;
  };
  showLinkNote();
  const storageNote = byId('storage-note', HTMLParagraphElement);
  const tabsNote = byId('tabs-note', HTMLParagraphElement);
  const storageBlocked = byId('storage-blocked', HTMLParagraphElement);
  persistState(store, catalogue, {
    onKept: (kept) => {
      storageNote.hidden = kept;
      storageNote.textContent = kept
        ? ''
        : "Too large for the browser's storage (a few MB): the program, your points, or the replaced program offered back will not come back after a reload or on a new visit, which open on the sample program (or without the points, or the offer). Save the text as a file to keep it.";
    },
    onOtherTab: (note) => {
      tabsNote.hidden = note === '';
      tabsNote.textContent = note;
    },
    onBlocked: (note) => {
      storageBlocked.textContent = note;
      storageBlocked.hidden = false;
    },
  });
  document.body.classList.toggle('embed', store.state.embed);
  embedding(store, catalogue, {
    open: byId('open-full', HTMLAnchorElement),
    stage: byId('stage', HTMLElement),
    button: byId('embed-open', HTMLButtonElement),
    dialog: byId('embed', HTMLDialogElement),
    snippet: byId('embed-snippet', HTMLTextAreaElement),
    note: byId('embed-note', HTMLParagraphElement),
    copy: byId('embed-copy', HTMLButtonElement),
    copied: byId('embed-copied', HTMLSpanElement),
  });
  const formError = byId('form-error', HTMLParagraphElement);
  const goTo = (pointIndex: number) => page.goTo(pointIndex);

  const modeTabs = new ModeTabs(
    {
      buttons: [...document.querySelectorAll<HTMLButtonElement>('.modes button')],
      parts: [...document.querySelectorAll<HTMLElement>('.mode-part')],
      secondViewport: byId('viewport-b', HTMLDivElement),
      inputsHeading: byId('inputs-heading', HTMLHeadingElement),
      exportPng: byId('export-png', HTMLButtonElement),
      exportJson: byId('export-json', HTMLButtonElement),
    },
    store,
    (mode) => inputs.switchMode(mode),
  );
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
  const pathViews = new PathViews(
    scene,
    {
      secondViewport: byId('viewport-b', HTMLDivElement),
      legend: byId('legend', HTMLUListElement),
      tools: byId('view-tools', HTMLDivElement),
      view2d: byId('view-2d', HTMLInputElement),
      reset: byId('reset-view', HTMLButtonElement),
      decision3d: byId('decision-3d', HTMLInputElement),
      decision3dLabel: byId('decision-3d-label', HTMLLabelElement),
      legendVisited: byId('legend-visited', HTMLSpanElement),
      legendSecondName: byId('legend-second-name', HTMLSpanElement),
      legendOnlyFirst: byId('legend-only-first', HTMLSpanElement),
      legendOnlySecond: byId('legend-only-second', HTMLSpanElement),
      legendLearner: byId('legend-learner', HTMLLIElement),
      legendPickedLine: byId('legend-picked-line', HTMLLIElement),
      legendDifference: byId('legend-difference', HTMLLIElement),
      legendFold: byId('legend-fold', HTMLButtonElement),
      openFull: byId('open-full', HTMLAnchorElement),
    },
    store,
  );
  views = pathViews;
  followControl(store, byId('follow', HTMLInputElement), () => pathViews.scenes);
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
      slowdown: byId('slowdown', HTMLSelectElement),
      machineTime: byId('machine-time', HTMLOutputElement),
      marker: byId('check-marker', HTMLButtonElement),
      jump: byId('jump', HTMLFormElement),
      jumpInput: byId('jump-input', HTMLInputElement),
    },
    store,
  );
  const inspector = new Inspector({
    point: byId('inspector-point', HTMLElement),
    deviation: byId('inspector-deviation', HTMLElement),
    decisionHeading: byId('decision-heading', HTMLHeadingElement),
    decisions: byId('decision-values', HTMLElement),
    explanation: byId('explanation', HTMLParagraphElement),
    figure: byId('decision-figure', HTMLDivElement),
    columnDocs: byId('column-docs', HTMLElement),
    setupNote: byId('setup-note', HTMLParagraphElement),
  });
  const gcodePanel = new GcodePanel(
    {
      sample: byId('sample', HTMLSelectElement),
      text: byId('gcode-text', HTMLTextAreaElement),
      listing: byId('gcode-listing', HTMLDivElement),
      longNote: byId('gcode-long', HTMLParagraphElement),
      editAnyway: byId('gcode-edit-anyway', HTMLButtonElement),
      replaced: byId('gcode-replaced', HTMLParagraphElement),
      bringBack: byId('gcode-bring-back', HTMLButtonElement),
      secondReplaced: byId('gcode-second-replaced', HTMLParagraphElement),
      secondBringBack: byId('gcode-second-bring-back', HTMLButtonElement),
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
      onPick: (_line, steps) => void page.pickLine(steps),
      onColumns: (names) => inspector.showColumns(names),
      onRun: () => void page.retrace(),
      onCancel: () => page.cancel(),
    },
  );

  // Runs the experiment on its inputs as they are: after a Cancel nothing did, short of changing one of them.
  const experimentStart = byId('experiment-start', HTMLButtonElement);
  experimentStart.addEventListener('click', () => void page.retrace());
  const exports = wireExports(
    { csv: byId('export-csv', HTMLButtonElement), json: byId('export-json', HTMLButtonElement), png: byId('export-png', HTMLButtonElement), vcd: byId('export-vcd', HTMLButtonElement) },
    {
      bar: byId('export-progress', HTMLProgressElement),
      cancel: byId('export-cancel', HTMLButtonElement),
      box: byId('export-run', HTMLSpanElement),
      text: byId('export-run-text', HTMLSpanElement),
      note: byId('export-note', HTMLSpanElement),
    },
    () => page.shown,
    pathViews,
    () => (store.state.mode === 'gcode' ? 'program' : store.state.algorithm),
  );
  const page = new Orchestrator({
    client,
    catalogue,
    store,
    status: new Status(byId('trace-status', HTMLParagraphElement), byId('embed-busy', HTMLParagraphElement)),
    modeTabs,
    views: pathViews,
    inputs,
    experimentForm,
    experimentProgress: new RunProgress(
      {
        bar: byId('experiment-progress', HTMLProgressElement),
        cancel: byId('experiment-cancel', HTMLButtonElement),
        start: experimentStart,
        box: byId('experiment-run', HTMLDivElement),
        text: byId('experiment-run-text', HTMLSpanElement),
        verb: 'Tracing',
      },
      () => page.cancel(),
    ),
    traceProgress: new RunProgress(
      {
        bar: byId('trace-progress', HTMLProgressElement),
        cancel: byId('trace-cancel', HTMLButtonElement),
        box: byId('trace-run', HTMLDivElement),
        text: byId('trace-run-text', HTMLSpanElement),
        verb: 'Measuring',
      },
      () => page.cancel(),
    ),
    gcodePanel,
    timeline,
    inspector,
    charts: new PathCharts(
      byId('charts', HTMLDivElement),
      goTo,
      {
        bar: byId('charts-progress', HTMLProgressElement),
        cancel: byId('charts-cancel', HTMLButtonElement),
        box: byId('charts-run', HTMLDivElement),
        text: byId('charts-run-text', HTMLSpanElement),
        verb: 'Charting',
        cancelled: byId('charts-cancelled', HTMLParagraphElement),
        start: byId('charts-draw', HTMLButtonElement),
      },
      { cancel: () => page.cancelCharts(), draw: () => page.drawCharts() },
    ),
    comparePanel: new ComparePanel(byId('comparison', HTMLDivElement), goTo),
    // Its "Go to point" also brings the difference close: on a long path it was too small to see.
    checkPanel: new CheckPanel(
      {
        box: byId('check-points', HTMLDetailsElement),
        text: byId('learner-points', HTMLTextAreaElement),
        listing: byId('learner-listing', HTMLDivElement),
        longNote: byId('learner-long', HTMLParagraphElement),
        clear: byId('learner-clear', HTMLButtonElement),
        editAnyway: byId('learner-edit-anyway', HTMLButtonElement),
        replaced: byId('learner-replaced', HTMLParagraphElement),
        bringBack: byId('learner-bring-back', HTMLButtonElement),
        secondReplaced: byId('learner-second-replaced', HTMLParagraphElement),
        secondBringBack: byId('learner-second-bring-back', HTMLButtonElement),
        result: byId('check-result', HTMLDivElement),
        run: {
          bar: byId('check-progress', HTMLProgressElement),
          cancel: byId('check-cancel', HTMLButtonElement),
          box: byId('check-run', HTMLDivElement),
          text: byId('check-run-text', HTMLSpanElement),
        },
      },
      store,
      {
        goTo: (pointIndex) => {
          goTo(pointIndex);
          scene.lookAtCurrentCell();
        },
        cancel: () => page.cancelCheck(),
        checkAgain: () => page.checkAgain(),
      },
    ),
    timing: new TimingDiagram(byId('timing', HTMLDivElement), goTo),
    timeViews: new TimeViews({ motion: byId('motion', HTMLDivElement), stepClocks: byId('step-clocks', HTMLDivElement), }, catalogue, timeline, goTo),
    experimentPanel: new ExperimentPanel(byId('experiment-view', HTMLDivElement), store, catalogue, byId('viewport', HTMLDivElement)),
    stepReason: new StepReason(byId('step-reason', HTMLParagraphElement)),
    staleNote: byId('stale-note', HTMLParagraphElement),
    embedProblem: byId('embed-problem', HTMLParagraphElement),
    exports,
    inspectorHeading: byId('inspector-heading', HTMLHeadingElement),
    firstPaths: (lastPoint) => {
      if (notes.step === undefined || notes.step <= lastPoint) return;
      const { mode } = store.state;
      const whose = mode === 'compare' ? "the longer path's" : mode === 'gcode' ? "the program's" : "this path's";
      linkSentences.push(`step ${grouped(notes.step)} is past ${whose} last step, ${grouped(lastPoint)}: shown at its end.`);
      showLinkNote();
    },
  });
  orchestrator = page;
  exports.refresh(false);

  wireHelp(byId('help', HTMLDialogElement), byId('help-open', HTMLButtonElement));
  store.subscribe((state, previous) => page.stateChanged(state, previous));
  void page.retrace();
}

catalogueLoaded.then(run, (error: unknown) => {
  showAlert(`The core could not start: ${String(error)}`, 'Reload the page', () => window.location.reload());
});
