/**
 * The page's one direction, input -> core -> views: a change of what is
 * traced runs the core again (debounced, in the worker; only the latest
 * run's answer is shown), and the views are given the traces it returns
 * (present). A change of the shown step goes to every view; a change of how
 * the paths are looked at (2D, Reset view, the camera, Decision in 3D) goes
 * to the path views alone (path-views.ts), with no new request.
 *
 * In trace mode a learner's points (Check points) are checked against the
 * traced rule in the worker once the trace is shown, and again (debounced)
 * when the points change; the answer goes to the check panel, the view (the
 * points beside the rule's path) and the timeline (a marker at the first
 * difference).
 *
 * Modes (state.mode): trace (one algorithm), compare (two on the same move),
 * gcode (a program on a machine), experiment (Wang's random lines). Each
 * mode's results plug into the same views through the RemoteTrace it
 * produces.
 */
import type { PathCharts } from '../charts/path-charts.js';
import type { CheckPanel } from '../check/check-panel.js';
import type { ComparePanel } from '../compare/compare-panel.js';
import type { PointsProgress, StepDetail, TraceOptions } from '../core/types.js';
import type { ExperimentPanel } from '../experiment/experiment-panel.js';
import type { AlgorithmInputs } from '../form/algorithm-inputs.js';
import { INPUTS_VALIDITY, type InputsValidity, type OptionsForm } from '../form/options-form.js';
import { diagnosticText, pathLimitAdvice } from '../form/page-advice.js';
import { linesBar, pointsBar, type RunProgress, throttled } from '../form/run-progress.js';
import type { GcodePanel } from '../gcode/gcode-panel.js';
import type { TimingDiagram } from '../gcode/timing-diagram.js';
import type { Inspector } from '../inspector/inspector.js';
import { PointDetails } from '../inspector/point-details.js';
import type { Handle } from '../scene/endpoint-handles.js';
import { PALETTE } from '../scene/palette.js';
import { type AppState, type Catalogue, type ComparedSide, MODE_INPUT_KEYS, type Mode, comparedRequests, experimentAlgorithm, tracedAlgorithms, traceOptions } from '../state/app-state.js';
import { markStale, staleness } from '../state/stale.js';
import type { Store } from '../state/store.js';
import type { StepReason } from '../timeline/step-reason.js';
import type { TimeViews } from './time-views.js';
import type { Timeline } from '../timeline/timeline.js';
import { Cancelled, CoreCrash, InputRejected, type MeasuredTrace, type Running, type TraceClient, traceName } from '../worker/client.js';
import type { LearnerCheck, LineSteps } from '../worker/protocol.js';
import { hideAlert, showAlert } from './alert.js';
import type { Exports } from './export.js';
import type { ModeTabs } from './mode-tabs.js';
import type { PathViews } from './path-views.js';
import { mainTrace, type Shown } from './shown.js';
import type { Status } from './status.js';

/** Quiet time after the last keystroke before re-tracing, ms. */
const RETRACE_DELAY_MS = 250;

/**
 * Both sides of a comparison. The worker holds each trace it answers until
 * the page frees it, so when the core refuses one side (a helix's move,
 * which no circle takes) the other side, traced all the same, is freed here:
 * nothing else held it, and each refused change kept one more in the worker.
 */
