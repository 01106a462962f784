/**
 * Handles on a move's points (from, to, center) in the view: buttons placed
 * over the 3D scene, so each is focusable, labelled and announced like any
 * control. Drag one with the pointer (in the floor's plane in 3D, Shift to
 * move it up and down; in the view's plane in 2D), or focus it and press the
 * arrow keys (x and y) and Page Up / Page Down (z). The point moves on the
 * grid, one unit at a time.
 *
 * A point outside the view (say a `to` the core rejected as too far) keeps
 * its handle at the view's edge, toward the point and marked as pinned
 * there, so it can still be seen and dragged back.
 */
import * as THREE from 'three';
import { CSS2DObject } from 'three/examples/jsm/renderers/CSS2DRenderer.js';
import { formatPoint } from '../format.js';

export interface Handle {
  /** The option it edits (from, to, center). */
  name: string;
  /** The point, grid units, 2 or 3 axes. */
  point: number[];
}

interface Placed {
  object: CSS2DObject;
  button: HTMLButtonElement;
  point: number[];
}

/** How far from the view's center a pinned handle sits, in normalized device coordinates (1 is the edge). */
const PIN_EDGE = 0.9;

/** The letter on each point's handle. */
const HANDLE_LETTERS: Record<string, string> = { from: 'S', to: 'E', center: 'c' };

/** Keys that move a focused handle: [axis, change]. */
const KEY_MOVES: Record<string, [number, number]> = {
  ArrowLeft: [0, -1],
  ArrowRight: [0, 1],
  ArrowDown: [1, -1],
  ArrowUp: [1, 1],
  PageDown: [2, -1],
  PageUp: [2, 1],
};

export class EndpointHandles {
  readonly #scene: THREE.Scene;
  readonly #camera: () => THREE.Camera;
  readonly #canvas: HTMLCanvasElement;
  readonly #onMove: (name: string, point: number[]) => void;
  readonly #onDragged: () => void;
  readonly #placed = new Map<string, Placed>();

  constructor(
    scene: THREE.Scene,
    camera: () => THREE.Camera,
    canvas: HTMLCanvasElement,
    events: { onMove(name: string, point: number[]): void; onDragged(): void },
  ) {
    this.#scene = scene;
    this.#camera = camera;
    this.#canvas = canvas;
    this.#onMove = events.onMove;
    this.#onDragged = events.onDragged;
  }

  /** Shows exactly `handles`, reusing the buttons of names already shown (so focus stays put). */
  set(handles: readonly Handle[]): void {
    for (const [name, placed] of this.#placed) {
      if (handles.some((h) => h.name === name)) continue;
      this.#scene.remove(placed.object);
      placed.object.element.remove();
      this.#placed.delete(name);
    }
    for (const h of handles) {
      const placed = this.#placed.get(h.name) ?? this.#create(h.name);
      this.#place(h.name, placed, h.point);
    }
  }

  #create(name: string): Placed {
    const button = document.createElement('button');
    button.type = 'button';
    button.className = 'handle';
    button.dataset.testid = `handle-${name}`;
    // The page's own keys (arrows step the path) give way to a focused handle.
    button.dataset.ownKeys = 'true';
    button.setAttribute('aria-keyshortcuts', 'ArrowLeft ArrowRight ArrowUp ArrowDown PageUp PageDown');
    const object = new CSS2DObject(button);
    const placed: Placed = { object, button, point: [] };
    button.addEventListener('keydown', (event) => {
      const move = KEY_MOVES[event.key];
      if (!move || move[0] >= placed.point.length || event.altKey || event.ctrlKey || event.metaKey) return;
      event.preventDefault();
      const point = [...placed.point];
      point[move[0]]! += move[1];
      this.#moveTo(name, placed, point);
    });
    button.addEventListener('pointerdown', (event) => this.#drag(name, placed, event));
    this.#scene.add(object);
    this.#placed.set(name, placed);
    return placed;
  }

