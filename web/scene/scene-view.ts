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
import { formatPoint } from '../format.js';
import type { CameraState, Projection } from '../state/app-state.js';
import { roundCamera } from '../state/query.js';
import { Cells, LIGHT_DRAWING_SPAN, cellUniforms } from './cells.js';
import { EndpointHandles, type Handle } from './endpoint-handles.js';
import { GridAxes } from './grid-axes.js';
import { FAT_LINE_POINTS, IdealPath } from './ideal-path.js';
import { PALETTE } from './palette.js';
import { VoxelPath } from './voxel-path.js';

/** Vertical field of view, degrees. */
const FOV_DEG = 35;
/**
 * Direction from the path's center to the camera: in front (-y), above (+z)
 * and a little to the right (+x), so x runs to the right and y recedes up and
 * to the right, as in an oblique drawing.
 */
const VIEW_DIRECTION = new THREE.Vector3(0.6, -1.4, 0.9).normalize();
/** Room around the cells for the axis arrows and tick labels: grid units, and a share of the path's size. */
const FRAME_MARGIN = 1.3;
const FRAME_MARGIN_SHARE = 0.08;
/** How much one press of + or - zooms the view. */
const KEY_ZOOM_FACTOR = 1.15;
/** Edge of a highlighted cell: larger than a path's cell, so it shows around it. */
const HIGHLIGHT_SIZE = 1.06;
/** Edge of the second path's cells in an overlaid comparison: smaller, so the first shows around it. */
const SECOND_PATH_SIZE = 0.5;

/** Whether WebGL draws on the CPU, found once per page by softwareRenderer(). */
let software: boolean | undefined;

/**
 * True when WebGL draws on the CPU (SwiftShader, llvmpipe), as in headless
 * Chromium or on a machine without a usable GPU. There multisampling roughly
 * doubles the time of every frame (a long G-code program's frame: about
 * 220 ms with it, 120 ms without, on the project's 2-core test machine),
 * and the main thread waits for each frame, so the view is drawn without
 * antialiasing: jagged edges, but a page that answers in half the time.
 */
function softwareRenderer(): boolean {
  if (software === undefined) {
    const gl = document.createElement('canvas').getContext('webgl2');
    const info = gl?.getExtension('WEBGL_debug_renderer_info');
    const name = gl ? String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER)) : '';
    gl?.getExtension('WEBGL_lose_context')?.loseContext();
    software = /swiftshader|llvmpipe|software/i.test(name);
  }
  return software;
}

/** What one trace gives the view: the summary parts it draws. */
export interface DrawnTrace {
  dims: number;
  steps: number;
  start: number[];
  end: number[];
  points: Int32Array;
  idealPolyline: Float64Array;
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
  /** Cell-inclusive bounds, grid units, for framing. */
  bounds: THREE.Box3;
  /** The axis (0..2) all points share a coordinate on, or undefined when the path is not planar. */
  planeNormal: number | undefined;
}

/** The smallest and largest coordinate of the points on each of the first 3 axes (0 for a missing axis). */
export function pointBounds(points: Int32Array, dims: number): { min: THREE.Vector3; max: THREE.Vector3 } {
  const min = [Infinity, Infinity, dims > 2 ? Infinity : 0];
  const max = [-Infinity, -Infinity, dims > 2 ? -Infinity : 0];
  for (let o = 0; o < points.length; o += dims) {
    for (let a = 0; a < Math.min(dims, 3); a++) {
      const c = points[o + a]!;
      if (c < min[a]!) min[a] = c;
      if (c > max[a]!) max[a] = c;
    }
  }
  return { min: new THREE.Vector3(...min), max: new THREE.Vector3(...max) };
}

/**
 * The 2D view looks down the plane's normal from this side, with this
 * screen-up axis: the xy plane from above (y up), zx from the front and yz
 * from the right (z up), as drawings of those planes usually are.
 */