function traceBoth(client: TraceClient, [first, second]: readonly [ComparedSide, ComparedSide], onProgress: (progress: PointsProgress) => void): Running<[MeasuredTrace, MeasuredTrace]> {
  // Their metrics' passes, reported as one: the points of both measured, of all.
  const sides: [PointsProgress | undefined, PointsProgress | undefined] = [undefined, undefined];
  const report = (side: 0 | 1) => (progress: PointsProgress) => {
    sides[side] = progress;
    const [a, b] = sides;
    if (a && b) onProgress({ pointsDone: a.pointsDone + b.pointsDone, points: a.points + b.points, done: a.done && b.done });
  };
  const runs = [client.trace(first.options, report(0), first.distinction), client.trace(second.options, report(1), second.distinction)] as const;
  const both = async (): Promise<[MeasuredTrace, MeasuredTrace]> => {
    const [a, b] = await Promise.allSettled(runs.map((r) => r.result));
    if (a.status === 'rejected') {
      if (b.status === 'fulfilled') b.value.free();
      throw refusedBy(traceName(first.options.algorithm, first.distinction), a.reason);
    }
    if (b.status === 'rejected') {
      a.value.free();
      throw refusedBy(traceName(second.options.algorithm, second.distinction), b.reason);
    }
    return [a.value, b.value];
  };
  return { result: both(), cancel: () => runs.forEach((r) => r.cancel()) };
}

/**
 * A compared algorithm's refusal, named as the core's own comparison names
 * it ("circle: z = 24 differs ..."): beside the one move's fields, the
 * circle's words for a helix's move ("use the helix algorithm") read as the
 * helix's, which was picked.
 */
function refusedBy(algorithm: string, error: unknown): unknown {
  return error instanceof InputRejected ? new InputRejected({ field: error.field, limit: error.limit, message: `${algorithm}: ${error.message}` }) : error;
}

/** What a Cancel stops: a mode's own run (its path or paths, program or experiment), the charts' rows of its path, the check of the learner's points. */
type Cancellable = 'run' | 'charts' | 'check';

/** Everything the orchestrator drives. */
export interface PageParts {
  client: TraceClient;
  catalogue: Catalogue;
  store: Store<AppState>;
  status: Status;
  modeTabs: ModeTabs;
  views: PathViews;
  inputs: AlgorithmInputs;
  experimentForm: OptionsForm;
  /** The experiment's progress bar and Cancel. */
  experimentProgress: RunProgress;
  /** The bar and Cancel of a path's metrics measured in the worker (trace and compare modes), and of two paths' cells compared. */
  traceProgress: RunProgress;
  gcodePanel: GcodePanel;
  timeline: Timeline;
  inspector: Inspector;
  charts: PathCharts;
  comparePanel: ComparePanel;
  checkPanel: CheckPanel;
  timing: TimingDiagram;
  timeViews: TimeViews;
  experimentPanel: ExperimentPanel;
  /** The current step's reason under the timeline (where the inspector is out of sight). */
  stepReason: StepReason;
  /** Says when the results on screen are not of the inputs shown. */
  staleNote: HTMLElement;
  /** Embedded (the inputs hidden): what the core refused, or where a program stopped. */
  embedProblem: HTMLElement;
  /** The export buttons, enabled only for what was traced from the inputs shown. */
  exports: Exports;
  inspectorHeading: HTMLElement;
  /** Told once, when the first paths are shown, their last point index (the longer one's), which only their traces know: a link's step past it is said in the link's note. */
  firstPaths: (lastPoint: number) => void;
}

export class Orchestrator {
  readonly #p: PageParts;
  /** Asks for the shown point's StepDetail: one request per point, for the inspector and the view's overlay alike. */
  readonly #details: PointDetails;
  #shown: Shown = {};
  /** The state the run that made what is shown started in: its mode (trace and compare both show traces in a and b) and inputs. */
  #shownState: AppState | undefined;
  /** Counts runs of the core, so only the latest one's answer is shown. */
  #latestRun = 0;
  /** The long run under way (a path's metrics, a program, an experiment), to cancel. */
  #running: Running<unknown> | undefined;
  /** The G-code line last picked (pickLine), whose cells are on their way. */
  #pickedLine: LineSteps | undefined;
  #retraceTimer: ReturnType<typeof setTimeout> | undefined;
  /** The request the shown trace-mode trace was made from: a learner's points are checked against its rule. */
  #ruleOptions: TraceOptions | undefined;
  /** Counts checks of a learner's points, so only the latest one's answer is shown. */
  #latestCheck = 0;
  #checkTimer: ReturnType<typeof setTimeout> | undefined;
  /** The check of a learner's points under way in the worker, to cancel (its Cancel, new points, a new rule). */
  #checking: Running<unknown> | undefined;