  /**
   * Before each frame: a handle whose point is outside the view seen by
   * `camera` is drawn at the view's edge toward it, `target` (the orbit
   * center) giving the depth.
   */
  pinToView(camera: THREE.Camera, target: THREE.Vector3): void {
    const depth = target.clone().project(camera).z;
    for (const placed of this.#placed.values()) {
      const point = new THREE.Vector3(placed.point[0] ?? 0, placed.point[1] ?? 0, placed.point[2] ?? 0);
      const eye = point.clone().applyMatrix4(camera.matrixWorldInverse);
      const ndc = point.clone().project(camera);
      // Behind a perspective camera the projection mirrors: the point lies the other way.
      if (camera instanceof THREE.PerspectiveCamera && eye.z > 0) ndc.multiplyScalar(-1);
      const reach = Math.max(Math.abs(ndc.x), Math.abs(ndc.y));
      const outside = reach > 1 || (camera instanceof THREE.PerspectiveCamera && eye.z > 0) || !(Math.abs(ndc.z) <= 1);
      if (outside) {
        const scale = PIN_EDGE / Math.max(reach, 1e-9);
        placed.object.position.set(ndc.x * scale, ndc.y * scale, depth).unproject(camera);
      } else {
        placed.object.position.copy(point);
      }
      placed.button.classList.toggle('pinned', outside);
    }
  }

  #place(name: string, placed: Placed, point: number[]): void {
    placed.point = [...point];
    placed.object.position.set(point[0] ?? 0, point[1] ?? 0, point[2] ?? 0);
    // S(tart) and E(nd), not A and B: the decision picture names its corners A to D.
    placed.button.textContent = HANDLE_LETTERS[name] ?? name[0]!.toUpperCase();
    placed.button.setAttribute('aria-label', `${name} ${formatPoint(point)}: drag, or use the arrow keys${point.length > 2 ? ' and Page Up / Page Down' : ''} to move it`);
    placed.button.title = `${name} ${formatPoint(point)}`;
  }

  #moveTo(name: string, placed: Placed, point: number[]): void {
    if (point.every((c, a) => c === placed.point[a])) return;
    this.#place(name, placed, point);
    this.#onDragged();
    this.#onMove(name, point);
  }

  /** Follows the pointer until it is released, moving the handle on the grid. */
  #drag(name: string, placed: Placed, down: PointerEvent): void {
    down.preventDefault();
    const button = placed.button;
    button.setPointerCapture(down.pointerId);
    const camera = this.#camera();
    const origin = placed.object.position.clone();
    const view = camera.getWorldDirection(new THREE.Vector3());
    const orthographic = camera instanceof THREE.OrthographicCamera;
    const plane = orthographic
      ? new THREE.Plane().setFromNormalAndCoplanarPoint(view, origin)
      : down.shiftKey
        ? new THREE.Plane().setFromNormalAndCoplanarPoint(new THREE.Vector3(view.x, view.y, 0).normalize(), origin)
        : new THREE.Plane(new THREE.Vector3(0, 0, 1), -origin.z);
    const raycaster = new THREE.Raycaster();
    const hit = new THREE.Vector3();
    const move = (event: PointerEvent) => {
      const rect = this.#canvas.getBoundingClientRect();
      const ndc = new THREE.Vector2(((event.clientX - rect.left) / rect.width) * 2 - 1, -((event.clientY - rect.top) / rect.height) * 2 + 1);
      raycaster.setFromCamera(ndc, camera);
      if (!raycaster.ray.intersectPlane(plane, hit)) return;
      const point = placed.point.map((_, a) => Math.round(hit.getComponent(a)));
      this.#moveTo(name, placed, point);
    };
    const up = () => {
      button.removeEventListener('pointermove', move);
      button.removeEventListener('pointerup', up);
      button.removeEventListener('pointercancel', up);
    };
    button.addEventListener('pointermove', move);
    button.addEventListener('pointerup', up);
    button.addEventListener('pointercancel', up);
  }
}
