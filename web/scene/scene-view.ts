/**
 * The view of one trace: its cells (scene/voxel-path.ts), the ideal path
 * (scene/ideal-path.ts), a labelled frame (scene/grid-axes.ts), and what the
 * mode adds: a second path (compare, overlaid; a learner's checked points), highlighted cells (the cells
 * one compared path visits and the other does not, the steps of a G-code
 * line), the decision overlay (scene/region-face.ts) and endpoint handles
 * (scene/endpoint-handles.ts). World units are grid units and z is up, as on
 * a machine.
 *
 * Two projections: 3d (perspective, orbiting) and 2d (orthographic, looking
 * down the normal of a planar path, with the pixel grid in its plane). The
 * camera can be read and set as a CameraState (the permalink's `camera`);
 * the user moving it (drag, wheel, or keys on the focused view) is reported.
 *
 * It renders on demand (after a change, a camera move or a resize), not every
 * frame: an idle page costs no CPU.
 */
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { CSS2DRenderer } from 'three/examples/jsm/renderers/CSS2DRenderer.js';
import type { IdealLine, PointBounds } from '../core/types.js';
import { formatPoint } from '../format.js';
import { idealLineOf } from '../ideal-line.js';
import type { CameraState, Projection } from '../state/app-state.js';
import { roundCamera } from '../state/query.js';
import { Cells, cellUniforms, setCellOrigin, softwareRenderer } from './cells.js';
import { EndpointHandles, type Handle } from './endpoint-handles.js';
import { GridAxes } from './grid-axes.js';
import { FAT_LINE_POINTS, IdealPath } from './ideal-path.js';
import { LIGHT_DRAWING_SPAN, pointBounds } from './light-drawing.js';
import { PALETTE } from './palette.js';
import { heldPoints, type PathPoints, type PathStyle, SAMPLED_POINTS, sampled, VoxelPath } from './voxel-path.js';

/** Vertical field of view, degrees. */
const FOV_DEG = 35;
/**
 * Direction from the path's center to the camera: in front (-y), above (+z)
 * and a little to the right (+x), so x runs to the right and y recedes up and
 * to the right, as in an oblique drawing.
 */
const VIEW_DIRECTION = new THREE.Vector3(0.6, -1.4, 0.9).normalize();
/** Children of the view starting this close to its top (px) lie over it there (#topInset)... */
const OVERLAY_TOP_PX = 16;
/** ...and take at most this share of its height from the framed picture; so does what stands over its bottom (#bottomInset). */
const MAX_INSET = 0.3;
/** Rounds of framing (#fit): each centers the picture and brings the camera in; three settle it within a pixel or so. */
const FIT_ROUNDS = 4;
/** Room around the cells for the axis arrows and tick labels: grid units, and a share of the path's size. */
const FRAME_MARGIN = 1.3;
const FRAME_MARGIN_SHARE = 0.08;
/**
 * The 3D framing (#fit) keeps this many pixels free at each edge of the
 * view, for the labels and handles drawn at the path's ends and corners
 * (pixel-sized however large the path is), and widens what it frames by a
 * share of the path's size for the ticks, which stand that far out, and for
 * the z axis's arrow and name above the path.
 */
const FIT_EDGE_PX = 26;
const FIT_EDGE_SHARE = 0.06;
const FIT_TICK_SHARE = 0.04;
const FIT_Z_TIP_SHARE = 0.14;
/**
 * Following the current cell (setFollow), the view is at least this close:
 * about this many cells from its top to its bottom, so a cell and its
 * decision overlay read however long the path.
 */
const FOLLOW_SPAN_CELLS = 14;
/** How much one press of + or - zooms the view. */
const KEY_ZOOM_FACTOR = 1.15;
/** Edge of a highlighted cell: larger than a path's cell, so it shows around it. */
const HIGHLIGHT_SIZE = 1.06;
/** A highlighted cube's fill: faint, so the cells inside show; its outline carries the colour. Points (a long path) have no outline: opaque. */
const HIGHLIGHT_FILL_OPACITY = 0.1;
const HIGHLIGHT_POINT_OPACITY = 0.9;
/** Edge of the second path's cells in an overlaid comparison: smaller, so the first shows around it (they are drawn over it). */
const SECOND_PATH_SIZE = 0.5;

/** What one trace gives the view: the summary parts it draws, and its points as the page holds them. */
export interface DrawnTrace extends PathPoints {
  start: number[];
  end: number[];
  /** The core's ideal polyline as the view draws it. */
  idealLine: IdealLine;
  /** The box every point lies in, as the core found it. */
  bounds: PointBounds;
  /** Per axis, when the grid is a machine's (a G-code program): its axes are labelled in mm. */
  stepsPerMm?: readonly number[];
}

/** Cells to pick out, flat with stride dims, in one colour. */
export interface Highlight {
  cells: Int32Array;
  dims: number;
  colour: string;
}

interface Drawn {
  voxels: VoxelPath;
  ideal: IdealPath;
  axes: GridAxes;
  /** Cell-inclusive bounds, grid units, for framing: the path's, widened on x and y to MIN_FLOOR_CELLS. */
  bounds: THREE.Box3;
  /** The axis (0..2) all points share a coordinate on, or undefined when the path is not planar. */
  planeNormal: number | undefined;
  /** Up to FRAMED_CELLS of the path's cells, evenly along it (the first and the last among them): what the 3D view frames. */
  framedCells: THREE.Vector3[];
}

/** Cells of a path the 3D framing looks at (#fit): enough to follow a helix's turns, few enough to project four times at once. */
const FRAMED_CELLS = 128;

/** Fewest cells the floor (the grid, and what is framed) spans on x and y. */
const MIN_FLOOR_CELLS = 5;

