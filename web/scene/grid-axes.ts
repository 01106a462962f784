/**
 * A frame to read coordinates from: a grid whose lines are the cell
 * boundaries (half-integers), on the floor in 3D and in the path's plane
 * behind it in 2D (the pixel grid), x, y, z axes from the near corner of the
 * path's bounding box, and tick labels at integer coordinates (cell centers),
 * so a cell's position can be read off the picture.
 */
import * as THREE from 'three';
import { CSS2DObject } from 'three/examples/jsm/renderers/CSS2DRenderer.js';
import { AXIS_NAMES } from '../format.js';
import { PALETTE } from './palette.js';

/** At most this many tick labels per axis; longer axes label every 2nd, 5th, 10th... coordinate. */
const MAX_TICKS = 12;
/** At most this many grid lines per direction, for the same reason. */
const MAX_GRID_LINES = 120;

/** The smallest of 1, 2, 5, 10, 20, 50... that splits `extent` into at most `parts`. */
function niceStep(extent: number, parts: number): number {
  for (let decade = 1; ; decade *= 10) {
    for (const m of [1, 2, 5]) if (extent / (m * decade) <= parts) return m * decade;
  }
}

/** A text label at `position` in the scene, an HTML element drawn by the view's label layer. */
export function sceneLabel(text: string, className: string, position: THREE.Vector3): CSS2DObject {
  const element = document.createElement('span');
  element.className = className;
  element.textContent = text;
  const object = new CSS2DObject(element);
  object.position.copy(position);
  return object;
}

/** Which side of the cells the 2D grid lies on, per plane normal: away from the 2D camera (scene-view's PLANE_VIEWS). */
const FAR_SIDE: Record<number, 'min' | 'max'> = { 0: 'min', 1: 'max', 2: 'min' };

export class GridAxes extends THREE.Group {
  #grid: THREE.LineSegments | undefined;

  /**
   * `min` and `max`: the smallest and largest grid coordinate of the path on
   * each axis (3 axes); `axes`: how many axes to draw (2 leaves out z).
   */
  constructor(min: THREE.Vector3, max: THREE.Vector3, axes: number) {
    super();
    // The corner of the bounding box of the cells, not of their centers.
    const corner = min.clone().subScalar(0.5);
    const size = max.clone().sub(min).addScalar(1);
    const floor = corner.z;

    const reach = 1.2;
    const directions = [new THREE.Vector3(1, 0, 0), new THREE.Vector3(0, 1, 0), new THREE.Vector3(0, 0, 1)].slice(0, axes);
    directions.forEach((direction, axis) => {
      const length = size.getComponent(axis) + reach;
      this.add(new THREE.ArrowHelper(direction, corner, length, PALETTE.axis, 0.45, 0.25));
      const tip = corner.clone().addScaledVector(direction, length + 0.45);
      this.add(sceneLabel(AXIS_NAMES[axis]!, 'scene-label axis-name', tip));
      // Ticks sit just outside the box: x along the front edge, z beside its
      // axis, y along the far-x edge of the floor, away from z's ticks.
      const base = [
        new THREE.Vector3(0, corner.y - 0.6, floor),
        new THREE.Vector3(corner.x + size.x + 0.6, 0, floor),
        new THREE.Vector3(corner.x - 0.45, corner.y - 0.45, 0),
      ][axis]!;
      const step = niceStep(size.getComponent(axis), MAX_TICKS);
      const first = Math.ceil(min.getComponent(axis) / step) * step;
      for (let c = first; c <= max.getComponent(axis); c += step) {
        this.add(sceneLabel(String(c), 'scene-label tick', base.clone().setComponent(axis, c)));
      }
    });
  }

  /**
   * Draws the grid in the plane normal to axis `normal` (2 = the floor),
   * through the far side of `bounds` (the cells' box), its lines on the cell
   * boundaries.
   */
  setGridPlane(normal: number, bounds: THREE.Box3): void {
    if (this.#grid) {
      this.remove(this.#grid);
      this.#grid.geometry.dispose();
      (this.#grid.material as THREE.Material).dispose();
    }
    const [u, v] = [0, 1, 2].filter((a) => a !== normal) as [number, number];
    const size = bounds.getSize(new THREE.Vector3());
    const level = (FAR_SIDE[normal] === 'min' ? bounds.min : bounds.max).getComponent(normal);
    const grid: number[] = [];
    const line = (a: THREE.Vector3, b: THREE.Vector3) => grid.push(a.x, a.y, a.z, b.x, b.y, b.z);
    for (const [along, across] of [
      [u, v],
      [v, u],
    ] as const) {
      const step = niceStep(size.getComponent(along), MAX_GRID_LINES);
      for (let t = 0; t <= size.getComponent(along) + 1e-9; t += step) {
        const a = bounds.min.clone().setComponent(normal, level);
        a.setComponent(along, bounds.min.getComponent(along) + t);
        const b = a.clone().setComponent(across, bounds.max.getComponent(across));
        line(a, b);
      }
    }
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.Float32BufferAttribute(grid, 3));
    this.#grid = new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ color: PALETTE.grid }));
    this.add(this.#grid);
  }

  dispose(): void {
    this.traverse((o) => {
      if (o instanceof THREE.Line || o instanceof THREE.Mesh) {
        o.geometry.dispose();
        (o.material as THREE.Material).dispose();
      }
      // A label leaves the DOM by itself only when its own object is removed,
      // not when a parent group is, as happens here.
      if (o instanceof CSS2DObject) o.element.remove();
    });
  }
}
