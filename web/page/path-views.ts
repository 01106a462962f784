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

/**
 * The usual shape (width over height) of a view's framed picture: the
 * example line's, (0,0,0) to (10,7,6), is about 170 x 135 px. Side by side,
 * two views across a room of this shape or wider show pictures larger than
 * one above the other (each has half the width, against half the height),
 * and smaller in a narrower one (#stackViews).
 */
const PICTURE_ASPECT = 4 / 3;

export interface PathViewElements {
  /** Where the second view goes (side by side). */
  secondViewport: HTMLDivElement;
  /** The legend, over the main view where it leaves the picture its room; else, and side by side, above the views (#placeLegend). */
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
  /**
   * The embedded page's Open in voxpath link, in the views' lower right
   * corner: over the last view in a frame under 400 px tall, where the
   * views frame their pictures above it (it covered the x axis's name
   * in frames up to 480 px wide, 720 side by side).
   */
  openFull: HTMLElement;
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
   * is: to the right, or below where the views are stacked (#stackViews; it
   * said "right view" of the lower one).
   */
  #nameSecond(side: boolean): void {
    const where = this.#e.secondViewport.parentElement!.hasAttribute('data-stacked') ? 'lower view' : 'right view';
    this.#e.legendSecondName.textContent = side ? `${this.#secondName} (${where})` : this.#secondName;
  }

  /**
   * Side by side, stands the two views one above the other (style.css's
   * .views[data-stacked]) where the room they share is narrower than
   * PICTURE_ASPECT, across it elsewhere: the arrangement in which each
   * view's picture is the larger. They stood so by the window's
   * orientation, and in the one-column layout a window taller than wide
   * (320 to 540 px wide, 400 to 700 tall) stacked them 39 to 100 px tall
   * each, the z axis's name cut off at their edge: at 480 x 541, two of
   * 462 x 94 px in a room of about 470 x 190, where across it each is
   * 230 x 190. The room is the same either way (the legend and the tools
   * span it), so the arrangement does not undo itself.
   */
  #stackViews(): void {
    const { secondViewport } = this.#e;
    const views = secondViewport.parentElement!;
    if (secondViewport.hidden) {
      views.removeAttribute('data-stacked');
      return;
    }
    const [first, second] = [this.#legendView, secondViewport].map((view) => view.getBoundingClientRect());
    const width = Math.max(first!.right, second!.right) - Math.min(first!.left, second!.left);
    const height = Math.max(first!.bottom, second!.bottom) - Math.min(first!.top, second!.top);
    views.toggleAttribute('data-stacked', width < PICTURE_ASPECT * height);
  }

  /** `main` is made early, so that its shaders compile while the core loads (SceneView's warm-up). */
  constructor(main: SceneView, elements: PathViewElements, store: Store<AppState>) {
    this.#main = main;
    this.#e = elements;
    this.#store = store;
    this.#legendView = elements.legend.parentElement!;
    main.frameAbove(elements.openFull);
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
    // A window or a layout that reshapes the views may call for the other arrangement side by side (the second view shown
    // reshapes only itself), and leave the legend too tall over the view, or give it room there again.
    const reshaped = new ResizeObserver(() => {
      this.#stackViews();
      this.#nameSecond(store.state.mode === 'compare' && store.state.layout === 'side');
      this.#placeLegend();
    });
    reshaped.observe(elements.secondViewport.parentElement!);
    reshaped.observe(elements.secondViewport);
  }

  /**
   * Puts the legend and the tools where the layout has them. Side by side,
   * the legend tells of both views and stands above them: over the first
   * one it covered its path (in a 640 x 480 frame). So do the tools, which
   * act on both (the cameras are linked): stacked in the first view's
   * corner, Reset view stood on its E handle.
   *
   * Over the one view, they stand at its top, and the view frames its
   * picture below them in what is left, but for at most MAX_INSET of
   * its height: taller, they covered the picture. Where they would take
   * more (SceneView.overlaysFit), both stand above the view, the legend
   * across its whole width. They stood there by the window's width alone
   * (430 px or narrower, compared or with a learner's points), and covered
   * the picture wherever else the view was short for them: compared, a
   * view 157 to 298 px tall beside the panels (721 x 541 to 900 x 600) had
   * y, z and the S and E handles under the legend; with a learner's
   * points, z in the one-column layout at 736 x 414; trace mode's tools,
   * stacked, put Reset view on the E handle at 721 x 541.
   *
   * The entries that come and go with what the user does are measured as
   * shown, so that the legend does not move at each: a learner's points,
   * while some are typed (a new rule hides their entries until its check
   * answers, and the view would be framed twice more at each change), and
   * the picked G-code line's steps (each line picked in turn).
   */
  #placeLegend(): void {
    const { mode, layout, learnerPoints } = this.#store.state;
    const { legend, tools, secondViewport, legendLearner, legendDifference, legendPickedLine } = this.#e;
    const views = secondViewport.parentElement!;
    const put = (place: HTMLElement) => {
      if (legend.parentElement === place) return;
      place.prepend(legend);
      legend.after(tools);
    };
    if (mode === 'compare' && layout === 'side') {
      put(views);
      return;
    }
    // Measured over the view, with the entries that come and go shown; put back as they were in the same task, before anything is drawn.
    const coming = [...(mode === 'trace' && learnerPoints.trim() !== '' ? [legendLearner, legendDifference] : []), ...(mode === 'gcode' ? [legendPickedLine] : [])].filter((e) => e.hidden);
    for (const entry of coming) entry.hidden = false;
    put(this.#legendView);
    const fits = this.#main.overlaysFit();
    for (const entry of coming) entry.hidden = true;
    put(fits ? this.#legendView : views);
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
    const e = this.#e;
    const compared = state.mode === 'compare';
    e.legendVisited.textContent = compared ? `visited by ${a?.name ?? 'the first'}` : 'visited';
    this.#secondName = b?.name ?? 'second';
    this.#stackViews();
    this.#nameSecond(side);
    e.legendOnlyFirst.textContent = `only ${a?.name ?? 'first'} visits`;
    e.legendOnlySecond.textContent = `only ${b?.name ?? 'second'} visits`;
    // Named, before the views frame their paths below what lies over them.
    this.#placeLegend();
    this.#main.setTrace(main, Math.min(pointIndex, main?.steps ?? 0), state.projection, state.camera);
    if (state.mode === 'compare' && !side) this.#main.setSecond(b);
    if (side) {
      if (!this.#second) {
        this.#second = new SceneView(this.#e.secondViewport, this.events, 'second path view', PALETTE.second);
        this.#second.frameAbove(this.#e.openFull);
      }
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
    // The legend, its entries shown or hidden, framed for before the view draws again.
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
    // Folded, it may fit over the view again; whole, no longer.
    this.#placeLegend();
    this.#main.overlaysChanged();
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