/** Up to `count` cells of `trace` evenly along the path (of the points the page holds), the last one included. */
function sampleCells(trace: DrawnTrace, count: number): THREE.Vector3[] {
  const { sampledPoints: points, dims } = trace;
  const cells = points.length / dims;
  const every = Math.max(1, Math.ceil((cells - 1) / (count - 1)));
  const out: THREE.Vector3[] = [];
  const cell = (p: ArrayLike<number>) => new THREE.Vector3(p[0]!, p[1]!, dims > 2 ? p[2]! : 0);
  for (let k = 0; k < cells; k = k === cells - 1 ? cells : Math.min(k + every, cells - 1)) out.push(cell(points.subarray(k * dims, (k + 1) * dims)));
  // A path sent as a sample may not hold its last point; its summary does.
  if (trace.pointsEvery > 1 && trace.steps % trace.pointsEvery !== 0) out.push(cell(trace.end));
  return out;
}

/** `bounds` on the scene's three axes: 0 on an axis the path lacks (axes past the third are not drawn). */
function sceneCorners(bounds: PointBounds): { min: THREE.Vector3; max: THREE.Vector3 } {
  const corner = (values: readonly number[]) => new THREE.Vector3(values[0] ?? 0, values[1] ?? 0, values[2] ?? 0);
  return { min: corner(bounds.min), max: corner(bounds.max) };
}

/**
 * The 2D view looks down the plane's normal from its positive end, with
 * this screen-up axis: the xy plane from +z (x right, y up), yz from +x (y
 * right, z up) and zx from +y (z right, x up, as a lathe's drawings put
 * them), so that a turn the page calls counterclockwise (G3), which is
 * counterclockwise seen from there, is counterclockwise on screen. The zx
 * plane seen from -y (the front, z up) showed every G18 arc the other way
 * round from its label.
 */
const PLANE_VIEWS: Record<number, { direction: THREE.Vector3; up: THREE.Vector3 }> = {
  0: { direction: new THREE.Vector3(1, 0, 0), up: new THREE.Vector3(0, 0, 1) },
  1: { direction: new THREE.Vector3(0, 1, 0), up: new THREE.Vector3(1, 0, 0) },
  2: { direction: new THREE.Vector3(0, 0, 1), up: new THREE.Vector3(0, 1, 0) },
};

export interface SceneCallbacks {
  /** The user moved the camera; the state is rounded as the permalink writes it, and the camera snapped to it. */
  onCamera(camera: CameraState): void;
  /** The user dragged or keyed an endpoint handle to a new grid point. */
  onHandle(name: string, point: number[]): void;
}

export class SceneView {
  readonly #container: HTMLElement;
  readonly #renderer: THREE.WebGLRenderer;
  readonly #labels: CSS2DRenderer;
  readonly #scene = new THREE.Scene();
  readonly #perspective = new THREE.PerspectiveCamera(FOV_DEG, 1, 0.1, 1e9);
  readonly #orthographic = new THREE.OrthographicCamera(-1, 1, 1, -1, 0.1, 1e9);
  readonly #controls: OrbitControls;
  readonly #callbacks: SceneCallbacks;
  readonly #handles: EndpointHandles;
  #projection: Projection = '3d';
  /** World units the 2D view shows top to bottom at zoom 1 (the framed path). */
  #orthoHeight = 10;
  #drawn: Drawn | undefined;
  #second: VoxelPath | undefined;
  #highlights: Cells[] = [];
  #overlay: THREE.Object3D | undefined;
  #renderPending = false;
  #pointIndex = 0;
  /** The camera moves with the current cell (setFollow). */
  #follow = false;
  /** A move of the camera closer to the current cell, held while that cell's point is on its way. */
  #followCloser = false;
  /** A close look at the current cell is asked for once (lookAtCurrentCell), taken when the cell is drawn. */
  #lookOnce = false;
  /** The camera is where resetView put it, not where the user or a link did: a resize frames the path again. */
  #framedByDefault = false;
  /** The container's size, CSS px, that the drawing and the labels were last sized to (#fitToContainer); 0 while it is hidden. */
  #sizedTo = { width: 0, height: 0 };
  /** The shares of the view's top and bottom that what lies over them took (#topInset, #bottomInset) when resetView last framed the path between them. */
  #framedInsets = { top: 0, bottom: 0 };
  /** Elements outside the view that may stand over its bottom (#bottomInset). */
  readonly #bottomOverlays: HTMLElement[] = [];
  /** Reports a change of size of what lies over the view (overlaysChanged). */
  readonly #overlays: ResizeObserver;
  /** False until a path has been drawn: before that the canvas stays undrawn (see #warmUp). */
  #drawnOnce = false;
  /** The warm-up's objects, kept so their compiled programs stay in three's cache. */
  readonly #warm = new THREE.Group();

  /** The colour of the path's visited cells: the second path's in the second view side by side. */
  readonly #visitedColour: string;

