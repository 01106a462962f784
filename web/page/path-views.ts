/**
 * The path views: the main view, a second one beside it when two paths are
 * compared side by side, their tools (2D, Reset view, Decision in 3D) and
 * their legend; in trace mode, a learner's checked points beside the rule's.
 *
 * show() draws what is on screen, building the views' GPU buffers: for new
 * traces or a new layout. Everything else only changes how the same paths
 * are looked at (the projection, the camera, the shown step, the decision
 * overlay) and is done on the views alone: nothing is rebuilt and the
 * worker is not asked (tests/browser/views.test.ts checks it).
 */
import type { FigureKind, StepDetail } from '../core/types.js';
import { decisionOverlay, decisionOverlayKinds } from '../scene/decision-overlay.js';
import type { Handle } from '../scene/endpoint-handles.js';
import { PALETTE } from '../scene/palette.js';
import { type Highlight, type SceneCallbacks, SceneView } from '../scene/scene-view.js';
import { heldPoints } from '../scene/voxel-path.js';
import type { AppState, CameraState, Projection } from '../state/app-state.js';
import type { Store } from '../state/store.js';
import type { LearnerCheck } from '../worker/protocol.js';
import { mainTrace, type Shown } from './shown.js';

/** Where style.css stacks two views one above the other (its @media (orientation: portrait)). */
const PORTRAIT = window.matchMedia('(orientation: portrait)');

/**
 * A window this narrow (a phone's, held upright) has no room over the view
 * for the comparison's legend: its seven entries, in a column beside the
 * view's stacked tools, stood 196 px tall over a view of 364 at 240 px
 * (125 to 161 px at 360), past the 30 % of its height the view frames its
 * picture below, and over the z axis's name. There it stands above the
 * view, with the tools, as side by side. At 390 to 430 px it took 20 to
 * 30 %. So does trace mode's with a learner's points, whose two entries
 * (the points, their first difference) run to three lines each: 224 px
 * over 364 at 240 (over y and z), 139 to 153 px at 272, 360 and 430 (over
 * z); without them its four short entries take 13 to 22 %.
 */
const NARROW = window.matchMedia('(max-width: 430px)');

export interface PathViewElements {
  /** Where the second view goes (side by side). */
  secondViewport: HTMLDivElement;
  /** The legend, over the main view; side by side above both views, and in a narrow window (NARROW), compared or with a learner's points, above the one. */
  legend: HTMLElement;
  /** The view's tools (2D, Decision in 3D, Follow, Reset view), after the legend wherever it is. */
  tools: HTMLElement;
  view2d: HTMLInputElement;
  reset: HTMLButtonElement;
  decision3d: HTMLInputElement;
  /** The label of decision3d, whose tooltip says what it draws. */
  decision3dLabel: HTMLElement;
  legendVisited: HTMLElement;
  legendSecondName: HTMLElement;
  legendOnlyFirst: HTMLElement;
  legendOnlySecond: HTMLElement;
  /** The legend's entries for a learner's checked points and their first difference, shown while there are some. */
  legendLearner: HTMLElement;
  /** The legend's entry for a picked G-code line's steps, shown while some are outlined. */
  legendPickedLine: HTMLElement;
  legendDifference: HTMLElement;
  /** Folds the legend to one line, itself, and shows it whole again (AppState.legendFolded). */
  legendFold: HTMLButtonElement;
}

export class PathViews {
  readonly #main: SceneView;
  #second: SceneView | undefined;
  readonly #e: PathViewElements;
  readonly #store: Store<AppState>;
  /** Where the views' camera moves and handle drags go: into the state. */
  readonly events: SceneCallbacks;

  /** Both views (the second only once made): for what applies to each alike, such as following the current cell. */
  get scenes(): readonly (SceneView | undefined)[] {
    return [this.#main, this.#second];
  }
  /** The shown point's detail, whose decision the overlay draws. */
  #detail: StepDetail | undefined;
  /** The pictures the main path's decisions have (its summary's): what Decision in 3D can draw. */
  #figures: readonly FigureKind[] = [];
  /** The second path's algorithm, as the legend names it. */
  #secondName = 'second';
  /** The main view, where the legend stands but side by side. */
  readonly #legendView: HTMLElement;

  /**
   * Names the second path in the legend, and side by side where its view
   * is: to the right, or below in a window taller than wide, where the
   * stylesheet stacks the views (it said "right view" of the lower one).
   */
  #nameSecond(side: boolean): void {
    const where = PORTRAIT.matches ? 'lower view' : 'right view';
    this.#e.legendSecondName.textContent = side ? `${this.#secondName} (${where})` : this.#secondName;
  }

