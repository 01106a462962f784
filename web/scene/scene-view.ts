/**
 * The 3D view of one trace: its cells (scene/voxel-path.ts), the ideal path
 * (scene/ideal-path.ts) and a labelled frame (scene/grid-axes.ts), with orbit
 * controls. World units are grid units and z is up, as on a machine.
 *
 * It renders on demand (after a change, a camera move or a resize), not every
 * frame: an idle page costs no CPU.
 */
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { CSS2DRenderer } from 'three/examples/jsm/renderers/CSS2DRenderer.js';
import { formatPoint } from '../format.js';
import type { RemoteTrace } from '../worker/client.js';
import { GridAxes } from './grid-axes.js';
import { IdealPath } from './ideal-path.js';
import { PALETTE } from './palette.js';
import { VoxelPath } from './voxel-path.js';

/** Vertical field of view, degrees. */
const FOV_DEG = 35;
/**
 * Direction from the path's centre to the camera: in front (-y), above (+z)
 * and a little to the right (+x), so x runs to the right and y recedes up and
 * to the right, as in an oblique drawing.
 */
const VIEW_DIRECTION = new THREE.Vector3(0.6, -1.4, 0.9).normalize();
/** Room around the cells for the axis arrows and tick labels, grid units. */
const FRAME_MARGIN = 1.3;

interface Drawn {
  voxels: VoxelPath;
  ideal: IdealPath;
  axes: GridAxes;
  /** Cell-inclusive bounds, grid units, for framing. */
  bounds: THREE.Box3;
}

/** The smallest and largest coordinate of the points on each of the first 3 axes (0 for a missing axis). */
function pointBounds(points: Int32Array, dims: number): { min: THREE.Vector3; max: THREE.Vector3 } {
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

export class SceneView {
  readonly #renderer: THREE.WebGLRenderer;
  readonly #labels: CSS2DRenderer;
  readonly #scene = new THREE.Scene();
  readonly #camera = new THREE.PerspectiveCamera(FOV_DEG, 1, 0.1, 1e9);
  readonly #controls: OrbitControls;
  #drawn: Drawn | undefined;
  /** A path has been framed once: later paths keep the user's viewing angle. */
  #framed = false;
  #renderPending = false;

  /** Fills `container` (a positioned element) with the canvas and its label layer. */
  constructor(container: HTMLElement) {
    this.#renderer = new THREE.WebGLRenderer({ antialias: true });
    this.#renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
    this.#renderer.setClearColor(PALETTE.background);
    const canvas = this.#renderer.domElement;
    canvas.dataset.testid = 'scene-canvas';
    canvas.setAttribute('role', 'img');
    canvas.setAttribute('aria-label', '3D view of the path');
    this.#labels = new CSS2DRenderer();
    this.#labels.domElement.className = 'scene-labels';
    this.#labels.domElement.setAttribute('aria-hidden', 'true');
    container.append(canvas, this.#labels.domElement);

    this.#camera.up.set(0, 0, 1);
    this.#scene.add(new THREE.HemisphereLight('#ffffff', '#8a8a80', 2.2));
    const sun = new THREE.DirectionalLight('#ffffff', 1.6);
    // Lit from front-left-above, so the three visible faces of a cell differ in shade.
    sun.position.set(-0.7, -1.1, 1.6);
    this.#scene.add(sun);

    this.#controls = new OrbitControls(this.#camera, canvas);
    this.#controls.addEventListener('change', () => this.requestRender());

    new ResizeObserver(() => {
      const { clientWidth: width, clientHeight: height } = container;
      if (width === 0 || height === 0) return;
      this.#renderer.setSize(width, height);
      this.#labels.setSize(width, height);
      this.#camera.aspect = width / height;
      this.#camera.updateProjectionMatrix();
      this.requestRender();
    }).observe(container);
  }

  /** Draws `trace` (undefined: nothing) at `pointIndex`, and frames it. */
  setTrace(trace: RemoteTrace | undefined, pointIndex: number): void {
    if (this.#drawn) {
      const { voxels, ideal, axes } = this.#drawn;
      this.#scene.remove(voxels, ideal, axes);
      voxels.dispose();
      ideal.dispose();
      axes.dispose();
      this.#drawn = undefined;
    }
    const canvas = this.#renderer.domElement;
    if (!trace) {
      canvas.setAttribute('aria-label', '3D view: no path');
      this.requestRender();
      return;
    }
    const { min, max } = pointBounds(trace.points, trace.dims);
    const drawn: Drawn = {
      voxels: new VoxelPath(trace.points, trace.dims),
      ideal: new IdealPath(trace.idealPolyline, trace.dims),
      axes: new GridAxes(min, max),
      bounds: new THREE.Box3(min.clone().subScalar(0.5), max.clone().addScalar(0.5)),
    };
    this.#scene.add(drawn.voxels, drawn.ideal, drawn.axes);
    this.#drawn = drawn;
    canvas.setAttribute(
      'aria-label',
      `3D view: ${trace.steps + 1} cells from ${formatPoint(trace.start)} to ${formatPoint(trace.end)} along the ideal path; drag to orbit, scroll to zoom`,
    );
    // Keep the angle the user orbited to; only the first path gets the default one.
    this.#fit(this.#framed ? this.#camera.position.clone().sub(this.#controls.target).normalize() : VIEW_DIRECTION);
    this.#framed = true;
    this.showPoint(pointIndex);
  }

  /** Shows the path after `pointIndex` steps. */
  showPoint(pointIndex: number): void {
    this.#drawn?.voxels.show(pointIndex);
    this.requestRender();
  }

  /** Points the camera at the whole path from the default direction. */
  resetView(): void {
    this.#fit(VIEW_DIRECTION);
  }

  /**
   * Frames the whole path, looking along -`direction` (a unit vector): the
   * camera backs off until every corner of the cells' box, widened for the
   * axes and their labels, is inside the view.
   */
  #fit(direction: THREE.Vector3): void {
    const bounds = this.#drawn?.bounds;
    if (!bounds) return;
    const box = bounds.clone().expandByScalar(FRAME_MARGIN);
    const center = box.getCenter(new THREE.Vector3());
    const right = new THREE.Vector3().crossVectors(this.#camera.up, direction).normalize();
    const up = new THREE.Vector3().crossVectors(direction, right);
    const tanV = Math.tan(THREE.MathUtils.degToRad(FOV_DEG / 2));
    const tanH = tanV * this.#camera.aspect;
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
    this.#camera.position.copy(center).addScaledVector(direction, distance);
    this.#camera.near = distance / 100;
    this.#camera.far = distance * 10;
    this.#camera.updateProjectionMatrix();
    this.#controls.target.copy(center);
    this.#controls.update();
    this.requestRender();
  }

  requestRender(): void {
    if (this.#renderPending) return;
    this.#renderPending = true;
    requestAnimationFrame(() => {
      this.#renderPending = false;
      this.#renderer.render(this.#scene, this.#camera);
      this.#labels.render(this.#scene, this.#camera);
    });
  }
}