  /** Fills `container` (a positioned element) with the canvas and its label layer. */
  constructor(container: HTMLElement, callbacks: SceneCallbacks, label = 'path view', visitedColour: string = PALETTE.visited) {
    this.#container = container;
    this.#visitedColour = visitedColour;
    this.#callbacks = callbacks;
    this.#renderer = new THREE.WebGLRenderer({ antialias: !softwareRenderer(), preserveDrawingBuffer: false });
    this.#renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
    this.#renderer.setClearColor(PALETTE.background);
    const canvas = this.#renderer.domElement;
    canvas.dataset.testid = 'scene-canvas';
    canvas.setAttribute('role', 'img');
    canvas.setAttribute('aria-roledescription', label);
    // Focusable, so the keyboard can move the camera: arrows pan, Shift+arrows orbit, + and - zoom.
    canvas.tabIndex = 0;
    canvas.dataset.ownKeys = 'true';
    canvas.setAttribute('aria-keyshortcuts', 'ArrowLeft ArrowRight ArrowUp ArrowDown Shift+ArrowLeft Shift+ArrowRight Shift+ArrowUp Shift+ArrowDown + = -');
    this.#labels = new CSS2DRenderer();
    this.#labels.domElement.className = 'scene-labels';
    container.append(canvas, this.#labels.domElement);

    this.#perspective.up.set(0, 0, 1);
    this.#scene.add(new THREE.HemisphereLight('#ffffff', '#8a8a80', 2.2));
    const sun = new THREE.DirectionalLight('#ffffff', 1.6);
    sun.position.set(-0.7, -1.1, 1.6);
    this.#scene.add(sun);

    this.#controls = new OrbitControls(this.#perspective, canvas);
    this.#controls.keyPanSpeed = 20;
    this.#controls.listenToKeyEvents(canvas);
    this.#controls.addEventListener('change', () => this.requestRender());
    // A press that did not move the camera (a click to focus the view) is
    // not a camera the user placed: the view stays framed by default.
    let atStart = '';
    this.#controls.addEventListener('start', () => (atStart = JSON.stringify(roundCamera(this.cameraState()))));
    this.#controls.addEventListener('end', () => {
      if (JSON.stringify(roundCamera(this.cameraState())) !== atStart) this.#reportCamera();
    });
    canvas.addEventListener('keydown', (event) => {
      // OrbitControls scales the camera's distance by the factor given to
      // dollyIn (and divides by it in dollyOut): under 1 comes closer.
      if (event.key === '+' || event.key === '=') this.#controls.dollyIn(1 / KEY_ZOOM_FACTOR);
      else if (event.key === '-') this.#controls.dollyOut(1 / KEY_ZOOM_FACTOR);
      else if (!event.key.startsWith('Arrow')) return;
      event.preventDefault();
      this.#reportCamera();
    });
    this.#handles = new EndpointHandles(this.#scene, () => this.#activeCamera(), canvas, {
      onMove: (name, point) => callbacks.onHandle(name, point),
      onDragged: () => this.requestRender(),
    });

    this.#warmUp();

    new ResizeObserver(() => {
      if (this.#fitToContainer()) this.requestRender();
    }).observe(container);
    // The legend and the tools over the view's top take their room from the
    // framed picture (#topInset): when they grow (a learner's points add two
    // legend entries) the path stood with its z axis under the legend.
    this.#overlays = new ResizeObserver(() => this.overlaysChanged());
    for (const child of container.children) if (child !== this.canvas && child !== this.#labels.domElement) this.#overlays.observe(child);
  }

  /**
   * Hands the GPU every shader program the view draws with, before any path
   * arrives. WebGL compiles and links asynchronously until a program is
   * first used, and ANGLE (Chromium's WebGL) also builds the program's
   * pipelines on its worker threads from the link on; on a software GPU
   * (SwiftShader, as in headless Chromium) that takes a few hundred
   * milliseconds for this set. Started here, it runs while the worker loads
   * the core and traces, instead of inside the first drawn frame, where the
   * main thread would wait for it. Until the first path is drawn nothing is
   * drawn at all: a drawn canvas is read back by the compositor (in software
   * compositing), which waits for the GPU just the same. The empty view
   * shows the container's background, the colour the canvas is cleared to.
   */
  #warmUp(): void {
    const box = new THREE.Box3(new THREE.Vector3(-0.5, -0.5, -0.5), new THREE.Vector3(LIGHT_DRAWING_SPAN + 0.5, 0.5, 0.5));
    // A path of each drawing (cubes; points plus near cubes), the current
    // cell, both kinds of ideal line (fat and plain), the frame and a highlight.
    const short = new Int32Array([0, 0, 0, 1, 0, 0]);
    const wide = new Int32Array([0, 0, 0, LIGHT_DRAWING_SPAN, 0, 0]);
    const longLine = idealLineOf(new Float64Array((FAT_LINE_POINTS + 1) * 3), 3);
    this.#warm.add(
      new VoxelPath(heldPoints(short, 3), box),
      new VoxelPath(heldPoints(wide, 3), box),
      new IdealPath(idealLineOf(new Float64Array([0, 0, 0, 1, 0, 0]), 3)),
      new IdealPath(longLine),
      new GridAxes(new THREE.Vector3(0, 0, 0), new THREE.Vector3(1, 1, 1), 3),
      new Cells(short, 3, { colour: PALETTE.onlyFirst, cellSize: HIGHLIGHT_SIZE, opacity: HIGHLIGHT_FILL_OPACITY, outline: true }, false, box),
      new Cells(short, 3, { colour: PALETTE.onlyFirst, cellSize: HIGHLIGHT_SIZE, opacity: HIGHLIGHT_POINT_OPACITY }, true, box),
      new VoxelPath(heldPoints(short, 3), box, { visited: PALETTE.second, cellSize: SECOND_PATH_SIZE, onTop: true }),
    );
    // The real scene's lights, so the lit materials get the programs the real frames use.
    this.#renderer.compile(this.#warm, this.#perspective, this.#scene);
  }

  /** The canvas, for export and tests. */
  get canvas(): HTMLCanvasElement {
    return this.#renderer.domElement;
  }

  #activeCamera(): THREE.PerspectiveCamera | THREE.OrthographicCamera {
    return this.#projection === '2d' ? this.#orthographic : this.#perspective;
  }

  /** Fits both cameras to the container's current shape (kept while it is hidden, with no shape). */
  #updateProjections(): void {
    const { clientWidth: width, clientHeight: height } = this.#container;
    if (width === 0 || height === 0) return;
    const aspect = width / height;
    this.#perspective.aspect = aspect;
    this.#perspective.updateProjectionMatrix();
    const h = this.#orthoHeight / 2;
    Object.assign(this.#orthographic, { left: -h * aspect, right: h * aspect, top: h, bottom: -h });
    this.#orthographic.updateProjectionMatrix();
  }

  #clear(): void {
    if (this.#drawn) {
      const { voxels, ideal, axes } = this.#drawn;
      this.#scene.remove(voxels, ideal, axes);
      voxels.dispose();
      ideal.dispose();
      axes.dispose();
      this.#drawn = undefined;
    }
    this.setSecond(undefined);
    this.setHighlights([]);
    this.setOverlay(undefined);
  }

  /**
   * Draws `trace` (undefined: nothing) at `pointIndex`, in `projection`
   * (2d only for a planar path), with `camera` or, when null, framed.
   */
  setTrace(trace: DrawnTrace | undefined, pointIndex: number, projection: Projection, camera: CameraState | null): void {
    this.#clear();
    const canvas = this.canvas;
    if (!trace) {
      canvas.setAttribute('aria-label', 'No path');
      this.requestRender();
      return;
    }
    const { min, max } = sceneCorners(trace.bounds);
    const flat = [0, 1, 2].filter((a) => min.getComponent(a) === max.getComponent(a));
    const planeNormal = trace.dims === 2 ? 2 : flat.length > 0 ? flat[flat.length - 1] : undefined;
    // The floor spans at least MIN_FLOOR_CELLS on x and y, the path in its
    // middle: a path of one cell, framed alone, filled the view with one
    // cube, its axis names off screen or over the legend.
    for (const axis of [0, 1]) {
      const short = MIN_FLOOR_CELLS - 1 - (max.getComponent(axis) - min.getComponent(axis));
      if (short <= 0) continue;
      min.setComponent(axis, min.getComponent(axis) - Math.floor(short / 2));
      max.setComponent(axis, max.getComponent(axis) + Math.ceil(short / 2));
    }
    const bounds = new THREE.Box3(min.clone().subScalar(0.5), max.clone().addScalar(0.5));
    const drawn: Drawn = {
      voxels: new VoxelPath(trace, bounds, { visited: this.#visitedColour }, () => this.#settled()),
      ideal: new IdealPath(trace.idealLine),
      axes: new GridAxes(min, max, trace.dims === 2 ? 2 : 3, trace.stepsPerMm),
      bounds,
      planeNormal,
      framedCells: sampleCells(trace, FRAMED_CELLS),
    };
    this.#scene.add(drawn.voxels, drawn.ideal, drawn.axes);
    this.#drawn = drawn;
    canvas.dataset.drawing = drawn.voxels.light ? 'points' : 'cubes';
    canvas.setAttribute(
      'aria-label',
      `${trace.steps + 1} cells from ${formatPoint(trace.start)} to ${formatPoint(trace.end)} along the ideal path` +
        `${drawn.voxels.light ? ', drawn as points' : ''}; focus and use the arrow keys to pan, Shift and arrows to orbit, + and - to zoom`,
    );
    this.#setProjection(projection);
    if (camera) this.setCamera(camera);
    else this.resetView();
    this.showPoint(pointIndex);
    if (this.#follow) this.#followCell(true);
  }

  /**
   * Follows the current cell (or stops): the camera comes close enough for a
   * cell to read (FOLLOW_SPAN_CELLS) and then moves with the cell at each
   * step, keeping its direction and any zoom or orbit the user adds.
   */
  setFollow(follow: boolean): void {
    if (follow === this.#follow) return;
    this.#follow = follow;
    this.canvas.dataset.follow = String(follow);
    if (follow) this.#followCell(true);
  }

  /**
   * Once (a check's "Go to point"): centres the view on the current cell, as
   * close as Follow comes, when it is drawn. A difference half-way along a
   * long path was outlined too small to see in the whole path's framing.
   */
  lookAtCurrentCell(): void {
    this.#lookOnce = true;
    this.#followCell(true);
  }

  /** Centres the view on the current cell; `closer`: also comes in to the following distance, if farther. */
  #followCell(closer: boolean): void {
    const drawn = this.#drawn;
    if (!drawn) return;
    const cell = drawn.voxels.currentCell;
    if (!cell) {
      // Its point is on its way from the worker: followed when it arrives (#settled).
      this.#followCloser ||= closer;
      return;
    }
    closer ||= this.#followCloser;
    this.#followCloser = false;
    this.#lookOnce = false;
    const camera = this.#activeCamera();
    const offset = camera.position.clone().sub(this.#controls.target);
    let zoom = this.#projection === '2d' ? this.#orthographic.zoom : 1;
    if (closer && this.#projection === '2d') {
      zoom = Math.max(zoom, this.#orthoHeight / FOLLOW_SPAN_CELLS);
    } else if (closer) {
      offset.setLength(Math.min(offset.length(), FOLLOW_SPAN_CELLS / 2 / Math.tan(THREE.MathUtils.degToRad(FOV_DEG / 2))));
    }
    this.setCamera({ position: cell.clone().add(offset).toArray(), target: cell.toArray(), zoom });
  }

  /** The path's cells asked of the worker have arrived and are drawn: the view draws again, and follows the current cell. */
  #settled(): void {
    this.#markCurrentCell();
    if (this.#follow || this.#lookOnce) this.#followCell(false);
    this.requestRender();
  }

  /** True when the path on screen lies in one plane, so the 2D view applies. */
  get planar(): boolean {
    return this.#drawn?.planeNormal !== undefined;
  }

  #setProjection(projection: Projection): void {
    this.#projection = projection === '2d' && this.planar ? '2d' : '3d';
    const camera = this.#activeCamera();
    this.#controls.object = camera;
    this.#controls.enableRotate = this.#projection === '3d';
    this.#drawn?.axes.setGridPlane(this.#projection === '2d' ? this.#drawn.planeNormal! : 2, this.#drawn.bounds);
    this.canvas.dataset.projection = this.#projection;
  }

  /** Switches between the 3D and the 2D view (2D only for a planar path), framing the path. */
  setProjection(projection: Projection): void {
    this.#setProjection(projection);
    this.resetView();
  }

  /** The camera, as the permalink keeps it. */
  cameraState(): CameraState {
    const camera = this.#activeCamera();
    return {
      position: camera.position.toArray(),
      target: this.#controls.target.toArray(),
      zoom: this.#projection === '2d' ? this.#orthographic.zoom : 1,
    };
  }

  /** Puts the camera where `state` says (no report: the state already holds it). */
  setCamera(state: CameraState): void {
    this.#framedByDefault = false;
    const camera = this.#activeCamera();
    camera.position.fromArray(state.position);
    this.#controls.target.fromArray(state.target);
    if (camera instanceof THREE.OrthographicCamera) camera.zoom = state.zoom;
    const distance = camera.position.distanceTo(this.#controls.target);
    camera.near = Math.max(distance / 1000, 1e-3);
    camera.far = distance * 100 + 1000;
    camera.updateProjectionMatrix();
    this.#controls.update();
    this.requestRender();
  }

  #reportCamera(): void {
    const state = roundCamera(this.cameraState());
    // Snap to what the link will say, so a link restores this very picture.
    this.setCamera(state);
    this.#callbacks.onCamera(state);
  }

  /** Shows the path (and the second one) after `pointIndex` steps, each at most its own. */
  showPoint(pointIndex: number): void {
    this.#pointIndex = pointIndex;
    if (this.#drawn) this.#drawn.voxels.show(Math.min(pointIndex, this.#drawn.voxels.steps));
    this.#second?.show(Math.min(pointIndex, this.#second.steps));
    this.#markCurrentCell();
    if (this.#follow) this.#followCell(false);
    this.requestRender();
  }

  /**
   * The canvas says where the current cell is drawn (x,y,z), empty while its
   * point is on its way, and what each path hands three.js (DrawnCounts, as
   * JSON; the second path's empty when there is none): for tests and tools.
   */
  #markCurrentCell(): void {
    this.canvas.dataset.currentCell = this.#drawn?.voxels.currentCell?.toArray().join(',') ?? '';
    this.canvas.dataset.pathDrawn = this.#drawn ? JSON.stringify(this.#drawn.voxels.drawnCounts) : '';
    this.canvas.dataset.secondDrawn = this.#second ? JSON.stringify(this.#second.drawnCounts) : '';
  }

  /**
   * A second path drawn over the first with smaller cells, in `colour` (an
   * overlaid comparison, a learner's checked points); undefined removes it.
   * With `centers`, also the line through its cells' centers in that
   * colour, drawn as its cells are (PathStyle.centers): a learner's path
   * mostly runs inside the rule's cells, and the line shows where it goes
   * there.
   */
  setSecond(trace: (PathPoints & Pick<DrawnTrace, 'bounds'>) | undefined, colour: string = PALETTE.second, centers?: PathStyle['centers']): void {
    if (this.#second) {
      this.#scene.remove(this.#second);
      this.#second.dispose();
      this.#second = undefined;
    }
    if (trace) {
      const { min, max } = sceneCorners(trace.bounds);
      const bounds = new THREE.Box3(min.subScalar(0.5), max.addScalar(0.5));
      this.#second = new VoxelPath(trace, bounds, { visited: colour, cellSize: SECOND_PATH_SIZE, onTop: true, centers }, () => {
        this.#markCurrentCell();
        this.requestRender();
      });
      this.#scene.add(this.#second);
      this.#second.show(Math.min(this.#pointIndex, this.#second.steps));
    }
    this.#markCurrentCell();
    this.requestRender();
  }

  /** Replaces the highlighted cells (outlined in their colour, drawn through the path). */
  setHighlights(highlights: readonly Highlight[]): void {
    for (const h of this.#highlights) {
      this.#scene.remove(h);
      h.dispose();
    }
    this.#highlights = highlights
      .filter((h) => h.cells.length > 0)
      .map((h) => {
        const light = this.#drawn?.voxels.light ?? false;
        // Drawn as points beside a path drawn as points, every n-th cell as
        // the path's own are, at most SAMPLED_POINTS: two lines of 1,400,000
        // steps compared differ in 2,800,000 cells, whose points took a
        // software GPU 1 to 2 s a frame, at every step.
        const every = light ? Math.max(1, Math.ceil(h.cells.length / h.dims / SAMPLED_POINTS)) : 1;
        const drawn = every > 1 ? sampled(h.cells, h.dims, every) : h.cells;
        // The box of the cells drawn, all that culling needs: found over
        // every highlighted cell (2,799,300 for two compared 1,400,000-step
        // lines), it took the main-thread task that shows them 20 ms more.
        const { min, max } = sceneCorners(pointBounds(drawn, h.dims));
        const bounds = new THREE.Box3(min.subScalar(0.5), max.addScalar(0.5));
        const style = light ? { opacity: HIGHLIGHT_POINT_OPACITY } : { opacity: HIGHLIGHT_FILL_OPACITY, outline: true };
        const cells = new Cells(drawn, h.dims, { colour: h.colour, cellSize: HIGHLIGHT_SIZE, ...style }, light, bounds);
        cells.setRange(0, drawn.length / h.dims);
        this.#scene.add(cells);
        return cells;
      });
    // The cells highlighted, and those drawn of them.
    this.canvas.dataset.highlighted = String(highlights.reduce((n, h) => n + h.cells.length / h.dims, 0));
    this.canvas.dataset.highlightsDrawn = String(this.#highlights.reduce((n, h) => n + h.count, 0));
    this.requestRender();
  }

  /** Replaces the decision overlay (undefined: none). The view disposes the old one. */
  setOverlay(overlay: (THREE.Object3D & { dispose(): void }) | undefined): void {
    // None before and none now (each new point while Decision in 3D is off): no frame to draw.
    if (!overlay && !this.#overlay) return;
    if (this.#overlay) {
      this.#scene.remove(this.#overlay);
      (this.#overlay as THREE.Object3D & { dispose(): void }).dispose();
    }
    this.#overlay = overlay;
    if (overlay) this.#scene.add(overlay);
    this.requestRender();
  }

  /** Endpoint handles to show (none: an empty list). */
  setHandles(handles: readonly Handle[]): void {
    this.#handles.set(handles);
    this.requestRender();
  }

  /**
   * Sizes the drawing to the container as it is laid out now, when that
   * changed: a path framed by default is framed for the new shape (a window
   * made narrower left the path's end outside the view); a camera the user
   * placed stays where they put it. False when nothing changed, or the
   * container is hidden (no shape: sized again when it shows).
   */
  #fitToContainer(): boolean {
    const { clientWidth: width, clientHeight: height } = this.#container;
    if (width === this.#sizedTo.width && height === this.#sizedTo.height) return false;
    this.#sizedTo = { width, height };
    if (width === 0 || height === 0) return false;
    this.#renderer.setSize(width, height);
    this.#labels.setSize(width, height);
    cellUniforms.halfHeightPx.value = (height * this.#renderer.getPixelRatio()) / 2;
    this.#updateProjections();
    if (this.#framedByDefault) this.resetView();
    return true;
  }

  /**
   * What lies over the view's top (the legend, the tools) may have changed
   * size: a path framed by default is framed again below it when it takes
   * another share of the view than the framing was made for. What changes
   * them calls it before the next frame, so that frame is drawn framed anew:
   * the overlays' ResizeObserver (which calls it too) reports a change only
   * after the layout of the frame that drew the path framed as before, and
   * framing it again then drew a second frame (a learner's checked points,
   * which add two legend entries, at the page's cap: two frames of 100 to
   * 210 ms each on a software GPU, the second only to move the camera).
   */
  overlaysChanged(): void {
    if (this.#framedByDefault && (this.#topInset() !== this.#framedInsets.top || this.#bottomInset() !== this.#framedInsets.bottom)) this.resetView();
  }

  /**
   * `element`, outside the view, may stand over its bottom (the embedded
   * page's Open in voxpath link, in its corner): where it does, the picture
   * is framed above it (#bottomInset), as below the legend and the tools.
   */
  frameAbove(element: HTMLElement): void {
    this.#bottomOverlays.push(element);
    this.#overlays.observe(element);
    this.overlaysChanged();
  }

  /** Frames the whole path from the default direction (3D) or the plane's normal (2D). */
  resetView(): void {
    const drawn = this.#drawn;
    if (!drawn) return;
    // Below the legend and the tools, and above what stands over the bottom: the picture fills what they leave.
    const insets = { top: this.#topInset(), bottom: this.#bottomInset() };
    if (this.#projection === '2d') {
      const view = PLANE_VIEWS[drawn.planeNormal!]!;
      const extent = drawn.bounds.getSize(new THREE.Vector3());
      const box = drawn.bounds.clone().expandByScalar(FRAME_MARGIN + FRAME_MARGIN_SHARE * Math.max(extent.x, extent.y, extent.z));
      // The axes' names too, as the 3D framing keeps them.
      for (const tip of drawn.axes.nameTips) box.expandByPoint(tip);
      const size = box.getSize(new THREE.Vector3());
      const right = new THREE.Vector3().crossVectors(view.up, view.direction);
      const width = Math.abs(size.dot(right));
      const height = Math.abs(size.dot(view.up));
      const aspect = this.#container.clientWidth / Math.max(1, this.#container.clientHeight);
      const free = 1 - insets.top - insets.bottom;
      this.#orthoHeight = Math.max(height / free, width / aspect, 2);
      this.#updateProjections();
      // The camera looks above the box's center by as much as the free part's middle is below the view's.
      const center = box.getCenter(new THREE.Vector3()).addScaledVector(view.up, (insets.top - insets.bottom) * (this.#orthoHeight / 2));
      const distance = size.length() + 10;
      this.#orthographic.up.copy(view.up);
      this.#orthographic.zoom = 1;
      this.setCamera({ position: center.clone().addScaledVector(view.direction, distance).toArray(), target: center.toArray(), zoom: 1 });
    } else {
      this.#fit(VIEW_DIRECTION, drawn, insets);
    }
    this.#framedInsets = insets;
    this.#framedByDefault = true;
  }

  /**
   * Frames the path looking along -`direction` (a unit vector), filling the
   * view: the camera backs off until what is drawn (the floor with its
   * ticks, the z axis, the path's cells) is inside the view, a few pixels
   * from its edges for labels and handles, and is moved across so the picture is
   * centered (a path seen obliquely is not centered on its center), which lets
   * it come closer. A few rounds settle both. The path's cells, not its
   * bounding box: a diagonal line leaves most of its box empty. `insets`:
   * the shares of the view's height the legend and the tools take at its
   * top (#topInset) and what stands over its bottom takes there (#bottomInset).
   */
  #fit(direction: THREE.Vector3, drawn: Drawn, insets: { top: number; bottom: number }): void {
    // The container's shape now, not as the last resize report left it: a
    // layout change (side by side) reshapes the view in the same task that
    // frames the path, before any ResizeObserver callback.
    this.#updateProjections();
    const camera = this.#perspective;
    const bounds = drawn.bounds;
    const largest = Math.max(...bounds.getSize(new THREE.Vector3()).toArray());
    const right = new THREE.Vector3().crossVectors(camera.up, direction).normalize();
    const up = new THREE.Vector3().crossVectors(direction, right);
    const tanV = Math.tan(THREE.MathUtils.degToRad(FOV_DEG / 2));
    const tanH = tanV * camera.aspect;
    const ticks = FIT_TICK_SHARE * largest;
    const box = bounds.clone().expandByScalar(ticks);
    const corners: THREE.Vector3[] = [];
    // The floor with its ticks, the z axis's ticks up to the top of the
    // path (beside the axis, as far out as the floor's), and its tip above
    // its corner.
    for (let c = 0; c < 4; c++) corners.push(new THREE.Vector3(c & 1 ? box.max.x : box.min.x, c & 2 ? box.max.y : box.min.y, bounds.min.z));
    corners.push(new THREE.Vector3(box.min.x, box.min.y, bounds.max.z));
    corners.push(new THREE.Vector3(bounds.min.x, bounds.min.y, bounds.max.z + Math.max(1.5, FIT_Z_TIP_SHARE * largest)));
    // The axes' names, past their arrows' heads (x's was out of a small path's view).
    corners.push(...drawn.axes.nameTips);
    // Each framed cell, whole.
    for (const cell of drawn.framedCells) {
      for (let c = 0; c < 8; c++) corners.push(new THREE.Vector3(cell.x + (c & 1 ? 0.5 : -0.5), cell.y + (c & 2 ? 0.5 : -0.5), cell.z + (c & 4 ? 0.5 : -0.5)));
    }
    // The picture goes below the legend and the tools, above what stands over
    // the bottom, FIT_EDGE_PX from the edges: within `freeX` of `middleX`
    // across (-1..1, screen right), and within `freeY` of `middle` (screen up).
    const { clientWidth: width, clientHeight: height } = this.#container;
    // A small view (an embedded one) spares less of itself for the edges.
    const edge = Math.min(FIT_EDGE_PX, FIT_EDGE_SHARE * Math.min(width, height));
    // The tick labels that reach out of the picture need their width at the
    // sides and, under it, x's their height: they hang below their points at
    // the front edge, which a small view's edge (6 px in a 320 x 240 embed)
    // left 2 px short of.
    const { left, right: rightRoom, below } = drawn.axes.labelRoomPx;
    const [edgeLeft, edgeRight, edgeBottom] = [Math.max(edge, left), Math.max(edge, rightRoom), Math.max(edge, below)];
    const freeX = 1 - (edgeLeft + edgeRight) / Math.max(width, 1);
    const middleX = (edgeLeft - edgeRight) / Math.max(width, 1);
    const freeY = 1 - insets.top - insets.bottom - (edge + edgeBottom) / Math.max(height, 1);
    const middle = insets.bottom - insets.top + (edgeBottom - edge) / Math.max(height, 1);
    // The free part's edges, from the screen's middle where the camera looks
    // (-1..1): the room each way. The legend and the tools take the top, so
    // there is less room above the middle than below it.
    const [roomRight, roomLeft] = [freeX + middleX, freeX - middleX];
    const [roomUp, roomDown] = [freeY + middle, freeY - middle];
    const center = box.getCenter(new THREE.Vector3());
    let distance = 0;
    for (let round = 0; round < FIT_ROUNDS; round++) {
      // The distance at which every corner is inside the free part, looking
      // at `center`: each corner against the room on its own side. (Against
      // the room either side of the free part's middle, as if the camera
      // looked there, the shift below that centers the picture grew the
      // distance every round: under a legend a third of the view tall, a
      // picture 2.7 times too small.)
      distance = 0;
      for (const corner of corners) {
        const p = corner.clone().sub(center);
        // A corner nearer the camera (p . direction > 0) needs the camera farther back.
        const towardCamera = p.dot(direction);
        const [across, upward] = [p.dot(right), p.dot(up)];
        const needX = Math.abs(across) / (tanH * (across >= 0 ? roomRight : roomLeft));
        const needY = Math.abs(upward) / (tanV * (upward >= 0 ? roomUp : roomDown));
        distance = Math.max(distance, towardCamera + needX, towardCamera + needY);
      }
      // Where the corners land on screen from there (-1..1 each way), and the middle of their spread.
      const spread = { left: Infinity, right: -Infinity, bottom: Infinity, top: -Infinity };
      for (const corner of corners) {
        const p = corner.clone().sub(center);
        const depth = distance - p.dot(direction);
        const x = p.dot(right) / (depth * tanH);
        const y = p.dot(up) / (depth * tanV);
        spread.left = Math.min(spread.left, x);
        spread.right = Math.max(spread.right, x);
        spread.bottom = Math.min(spread.bottom, y);
        spread.top = Math.max(spread.top, y);
      }
      // Look so the middle of the picture is the middle of the free part, at about the same depth.
      center.addScaledVector(right, ((spread.left + spread.right) / 2 - middleX) * distance * tanH);
      center.addScaledVector(up, ((spread.bottom + spread.top) / 2 - middle) * distance * tanV);
    }
    this.setCamera({ position: center.clone().addScaledVector(direction, distance).toArray(), target: center.toArray(), zoom: 1 });
  }

  /** The share of the view's height (0..MAX_INSET) the framed picture leaves at its top to what lies over it there (#overlaidShare). */
  #topInset(): number {
    return Math.min(this.#overlaidShare(), MAX_INSET);
  }

  /**
   * The share of the view's height taken at its top by what lies over it
   * there (the legend, the view's tools): the other children of the
   * container that start at its top.
   */
  #overlaidShare(): number {
    const top = this.#container.getBoundingClientRect().top;
    const height = Math.max(1, this.#container.clientHeight);
    let bottom = 0;
    for (const child of this.#container.children) {
      if (child === this.canvas || child === this.#labels.domElement) continue;
      const box = child.getBoundingClientRect();
      if (box.height > 0 && box.top - top < OVERLAY_TOP_PX) bottom = Math.max(bottom, box.bottom - top);
    }
    return bottom / height;
  }

  /**
   * True when what lies over the view's top (the legend, the view's tools),
   * as laid out now, takes no more of its height than the framed picture
   * leaves it (MAX_INSET): taller, it covers the picture's top (the z
   * axis's name, the handle at a path's upper end).
   */
  overlaysFit(): boolean {
    return this.#overlaidShare() <= MAX_INSET;
  }

  /**
   * The share of the view's height (0..MAX_INSET) the framed picture
   * leaves at its bottom to what stands over it there (frameAbove): from the
   * top of each such element that overlaps the view's lower half.
   */
  #bottomInset(): number {
    const view = this.#container.getBoundingClientRect();
    const middle = view.top + view.height / 2;
    let top = view.bottom;
    for (const element of this.#bottomOverlays) {
      const box = element.getBoundingClientRect();
      if (box.width > 0 && box.height > 0 && box.left < view.right && view.left < box.right && box.top < view.bottom && box.top > middle) top = Math.min(top, box.top);
    }
    return Math.min((view.bottom - top) / Math.max(1, view.height), MAX_INSET);
  }

  /**
   * The view as a PNG: the drawing, with the labels drawn over it as they
   * stand (axis names, tick values in grid units or mm and steps, the
   * endpoint handles). The labels are HTML over the canvas, so the canvas
   * alone gave a picture without a coordinate to read.
   */
  toPng(): Promise<Blob> {
    this.#render();
    const picture = document.createElement('canvas');
    [picture.width, picture.height] = [this.canvas.width, this.canvas.height];
    const context = picture.getContext('2d')!;
    context.drawImage(this.canvas, 0, 0);
    const view = this.canvas.getBoundingClientRect();
    context.scale(picture.width / Math.max(1, view.width), picture.height / Math.max(1, view.height));
    const labels = this.#labels.domElement;
    // The handles' discs first, then every piece of label text on top, each
    // in its own font and colour, where the page shows it.
    for (const handle of labels.querySelectorAll<HTMLElement>('.handle')) {
      const box = handle.getBoundingClientRect();
      const style = getComputedStyle(handle);
      if (box.width === 0 || style.visibility !== 'visible') continue;
      context.beginPath();
      context.arc(box.left - view.left + box.width / 2, box.top - view.top + box.height / 2, box.width / 2 - 1, 0, 2 * Math.PI);
      context.fillStyle = style.backgroundColor;
      context.fill();
      context.lineWidth = parseFloat(style.borderTopWidth) || 2;
      context.strokeStyle = style.borderTopColor;
      context.stroke();
    }
    const texts = document.createTreeWalker(labels, NodeFilter.SHOW_TEXT);
    const range = document.createRange();
    for (let node = texts.nextNode(); node; node = texts.nextNode()) {
      const text = node.textContent?.trim();
      if (!text) continue;
      range.selectNodeContents(node);
      const box = range.getBoundingClientRect();
      const style = getComputedStyle(node.parentElement!);
      if (box.width === 0 || style.visibility !== 'visible') continue;
      context.font = `${style.fontStyle} ${style.fontWeight} ${style.fontSize} ${style.fontFamily}`;
      context.fillStyle = style.color;
      context.textAlign = 'center';
      context.textBaseline = 'middle';
      context.fillText(text, box.left - view.left + box.width / 2, box.top - view.top + box.height / 2);
    }
    return new Promise((resolve, reject) => picture.toBlob((blob) => (blob ? resolve(blob) : reject(new Error('the view could not be encoded as PNG'))), 'image/png'));
  }

  #render(): void {
    if (!this.#drawn && !this.#drawnOnce) return;
    this.#drawnOnce = true;
    const camera = this.#activeCamera();
    camera.updateMatrixWorld();
    // Cells and ideal lines drawn from the grid point looked at, so that
    // near it every number the GPU rounds is small (setCellOrigin, drawNear).
    const target = this.#controls.target;
    const lookedAt = new THREE.Vector3(Math.round(target.x), Math.round(target.y), Math.round(target.z));
    setCellOrigin(lookedAt);
    this.#drawn?.ideal.drawNear(lookedAt);
    this.#second?.drawNear(lookedAt);
    this.#handles.pinToView(camera, this.#controls.target);
    this.#drawn?.axes.showLegibleTicks(camera, this.#container.clientWidth, this.#container.clientHeight);
    this.#renderer.render(this.#scene, camera);
    this.#labels.render(this.#scene, camera);
  }

  requestRender(): void {
    if (this.#renderPending) return;
    this.#renderPending = true;
    requestAnimationFrame(() => {
      // Drawn for the container as laid out now. A change of its shape in
      // the tasks before this frame (the step reason's line shown under the
      // views with two compared paths) reaches the ResizeObserver only after
      // this frame's layout: sized and framed anew then, the view drew a
      // second frame, at two 1,400,000-step lines compared 80 to 160 ms of
      // a software GPU. Fitted while this frame is pending, so that the
      // framing's own request to draw is this frame, and the observer finds
      // nothing changed.
      this.#fitToContainer();
      this.#renderPending = false;
      this.#render();
    });
  }
}