  /** `main` is made early, so that its shaders compile while the core loads (SceneView's warm-up). */
  constructor(main: SceneView, elements: PathViewElements, store: Store<AppState>) {
    this.#main = main;
    this.#e = elements;
    this.#store = store;
    this.#legendView = elements.legend.parentElement!;
    this.events = {
      onCamera: (camera) => store.update({ camera }),
      onHandle: (name, point) => store.update({ options: { ...store.state.options, [name]: point } }),
    };
    const { view2d, reset, decision3d } = elements;
    view2d.addEventListener('change', () => store.update({ projection: view2d.checked ? '2d' : '3d', camera: null }));
    reset.addEventListener('click', () => store.update({ camera: null }));
    decision3d.addEventListener('change', () => store.update({ decision3d: decision3d.checked }));
    elements.legendFold.addEventListener('click', () => store.update({ legendFolded: !store.state.legendFolded }));
    this.setLegendFolded(store.state.legendFolded);
    PORTRAIT.addEventListener('change', () => this.#nameSecond(store.state.mode === 'compare' && store.state.layout === 'side'));
    NARROW.addEventListener('change', () => this.#placeLegend());
  }

  /**
   * Puts the legend and the tools where the layout has them. Side by side,
   * the legend tells of both views and stands above them: over the first
   * one it covered its path (in a 640 x 480 frame). So do the tools, which
   * act on both (the cameras are linked): stacked in the first view's
   * corner, Reset view stood on its E handle. In a narrow window (NARROW),
   * compared or with a learner's points, both stand above the one view
   * too: the legend alone above it left the stacked tools more of the
   * shorter view than it frames its picture below, and Reset view stood on
   * the E handle. It goes there with the points typed, not with their
   * entries shown, which a new rule hides until its check answers: the
   * view would be framed twice more at each change.
   */
  #placeLegend(): void {
    const { mode, layout, learnerPoints } = this.#store.state;
    const { legend, tools, secondViewport } = this.#e;
    const long = mode === 'compare' || (mode === 'trace' && learnerPoints.trim() !== '');
    const above = (mode === 'compare' && layout === 'side') || (NARROW.matches && long);
    const place = above ? secondViewport.parentElement! : this.#legendView;
    if (legend.parentElement === place) return;
    place.prepend(legend);
    legend.after(tools);
  }

  /**
   * Draws what is shown at `pointIndex` (new traces, or a new layout): the
   * views' buffers are built again. New traces come without a detail yet
   * (setDetail(undefined) first).
   */
  show(shown: Shown, pointIndex: number): void {
    const state = this.#store.state;
    // New paths are drawn with no line picked (SceneView.setTrace clears its highlights).
    this.#e.legendPickedLine.hidden = true;
    const { a, b, difference } = shown;
    const main = mainTrace(shown);
    const side = state.mode === 'compare' && state.layout === 'side';
    // Before the views frame their paths below what lies over them.
    this.#placeLegend();
    this.#main.setTrace(main, Math.min(pointIndex, main?.steps ?? 0), state.projection, state.camera);
    if (state.mode === 'compare' && !side) this.#main.setSecond(b);
    if (side) {
      this.#second ??= new SceneView(this.#e.secondViewport, this.events, 'second path view', PALETTE.second);
      this.#second.setTrace(b, Math.min(pointIndex, b?.steps ?? 0), state.projection, state.camera);
    } else {
      this.#second?.setTrace(undefined, 0, state.projection, null);
    }
    if (difference && a && b) {
      const onlyA = { cells: difference.onlyInA, dims: a.dims, colour: PALETTE.onlyFirst };
      const onlyB = { cells: difference.onlyInB, dims: b.dims, colour: PALETTE.onlySecond };
      if (side) {
        this.#main.setHighlights([onlyA]);
        this.#second?.setHighlights([onlyB]);
      } else {
        this.#main.setHighlights([onlyA, onlyB]);
      }
    }
    this.#figures = main?.figures ?? [];
    this.#showProjection();
    this.#e.decision3d.checked = state.decision3d;
    const e = this.#e;
    const compared = state.mode === 'compare';
    e.legendVisited.textContent = compared ? `visited by ${a?.name ?? 'the first'}` : 'visited';
    this.#secondName = b?.name ?? 'second';
    this.#nameSecond(side);
    e.legendOnlyFirst.textContent = `only ${a?.name ?? 'first'} visits`;
    e.legendOnlySecond.textContent = `only ${b?.name ?? 'second'} visits`;
    this.setLearner(shown.learner);
    // The shown point's decision, on the views built anew.
    this.#drawDecision();
  }

  /**
   * Trace mode: a learner's checked points as a second path, in their own
   * colour, and the first difference's cells (the rule's and theirs)
   * outlined; undefined removes them. Nothing else is rebuilt.
   */
  setLearner(learner: LearnerCheck | undefined): void {
    const traced = this.#store.state.mode === 'trace';
    const points = traced ? learner?.points : undefined;
    const difference = traced ? learner?.check.firstDifference : undefined;
    const cells = [difference?.expected, difference?.got].filter((p): p is number[] => p !== null && p !== undefined);
    this.#e.legendLearner.hidden = !points;
    this.#e.legendDifference.hidden = cells.length === 0;
    // Points typed, or cleared, since the last paths were drawn.
    this.#placeLegend();
    // The legend, its entries shown or hidden (and, from show, renamed), framed for before the view draws again.
    this.#main.overlaysChanged();
    // Other modes' second path and highlights are their own.
    if (!traced) return;
    // The points' box and their line (for a path drawn whole) as the worker found them.
    const bounds = learner?.bounds;
    this.#main.setSecond(points && bounds ? { ...heldPoints(points, learner.dims), bounds } : undefined, PALETTE.learner, { whole: learner?.centers ?? null });
    this.#main.setHighlights(cells.length > 0 ? [{ cells: Int32Array.from(cells.flat()), dims: learner!.dims, colour: PALETTE.onlyFirst }] : []);
  }

  /**
   * Folds the legend to its one line, its button, or shows it whole. In a
   * short window its entries covered the axes' names: compared, z at 640 x
   * 360 and y and z at 800 x 450 (a view of 148 px), where above the view
   * (as in a narrow window) they would have left it 80 to 150 px. The view
   * frames its picture anew below it (SceneView.overlaysChanged, on its
   * resize).
   */
  setLegendFolded(folded: boolean): void {
    const { legend, legendFold } = this.#e;
    legend.classList.toggle('folded', folded);
    // Named "Legend" either way (aria-label), its state said by aria-expanded.
    legendFold.textContent = folded ? 'Legend ▾' : '▴';
    legendFold.title = folded ? 'Show the legend whole' : 'Fold the legend to one line';
    legendFold.setAttribute('aria-expanded', String(!folded));
  }

  /** The 2D toggle as the main view is: on in 2D, off where the path is not planar; and Decision in 3D as it can be drawn there. */
  #showProjection(): void {
    const { view2d, decision3d, decision3dLabel } = this.#e;
    const planar = this.#main.planar;
    view2d.checked = this.#store.state.projection === '2d' && planar;
    view2d.disabled = !planar;
    view2d.parentElement!.title = planar ? "Orthographic view of the path's plane, with the pixel grid" : 'The path is not in one plane';
    const overlays = decisionOverlayKinds(this.#figures, view2d.checked);
    decision3d.disabled = overlays.length === 0;
    decision3dLabel.title =
      overlays.length > 0
        ? `The current step's decision in the view: ${overlays.join('; or ')}.`
        : decisionOverlayKinds(this.#figures, false).length > 0
          ? "In 2D the exit face is seen edge on, its letters on one another: the inspector's figure shows it, and so does the view in 3D"
          : "This algorithm's decisions have no 3D picture: only the discriminate regions' exit face and the circle's candidates do";
  }

  /** Switches every view to `projection`, framing its path. */
  setProjection(projection: Projection): void {
    this.#main.setProjection(projection);
    this.#second?.setProjection(projection);
    this.#showProjection();
    this.#drawDecision();
  }

  /** Frames every view's path. */
  resetView(): void {
    this.#main.resetView();
    this.#second?.resetView();
  }

  setCamera(camera: CameraState): void {
    this.#main.setCamera(camera);
    this.#second?.setCamera(camera);
  }

  /**
   * Shows each path after `pointIndex` steps (each view caps each of its
   * paths at its own: overlaid, the second path is the main view's, and
   * capping the view at the first path's length stopped a longer second
   * path there).
   */
  showPoint(pointIndex: number): void {
    this.#main.showPoint(pointIndex);
    this.#second?.showPoint(pointIndex);
  }

  /** Outlines cells of the main view (the steps of a picked G-code line), with their legend entry. */
  setHighlights(highlights: readonly Highlight[]): void {
    this.#main.setHighlights(highlights);
    this.#e.legendPickedLine.hidden = highlights.length === 0;
  }

  setHandles(handles: readonly Handle[]): void {
    this.#main.setHandles(handles);
  }

  /** The shown point's detail: its decision is drawn in the view while Decision in 3D is on. */
  setDetail(detail: StepDetail | undefined): void {
    this.#detail = detail;
    this.#drawDecision();
  }

  /** Decision in 3D on or off. */
  setDecision3d(on: boolean): void {
    this.#e.decision3d.checked = on;
    this.#drawDecision();
  }

  #drawDecision(): void {
    const detail = this.#detail;
    this.#main.setOverlay(this.#store.state.decision3d && detail ? decisionOverlay(detail, this.#e.view2d.checked) : undefined);
  }

  /** The main view as a PNG. */
  toPng(): Promise<Blob> {
    return this.#main.toPng();
  }
}