const PLANE_VIEWS: Record<number, { direction: THREE.Vector3; up: THREE.Vector3 }> = {
  0: { direction: new THREE.Vector3(1, 0, 0), up: new THREE.Vector3(0, 0, 1) },
  1: { direction: new THREE.Vector3(0, -1, 0), up: new THREE.Vector3(0, 0, 1) },
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
  /** A line through the second path's cell centres, when it has one (a learner's points). */
  #secondLine: IdealPath | undefined;
  #highlights: Cells[] = [];
  #overlay: THREE.Object3D | undefined;
  #renderPending = false;
  #pointIndex = 0;
  /** False until a path has been drawn: before that the canvas stays undrawn (see #warmUp). */
  #drawnOnce = false;
  /** The warm-up's objects, kept so their compiled programs stay in three's cache. */
  readonly #warm = new THREE.Group();

  /** Fills `container` (a positioned element) with the canvas and its label layer. */
  constructor(container: HTMLElement, callbacks: SceneCallbacks, label = 'path view') {
    this.#container = container;
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
    canvas.setAttribute('aria-keyshortcuts', 'ArrowLeft ArrowRight ArrowUp ArrowDown Shift+ArrowLeft Shift+ArrowRight + -');
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
    this.#controls.addEventListener('end', () => this.#reportCamera());
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
      const { clientWidth: width, clientHeight: height } = container;
      if (width === 0 || height === 0) return;
      this.#renderer.setSize(width, height);
      this.#labels.setSize(width, height);
      cellUniforms.halfHeightPx.value = (height * this.#renderer.getPixelRatio()) / 2;
      this.#updateProjections();
      this.requestRender();
    }).observe(container);
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
    const longLine = new Float64Array((FAT_LINE_POINTS + 1) * 3);
    this.#warm.add(
      new VoxelPath(short, 3, box),
      new VoxelPath(wide, 3, box),
      new IdealPath(new Float64Array([0, 0, 0, 1, 0, 0]), 3),
      new IdealPath(longLine, 3),
      new GridAxes(new THREE.Vector3(0, 0, 0), new THREE.Vector3(1, 1, 1), 3),
      new Cells(short, 3, { colour: PALETTE.onlyFirst, cellSize: HIGHLIGHT_SIZE, opacity: 0.55 }, false, box),
      new Cells(short, 3, { colour: PALETTE.onlyFirst, cellSize: HIGHLIGHT_SIZE, opacity: 0.55 }, true, box),
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
    const { min, max } = pointBounds(trace.points, trace.dims);
    const flat = [0, 1, 2].filter((a) => min.getComponent(a) === max.getComponent(a));
    const planeNormal = trace.dims === 2 ? 2 : flat.length > 0 ? flat[flat.length - 1] : undefined;
    const bounds = new THREE.Box3(min.clone().subScalar(0.5), max.clone().addScalar(0.5));
    const drawn: Drawn = {
      voxels: new VoxelPath(trace.points, trace.dims, bounds),
      ideal: new IdealPath(trace.idealPolyline, trace.dims),
      axes: new GridAxes(min, max, trace.dims === 2 ? 2 : 3),
      bounds,
      planeNormal,
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

  /** Shows the path (and the second one) after `pointIndex` steps. */
  showPoint(pointIndex: number): void {
    this.#pointIndex = pointIndex;
    this.#drawn?.voxels.show(pointIndex);
    this.#second?.show(Math.min(pointIndex, this.#second.steps));
    this.requestRender();
  }

  /**
   * A second path drawn over the first with smaller cells, in `colour` (an
   * overlaid comparison, a learner's checked points); undefined removes it.
   * With `throughCentres`, also a line through its cells' centres in that
   * colour: a learner's path mostly runs inside the rule's cells, and the
   * line shows where it goes there.
   */
  setSecond(trace: Pick<DrawnTrace, 'points' | 'dims'> | undefined, colour: string = PALETTE.second, throughCentres = false): void {
    if (this.#second) {
      this.#scene.remove(this.#second);
      this.#second.dispose();
      this.#second = undefined;
    }
    if (this.#secondLine) {
      this.#scene.remove(this.#secondLine);
      this.#secondLine.dispose();
      this.#secondLine = undefined;
    }
    if (trace && throughCentres) {
      this.#secondLine = new IdealPath(Float64Array.from(trace.points), trace.dims, colour);
      this.#scene.add(this.#secondLine);
    }
    if (trace) {
      const { min, max } = pointBounds(trace.points, trace.dims);
      const bounds = new THREE.Box3(min.subScalar(0.5), max.addScalar(0.5));
      this.#second = new VoxelPath(trace.points, trace.dims, bounds, { visited: colour, cellSize: SECOND_PATH_SIZE });
      this.#scene.add(this.#second);
      this.#second.show(Math.min(this.#pointIndex, this.#second.steps));
    }
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
        const { min, max } = pointBounds(h.cells, h.dims);
        const bounds = new THREE.Box3(min.subScalar(0.5), max.addScalar(0.5));
        const count = h.cells.length / h.dims;
        const cells = new Cells(h.cells, h.dims, { colour: h.colour, cellSize: HIGHLIGHT_SIZE, opacity: 0.55 }, (this.#drawn?.voxels.light ?? false), bounds);
        cells.setRange(0, count);
        this.#scene.add(cells);
        return cells;
      });
    this.canvas.dataset.highlighted = String(this.#highlights.reduce((n, h) => n + h.count, 0));
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

  /** Frames the whole path from the default direction (3D) or the plane's normal (2D). */
  resetView(): void {
    const drawn = this.#drawn;
    if (!drawn) return;
    if (this.#projection === '2d') {
      const view = PLANE_VIEWS[drawn.planeNormal!]!;
      const extent = drawn.bounds.getSize(new THREE.Vector3());
      const box = drawn.bounds.clone().expandByScalar(FRAME_MARGIN + FRAME_MARGIN_SHARE * Math.max(extent.x, extent.y, extent.z));
      const size = box.getSize(new THREE.Vector3());
      const right = new THREE.Vector3().crossVectors(view.up, view.direction);
      const width = Math.abs(size.dot(right));
      const height = Math.abs(size.dot(view.up));
      const aspect = this.#container.clientWidth / Math.max(1, this.#container.clientHeight);
      this.#orthoHeight = Math.max(height, width / aspect, 2);
      this.#updateProjections();
      const center = box.getCenter(new THREE.Vector3());
      const distance = size.length() + 10;
      this.#orthographic.up.copy(view.up);
      this.#orthographic.zoom = 1;
      this.setCamera({ position: center.clone().addScaledVector(view.direction, distance).toArray(), target: center.toArray(), zoom: 1 });
    } else {
      this.#fit(VIEW_DIRECTION, drawn.bounds);
    }
  }

  /**
   * Frames `bounds` looking along -`direction` (a unit vector): the camera
   * backs off until every corner of the box, widened for the axes and their
   * labels, is inside the view.
   */
  #fit(direction: THREE.Vector3, bounds: THREE.Box3): void {
    // The container's shape now, not as the last resize report left it: a
    // layout change (side by side) reshapes the view in the same task that
    // frames the path, before any ResizeObserver callback.
    this.#updateProjections();
    const camera = this.#perspective;
    // Room for the axis labels, which stand a few pixels outside the box however large the path is.
    const extent = bounds.getSize(new THREE.Vector3());
    const box = bounds.clone().expandByScalar(FRAME_MARGIN + FRAME_MARGIN_SHARE * Math.max(extent.x, extent.y, extent.z));
    const center = box.getCenter(new THREE.Vector3());
    const right = new THREE.Vector3().crossVectors(camera.up, direction).normalize();
    const up = new THREE.Vector3().crossVectors(direction, right);
    const tanV = Math.tan(THREE.MathUtils.degToRad(FOV_DEG / 2));
    const tanH = tanV * camera.aspect;
    let distance = 0;
    for (let corner = 0; corner < 8; corner++) {
      const p = new THREE.Vector3(
        corner & 1 ? box.max.x : box.min.x,
        corner & 2 ? box.max.y : box.min.y,
        corner & 4 ? box.max.z : box.min.z,
      ).sub(center);
      // A corner nearer the camera (p . direction > 0) needs the camera farther back.
      const towardCamera = p.dot(direction);
      distance = Math.max(distance, towardCamera + Math.abs(p.dot(right)) / tanH, towardCamera + Math.abs(p.dot(up)) / tanV);
    }
    this.setCamera({ position: center.clone().addScaledVector(direction, distance).toArray(), target: center.toArray(), zoom: 1 });
  }

  /** The view as a PNG (the canvas; labels are HTML and not in it). */
  toPng(): Promise<Blob> {
    this.#render();
    return new Promise((resolve, reject) => this.canvas.toBlob((blob) => (blob ? resolve(blob) : reject(new Error('the view could not be encoded as PNG'))), 'image/png'));
  }

  #render(): void {
    if (!this.#drawn && !this.#drawnOnce) return;
    this.#drawnOnce = true;
    const camera = this.#activeCamera();
    this.#renderer.render(this.#scene, camera);
    this.#labels.render(this.#scene, camera);
  }

  requestRender(): void {
    if (this.#renderPending) return;
    this.#renderPending = true;
    requestAnimationFrame(() => {
      this.#renderPending = false;
      this.#render();
    });
  }
}