  /** The core refused the last request (its message is by the inputs). */
  #rejected = false;
  /** The inputs changed and their trace is not on screen yet (a retrace waits or runs). */
  #inputsPending = false;
  /** Forms with a field holding a value the page refused itself (INPUTS_VALIDITY). */
  readonly #invalidForms = new Set<Element>();
  /** PageParts.firstPaths has been told. */
  #firstPathsTold = false;
  /**
   * The state each mode's last run of each kind was cancelled in, until one
   * of that kind starts in that mode: going back to the mode with the same
   * inputs does not run it again by itself (a Cancel stands until the user
   * asks again: an input changed, or the run's own button).
   */
  readonly #cancelled: Partial<Record<Mode, Partial<Record<Cancellable, AppState>>>> = {};

  /** A Cancel of `what` stands in `state`: it was made in `state`'s mode on the inputs `state` holds (a check's: the learner's points too). */
  #cancelStands(what: Cancellable, state: AppState): boolean {
    const cancelled = this.#cancelled[state.mode]?.[what];
    const keys = what === 'check' ? [...MODE_INPUT_KEYS[state.mode], 'learnerPoints' as const] : MODE_INPUT_KEYS[state.mode];
    return cancelled !== undefined && keys.every((k) => state[k] === cancelled[k]);
  }

  /** A run of `what` was cancelled in `state` (its mode, on its inputs). */
  #cancelledIn(what: Cancellable, state: AppState): void {
    (this.#cancelled[state.mode] ??= {})[what] = state;
  }

  /** A run of `what` starts in mode `mode` (asked for, or on other inputs): a Cancel of it no longer stands. */
  #cancelWithdrawn(what: Cancellable, mode: Mode): void {
    delete this.#cancelled[mode]?.[what];
  }

  /** A form of the mode shown holds a value the page refused (another mode's form is hidden, and says nothing of this one's results). */
  #refusedHere(): boolean {
    return [...this.#invalidForms].some((form) => form.checkVisibility());
  }

  constructor(parts: PageParts) {
    this.#p = parts;
    // A value the page refuses never reaches the core, so no run says the
    // view is out of date: the fields' own checks do (as a refusal by the
    // core does), and a field made right again takes it back unless the
    // core's refusal stands.
    document.addEventListener(INPUTS_VALIDITY, (event) => {
      const { invalid } = (event as CustomEvent<InputsValidity>).detail;
      if (invalid) this.#invalidForms.add(event.target as Element);
      else this.#invalidForms.delete(event.target as Element);
      const [refused, shown] = [this.#refusedHere(), Object.keys(this.#shown).length > 0];
      // An offer to trace again would trace the last valid value, not the one refused.
      if (refused) hideAlert();
      if (refused && shown) markStale(parts.staleNote, 'rejected');
      else if (!refused && !this.#rejected && staleness() === 'rejected') markStale(parts.staleNote, undefined);
      parts.exports.refresh(this.#inputsPending);
    });
    this.#details = new PointDetails(
      (detail: StepDetail) => {
        parts.inspector.showDetail(detail);
        parts.views.setDetail(detail);
        parts.stepReason.setMainDetail(detail);
      },
      (error) => parts.inspector.showError(error),
    );
  }

  /** What is on screen. */
  get shown(): Shown {
    return this.#shown;
  }

  /** Stops the long run under way (a path's metrics, a G-code program, the experiment). */
  cancel(): void {
    this.#running?.cancel();
  }

  /** Stops the check of the learner's points under way (its Cancel): the panel says so, and the Cancel stands until Check them. */
  cancelCheck(): void {
    // A change of the points or the rule stops a check at once (#stopCheck): the one under way is of the state now.
    if (this.#checking) this.#cancelledIn('check', this.#p.store.state);
    this.#checking?.cancel();
  }

  /** Checks the learner's points again (after a Cancel). */
  checkAgain(): void {
    this.#cancelWithdrawn('check', 'trace');
    void this.#check();
  }

  /** Stops the charts' rows on their way (their Cancel): the charts say so, and the Cancel stands until Draw charts. */
  cancelCharts(): void {
    const charted = this.#shownState;
    if (this.#p.charts.drawing && charted) this.#cancelledIn('charts', charted);
    this.#p.charts.cancel();
  }

  /** Draws the charts of the path shown (after a Cancel). */
  drawCharts(): void {
    if (this.#shownState) this.#cancelWithdrawn('charts', this.#shownState.mode);
    this.#p.charts.draw();
  }

  /**
   * Goes to point index `pointIndex` (a chart or a panel was clicked),
   * stopping playback; within the paths shown (a learner's points past the
   * end offered "Go to point 11" on a 10-step path, which showed step 11 of 10).
   */
  goTo(pointIndex: number): void {
    this.#p.store.update({ pointIndex: Math.min(Math.max(0, pointIndex), this.#lastPoint()), playing: false });
  }

  /** The last point index of the paths shown: the longer one's. */
  #lastPoint(): number {
    return Math.max(mainTrace(this.#shown)?.steps ?? 0, this.#shown.b?.steps ?? 0);
  }

  /** Goes to the last point of a picked G-code line and highlights its steps. */
  async pickLine(steps: LineSteps): Promise<void> {
    const program = this.#shown.program;
    if (!program) return;
    this.#pickedLine = steps;
    // The line picked before is no longer outlined while this one's cells are on their way.
    this.#p.views.setHighlights([]);
    this.goTo(steps.steps > 0 ? steps.firstStep + steps.steps : steps.pointBefore);
    // The line's cells are asked of the worker, which holds a long program's points.
    let cells: Int32Array;
    try {
      cells = await program.pointsInRange(steps.firstStep + 1, steps.firstStep + steps.steps + 1);
    } catch (error) {
      // A crash is reported as it happens (coreCrashed); anything else is a bug, said on the status line.
      if (!(error instanceof CoreCrash)) {
        console.error(error);
        this.#p.status.bug(error);
      }
      return;
    }
    // Another line, or another program, was picked meanwhile.
    if (this.#shown.program !== program || this.#pickedLine !== steps) return;
    this.#p.views.setHighlights([{ cells, dims: program.dims, colour: PALETTE.onlyFirst }]);
  }

  /** Handles on the move's points: the point options the traced algorithms take (from, to, center). */
  #handles(): Handle[] {
    const { store, catalogue } = this.#p;
    const { mode, options } = store.state;
    if (mode !== 'trace' && mode !== 'compare') return [];
    const names = new Set(tracedAlgorithms(store.state, catalogue.algorithms).flatMap((a) => a.options.filter((o) => o.kind.type === 'point').map((o) => o.name)));
    return [...names].flatMap((name) => {
      const point = options[name];
      return Array.isArray(point) && point.every(Number.isFinite) ? [{ name, point }] : [];
    });
  }

  /** Gives every view the traces now shown. */
  #present(): void {
    const p = this.#p;
    const state = p.store.state;
    const { a, b, program, difference } = this.#shown;
    const main = mainTrace(this.#shown);
    const pointIndex = Math.min(state.pointIndex, this.#lastPoint());
    const mainPoint = Math.min(pointIndex, main?.steps ?? 0);
    p.views.setDetail(undefined);
    p.views.show(this.#shown, pointIndex);
    p.views.setHandles(this.#handles());
    p.inspector.setTrace(main, mainPoint);
    p.stepReason.setTraces(main, state.mode === 'compare' ? b : undefined, pointIndex);
    this.#details.setTrace(main, mainPoint);
    const charted = this.#shownState;
    if (main && charted && this.#cancelStands('charts', charted)) p.charts.setCancelled(main, mainPoint);
    else {
      if (main && charted) this.#cancelWithdrawn('charts', charted.mode);
      void p.charts.setTrace(main, mainPoint);
    }
    p.comparePanel.show(a, b, difference);
    p.gcodePanel.setProgram(program);
    p.timing.setTrace(program, pointIndex);
    p.timeViews.show(state.mode, program, a, pointIndex);
    if (program) void p.gcodePanel.showPoint(pointIndex);
    // Last: it may clamp the step to a shorter path, and every view must hold the new traces by then.
    p.timeline.setSteps(main || b ? this.#lastPoint() : undefined);
    this.#markDifference();
    // Compared, the inspector follows the first path only: say which.
    p.inspectorHeading.textContent = state.mode === 'compare' ? `Current point of ${a?.name ?? 'the first'}` : 'Current point';
  }

  #freeShown(): void {
    this.#shown.a?.free();
    this.#shown.b?.free();
    this.#shown.program?.free();
    this.#shown = {};
  }

  /** `show`, throttled (run-progress.ts), for run `run`'s progress; not once a later run has started. */
  #throttled<Progress extends { done: boolean }>(run: number, show: (progress: Progress) => void): (progress: Progress) => void {
    return throttled(() => run === this.#latestRun, show);
  }

  /**
   * How far a pass over the points of the path (or both paths) has got, on
   * its bar (`verb`) and the status line (`said`): their metrics', or
   * compared, their cells' sort.
   */
  #passing(progress: PointsProgress, verb = 'Measuring', said = 'Measuring the path'): void {
    const bar = pointsBar(progress);
    this.#p.traceProgress.set(bar, verb);
    this.#p.status.passing(said, bar);
  }

  /** Says that mode `mode`'s run was cancelled, and what of an earlier run is still shown, with the way to run the inputs again. */
  #sayCancelled(mode: Mode): void {
    const p = this.#p;
    const { a, program, experiment } = this.#shown;
    const kept = program ? 'program' : experiment ? 'experiment' : a ? 'paths' : undefined;
    p.status.cancelled(kept);
    markStale(p.staleNote, kept ? 'cancelled' : undefined);
    // G-code's "Run program" and the experiment's "Run experiment" run
    // their inputs again; trace and compare mode have no such button,
    // and a Cancel left their inputs untraced (a link's: a blank view)
    // until one was changed.
    if (mode === 'trace' || mode === 'compare') {
      showAlert(kept ? 'Cancelled: the view shows the last paths traced, not the inputs.' : 'Cancelled: the inputs are not traced.', 'Trace again', () => {
        hideAlert();
        void this.retrace();
      });
    } else hideAlert();
  }

  /**
   * Back in a mode whose last run was cancelled, on the inputs it was
   * cancelled with: they stay untraced, as they were left, until the user
   * asks (the mode switch ran them again by itself, a long program or
   * experiment the user had stopped). What another mode's run shows is
   * dropped; the mode's own results, if nothing replaced them since, stay.
   */
  #stayCancelled(mode: Mode): void {
    const p = this.#p;
    // The run of the mode left, under way or waiting, is no longer wanted, and its end shows nothing.
    this.#latestRun += 1;
    clearTimeout(this.#retraceTimer);
    this.#running?.cancel();
    this.#running = undefined;
    p.gcodePanel.setProgress(undefined);
    p.experimentProgress.set(undefined);
    p.traceProgress.set(undefined);
    // Another mode's refusal is not of these inputs.
    p.inputs.showCoreError(undefined);
    p.gcodePanel.showCoreError(undefined);
    p.experimentForm.showCoreError(undefined);
    this.#rejected = false;
    p.embedProblem.textContent = '';
    if (this.#shownState?.mode !== mode) {
      this.#freeShown();
      this.#shownState = undefined;
      this.#ruleOptions = undefined;
      p.charts.cancel();
      this.#present();
      p.experimentPanel.clear();
    }
    this.#sayCancelled(mode);
    this.#inputsPending = false;
    p.exports.refresh(false);
  }

  /** Runs the core on the current inputs and shows what it returns (unless a later run has started). */
  async retrace(): Promise<void> {
    const p = this.#p;
    const run = ++this.#latestRun;
    const state = p.store.state;
    // Asked for: by an input, the mode's button (Run program, Run experiment, Trace again) or the page's load.
    this.#cancelWithdrawn('run', state.mode);
    this.#running?.cancel();
    this.#running = undefined;
    // The charts' rows of the path about to be replaced would hold up the new one's in the worker, as would a check against its rule.
    p.charts.cancel();
    this.#stopCheck();
    p.gcodePanel.setProgress(undefined);
    p.experimentProgress.set(undefined);
    p.traceProgress.set(undefined);
    p.status.tracing(state.mode);
    try {
      let next: Shown;
      let ruleOptions: TraceOptions | undefined;
      if (state.mode === 'trace') {
        const [info] = tracedAlgorithms(state, p.catalogue.algorithms);
        ruleOptions = traceOptions(state, info!);
        const started = p.client.trace(ruleOptions, this.#throttled(run, (progress) => this.#passing(progress)));
        this.#running = started;
        next = { a: await started.result };
      } else if (state.mode === 'compare') {
        const started = traceBoth(p.client, comparedRequests(state, p.catalogue.algorithms), this.#throttled(run, (progress) => this.#passing(progress)));
        this.#running = started;
        const [a, b] = await started.result;
        const differing = p.client.difference(a, b, this.#throttled(run, (progress) => this.#passing(progress, 'Comparing', 'Comparing the paths (cells sorted)')));
        this.#running = differing;
        try {
          next = { a, b, difference: await differing.result };
        } catch (error) {
          // Not shown: nothing else holds them.
          a.free();
          b.free();
          throw error;
        }
      } else if (state.mode === 'gcode') {
        const started = p.client.runGcode(
          state.gcode,
          state.machine,
          this.#throttled(run, (progress) => {
            p.gcodePanel.setProgress(progress);
            p.status.running('Running', progress);
          }),
        );
        this.#running = started;
        next = { program: await started.result };
      } else {
        const options = { algorithm: experimentAlgorithm(state, p.catalogue).id, ...state.experiment };
        const started = p.client.randomLines(
          options,
          this.#throttled(run, (progress) => {
            p.experimentProgress.set(linesBar(progress));
            p.status.running('Tracing', progress);
          }),
        );
        this.#running = started;
        next = { experiment: await started.result };
      }
      if (run !== this.#latestRun) {
        for (const t of [next.a, next.b, next.program]) t?.free();
        return;
      }
      hideAlert();
      p.inputs.showCoreError(undefined);
      p.gcodePanel.showCoreError(undefined);
      p.experimentForm.showCoreError(undefined);
      // Traced, unless a field still holds a value the page refused: then
      // what is shown is not of what the fields show.
      markStale(p.staleNote, this.#refusedHere() ? 'rejected' : undefined);
      this.#rejected = false;
      this.#freeShown();
      this.#shown = next;
      this.#shownState = state;
      this.#ruleOptions = ruleOptions;
      if (next.experiment) p.experimentPanel.show(next.experiment);
      else {
        this.#present();
        if (!this.#firstPathsTold) {
          this.#firstPathsTold = true;
          p.firstPaths(this.#lastPoint());
        }
      }
      p.status.shown(next);
      const stop = next.program?.program.errors[0];
      p.embedProblem.textContent = stop ? `The program stopped at line ${stop.line}, column ${stop.column}: ${diagnosticText(stop)}` : '';
      void this.#check();
    } catch (error) {
      if (run !== this.#latestRun || error instanceof CoreCrash) return;
      if (error instanceof Cancelled) {
        this.#cancelledIn('run', state);
        this.#sayCancelled(state.mode);
      } else if (error instanceof InputRejected) {
        // An offer to trace again (after a Cancel) would trace what is refused.
        hideAlert();
        this.#rejected = true;
        if (Object.keys(this.#shown).length > 0) markStale(p.staleNote, 'rejected');
        if (state.mode === 'gcode') p.gcodePanel.showCoreError(error);
        else if (state.mode === 'experiment') p.experimentForm.showCoreError(error);
        else p.inputs.showCoreError(error);
        p.status.rejected(this.#shown.a !== undefined || this.#shown.program !== undefined);
        const pathLimit = error.limit && (state.mode === 'trace' || state.mode === 'compare');
        p.embedProblem.textContent = `Not traced: ${error.field ? `${error.field}: ` : ''}${pathLimit ? pathLimitAdvice(error.limit!) : error.message}`;
      } else {
        console.error(error);
        p.status.bug(error);
        p.embedProblem.textContent = `Not traced, because of a bug in voxpath: ${String(error)}`;
      }
    } finally {
      if (run === this.#latestRun) {
        this.#running = undefined;
        p.gcodePanel.setProgress(undefined);
        p.experimentProgress.set(undefined);
        p.traceProgress.set(undefined);
        this.#inputsPending = false;
        p.exports.refresh(false);
      }
    }
  }

  /**
   * Checks the learner's points against the shown trace's rule (in the
   * worker) and shows the answer; with no points, or outside trace mode,
   * clears it.
   */
  async #check(): Promise<void> {
    const p = this.#p;
    this.#stopCheck();
    const check = this.#latestCheck;
    const { mode, learnerPoints } = p.store.state;
    const rule = this.#shown.a;
    const options = this.#ruleOptions;
    if (mode !== 'trace' || !rule || !options || learnerPoints.trim() === '') {
      this.#showLearner(undefined);
      p.checkPanel.clear();
      return;
    }
    // The path traced again (another mode and back) on the points and rule of a check cancelled: it stands until Check them.
    if (this.#cancelStands('check', p.store.state)) {
      this.#showLearner(undefined);
      p.checkPanel.cancelled();
      return;
    }
    this.#cancelWithdrawn('check', mode);
    const current = () => check === this.#latestCheck && rule === this.#shown.a;
    const started = p.client.check(rule, options, learnerPoints, throttled(current, (progress) => p.checkPanel.setProgress(progress)));
    this.#checking = started;
    try {
      const learner = await started.result;
      if (!current()) return;
      this.#showLearner(learner);
      p.checkPanel.show(learner.check);
    } catch (error) {
      if (!current() || error instanceof CoreCrash) return;
      this.#showLearner(undefined);
      if (error instanceof Cancelled) {
        p.checkPanel.cancelled();
      } else if (error instanceof InputRejected) {
        p.checkPanel.showError(error.field ? `${error.field}: ${error.message}` : error.message);
      } else {
        console.error(error);
        p.checkPanel.showError(`The check failed, a bug in voxpath: ${String(error)}`);
      }
    } finally {
      if (check === this.#latestCheck) {
        this.#checking = undefined;
        p.checkPanel.setProgress(undefined);
      }
    }
  }

  /**
   * Stops the check under way and any waiting to start: a newer input (an
   * edit of the points, a new rule) cancels it in the worker rather than
   * waiting behind it, and a later answer of it is not shown.
   */
  #stopCheck(): void {
    this.#latestCheck += 1;
    clearTimeout(this.#checkTimer);
    this.#checking?.cancel();
    this.#checking = undefined;
    this.#p.checkPanel.setProgress(undefined);
  }

  #showLearner(learner: LearnerCheck | undefined): void {
    this.#shown.learner = learner;
    this.#p.views.setLearner(learner);
    this.#markDifference();
  }

  /** The timeline's marker at the first difference of the learner's points, if any. */
  #markDifference(): void {
    const first = this.#shown.learner?.check.firstDifference;
    this.#p.timeline.setMarker(first?.pointIndex, first ? `First difference of your points: point ${first.pointIndex}` : undefined);
  }

  /** The worker's core crashed: its traces died with it. */
  coreCrashed(message: string): void {
    // Drop them rather than show values that can no longer be explained.
    this.#shown = {};
    this.#present();
    this.#p.status.clear();
    showAlert(`The core stopped with an internal error, a bug in voxpath: ${message}. It has been restarted.`, 'Trace again', () => {
      hideAlert();
      void this.retrace();
    });
  }

  /** Reacts to a change of the state (the store's listener). */
  stateChanged(state: AppState, previous: AppState): void {
    const p = this.#p;
    if (state.mode !== previous.mode || state.layout !== previous.layout) p.modeTabs.render();
    const inputsChanged = state.mode !== previous.mode || MODE_INPUT_KEYS[state.mode].some((k) => state[k] !== previous[k]);
    if (state.mode !== previous.mode && this.#cancelStands('run', state)) {
      this.#stopCheck();
      this.#stayCancelled(state.mode);
    } else if (inputsChanged) {
      // A check against the rule about to be replaced stops now, not when the retrace starts.
      this.#stopCheck();
      clearTimeout(this.#retraceTimer);
      this.#retraceTimer = setTimeout(() => void this.retrace(), RETRACE_DELAY_MS);
      this.#inputsPending = true;
      p.exports.refresh(true);
      if (state.options !== previous.options) p.views.setHandles(this.#handles());
    } else if (state.learnerPoints !== previous.learnerPoints) {
      // The same rule: only the check runs again, the one under way stopped at once.
      this.#stopCheck();
      this.#checkTimer = setTimeout(() => void this.#check(), RETRACE_DELAY_MS);
    } else if (state.layout !== previous.layout) {
      // The same traces, laid out anew: the path views only.
      p.views.show(this.#shown, state.pointIndex);
    } else if (state.projection !== previous.projection) {
      p.views.setProjection(state.projection);
    } else if (state.camera === null && previous.camera !== null) {
      p.views.resetView();
    } else if (state.camera && state.camera !== previous.camera) {
      p.views.setCamera(state.camera);
    }
    if (state.decision3d !== previous.decision3d) p.views.setDecision3d(state.decision3d);
    if (state.legendFolded !== previous.legendFolded) p.views.setLegendFolded(state.legendFolded);
    if (state.mode === 'gcode') p.gcodePanel.render();
    const pointsFields = ['learnerPoints', 'replacedPoints', 'replacedPointsBy', 'secondReplacedPoints'] as const;
    if (pointsFields.some((field) => state[field] !== previous[field])) p.checkPanel.render();
    p.experimentForm.setValues(state.experiment);
    if (state.pointIndex !== previous.pointIndex) this.#showPoint(state.pointIndex);
  }

  /** Every view at point index `pointIndex` (each path at most at its end). */
  #showPoint(pointIndex: number): void {
    const p = this.#p;
    const main = mainTrace(this.#shown);
    p.views.showPoint(pointIndex);
    if (main) {
      p.inspector.showPoint(Math.min(pointIndex, main.steps));
      this.#details.show(Math.min(pointIndex, main.steps));
    }
    p.stepReason.show(pointIndex);
    p.charts.showPoint(pointIndex);
    p.timing.showPoint(pointIndex);
    p.timeViews.showPoint(pointIndex);
    if (this.#shown.program) void p.gcodePanel.showPoint(pointIndex);
  }
}
