/**
 * A frame to read coordinates from: a grid whose lines are the cell
 * boundaries (half-integers), on the floor in 3D and in the path's plane
 * behind it in 2D (the pixel grid), x, y, z axes from the near corner of the
 * path's bounding box, and tick labels at integer coordinates (cell centers),
 * so a cell's position can be read off the picture. A machine's grid (a
 * G-code program) is labelled in mm, with the step each tick is at beside it,
 * as its move list counts mm.
 *
 * The grid reaches past the path by a margin and is drawn first, never
 * hiding anything: a path along its border (the square sample's) stands out
 * on it rather than vanishing into its lines.
 */
import * as THREE from 'three';
import { CSS2DObject } from 'three/examples/jsm/renderers/CSS2DRenderer.js';
import { AXIS_NAMES } from '../format.js';
import { PALETTE } from './palette.js';

/** At most this many tick labels per axis; longer axes label every 2nd, 5th, 10th... coordinate. */
const MAX_TICKS = 8;
/** Fewer for mm ticks, each wider with its step beside it. */
const MAX_MM_TICKS = 6;
/**
 * Where each axis's tick labels hang from their point (CSS2DObject.center):
 * x's below it, y's to its right, z's to its left, so each reads away from
 * the box and from the other axes' labels at the shared corners.
 */
const TICK_ANCHORS = [new THREE.Vector2(0.5, 0), new THREE.Vector2(0, 0.5), new THREE.Vector2(1, 0.5)];
/**
 * The same in the 2D view of the zx plane, seen from +y (scene-view's
 * PLANE_VIEWS): x runs up the screen along z's lowest edge and z across it
 * along x's, so x's labels stand left of their points and z's hang below
 * (with the 3D anchors each x label was centred on its own axis line).
 */
const ZX_TICK_ANCHORS = [new THREE.Vector2(1, 0.5), new THREE.Vector2(0, 0.5), new THREE.Vector2(0.5, 0)];
/** At most this many grid lines per direction: a pixel grid up to this size, a lighter reference beyond. */
const MAX_GRID_LINES = 48;
/** The grid's margin around the path, as a share of its largest extent (at least one line's spacing). */
const GRID_MARGIN_SHARE = 0.06;
/** How far each axis arrow reaches past the path: grid units, and a share of its largest extent, so its name stays clear of the last tick. */
const AXIS_REACH = 1.2;
const AXIS_REACH_SHARE = 0.09;
const TICK_PAD_SHARE = 0.035;

/** The smallest of 1, 2 or 5 times a power of ten (fractions too) that splits `extent` into at most `parts`. */
function niceStep(extent: number, parts: number): number {
  const rough = Math.max(extent, Number.MIN_VALUE) / parts;
  const decade = 10 ** Math.floor(Math.log10(rough));
  return [1, 2, 5, 10].map((m) => m * decade).find((step) => step >= rough * (1 - 1e-12))!;
}

/** `value` as a tick prints it: no more decimals than the tick spacing `step` has. */
function tickText(value: number, step: number): string {
  return String(Number(value.toFixed(Math.max(0, -Math.floor(Math.log10(step))))));
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
const FAR_SIDE: Record<number, 'min' | 'max'> = { 0: 'min', 1: 'min', 2: 'min' };

/**
 * Rough widths of a tick's characters, CSS pixels (12 px digits, the unit
 * " mm" after them, 10 px for the steps beside mm), each a little over what
 * Chromium lays out (7.6, 27.2 and 6.4): enough to keep a label inside the
 * view when framing. Counted as digits at 7 px, '20 mm1600' took 71 px
 * where 65 were kept for it, and its last digit was cut at the view's edge.
 */
const TICK_CHAR_PX = 8;
const MM_UNIT_PX = 28;
const STEPS_CHAR_PX = 6.5;
/** A tick label's height (style.css .scene-label: 12 px, line-height 1), and the least room between two on screen, CSS pixels. */
const TICK_HEIGHT_PX = 12;
const TICK_SPACE_PX = 4;

/** A tick label and its rough width, CSS pixels. */
interface Tick {
  label: CSS2DObject;
  widthPx: number;
}

export class GridAxes extends THREE.Group {
  #grid: THREE.LineSegments | undefined;
  /**
   * How far the tick labels reach out of the picture from their points, CSS
   * pixels: y's to the right of the floor, z's to the left of its axis, x's
   * below its front edge. The view's framing keeps that much room at those
   * edges.
   */
  readonly labelRoomPx = { left: 0, right: 0, below: 0 };
  /** Where each axis's name stands, past its arrow's head: what a framing keeps in view with the path. */
  readonly nameTips: THREE.Vector3[] = [];
  /** Per axis, its tick labels, lowest coordinate first, which showLegibleTicks thins out where they would overlap. */
  readonly #ticks: Tick[][] = [];

  /**
   * `min` and `max`: the smallest and largest grid coordinate of the path on
   * each axis (3 axes); `axes`: how many axes to draw (2 leaves out z);
   * `stepsPerMm`: per axis, for a machine's grid labelled in mm.
   */
  constructor(min: THREE.Vector3, max: THREE.Vector3, axes: number, stepsPerMm?: readonly number[]) {
    super();
    // The corner of the bounding box of the cells, not of their centers.
    const corner = min.clone().subScalar(0.5);
    const size = max.clone().sub(min).addScalar(1);
    const floor = corner.z;
    const largest = Math.max(size.x, size.y, size.z);
    const reach = Math.max(AXIS_REACH, AXIS_REACH_SHARE * largest);
    // The ticks' distance from the box, grid units: a few pixels when framed, however large the path.
    const pad = Math.max(0.6, TICK_PAD_SHARE * largest);

    const directions = [new THREE.Vector3(1, 0, 0), new THREE.Vector3(0, 1, 0), new THREE.Vector3(0, 0, 1)].slice(0, axes);
    directions.forEach((direction, axis) => {
      const ticks: Tick[] = [];
      this.#ticks.push(ticks);
      const length = size.getComponent(axis) + reach;
      this.add(new THREE.ArrowHelper(direction, corner, length, PALETTE.axis, 0.375 * reach, 0.21 * reach));
      const tip = corner.clone().addScaledVector(direction, length + 0.375 * reach);
      this.add(sceneLabel(AXIS_NAMES[axis]!, 'scene-label axis-name', tip));
      this.nameTips.push(tip);
      // Ticks sit just outside the box: x along the front edge, z beside its
      // axis, y along the far-x edge of the floor, away from z's ticks.
      const base = [
        new THREE.Vector3(0, corner.y - pad, floor),
        new THREE.Vector3(corner.x + size.x + pad, 0, floor),
        new THREE.Vector3(corner.x - 0.75 * pad, corner.y - 0.75 * pad, 0),
      ][axis]!;
      const [low, high] = [min.getComponent(axis), max.getComponent(axis)];
      // y and z start at a corner of the box that x's ticks already label, beside x's own labels: their first tick is left out there.
      const shown = (c: number) => axis === 0 || c > low;
      const perMm = stepsPerMm?.[axis];
      if (perMm) {
        // Ticks at round mm, each at the step its mm rounds to (the machine's round(mm × steps/mm)).
        const step = niceStep((high - low + 1) / perMm, MAX_MM_TICKS);
        for (let k = Math.ceil(low / perMm / step); k * step * perMm <= high + 1e-9; k++) {
          const mm = k * step;
          if (!shown(mm * perMm)) continue;
          const number = tickText(mm, step);
          const text = `${number} mm`;
          const label = sceneLabel(text, 'scene-label tick', base.clone().setComponent(axis, mm * perMm));
          label.center.copy(TICK_ANCHORS[axis]!);
          const steps = document.createElement('span');
          steps.className = 'tick-steps';
          steps.textContent = String(Math.round(mm * perMm));
          label.element.append(steps);
          this.#addTick(axis, ticks, label, number.length * TICK_CHAR_PX + MM_UNIT_PX + (steps.textContent.length + 1) * STEPS_CHAR_PX);
        }
      } else {
        const step = Math.max(1, niceStep(size.getComponent(axis), MAX_TICKS));
        for (let c = Math.ceil(low / step) * step; c <= high; c += step) {
          if (!shown(c)) continue;
          const label = sceneLabel(String(c), 'scene-label tick', base.clone().setComponent(axis, c));
          label.center.copy(TICK_ANCHORS[axis]!);
          this.#addTick(axis, ticks, label, String(c).length * TICK_CHAR_PX);
        }
      }
    });
  }

  /** Adds a tick label of `axis`, about `widthPx` wide, to the scene and to the axis's `ticks`. */
  #addTick(axis: number, ticks: Tick[], label: CSS2DObject, widthPx: number): void {
    // Which axis it counts, for a reader of the page (and its tests).
    label.element.dataset.axis = AXIS_NAMES[axis];
    this.add(label);
    this.#reach(axis, widthPx);
    ticks.push({ label, widthPx });
  }

  /** Notes a tick label `widthPx` wide on `axis`: y's reach right by their width, z's left, x's hang below by their height. */
  #reach(axis: number, widthPx: number): void {
    if (axis === 0) this.labelRoomPx.below = TICK_HEIGHT_PX;
    if (axis === 1) this.labelRoomPx.right = Math.max(this.labelRoomPx.right, widthPx);
    if (axis === 2) this.labelRoomPx.left = Math.max(this.labelRoomPx.left, widthPx);
  }

  /**
   * Draws the grid in the plane normal to axis `normal` (2 = the floor),
   * through the far side of `bounds` (the cells' box), its lines on the cell
   * boundaries, a margin around the cells.
   */
  setGridPlane(normal: number, bounds: THREE.Box3): void {
    const anchors = normal === 1 ? ZX_TICK_ANCHORS : TICK_ANCHORS;
    this.#ticks.forEach((ticks, axis) => {
      for (const { label } of ticks) label.center.copy(anchors[axis]!);
    });
    if (this.#grid) {
      this.remove(this.#grid);
      this.#grid.geometry.dispose();
      (this.#grid.material as THREE.Material).dispose();
    }
    const [u, v] = [0, 1, 2].filter((a) => a !== normal) as [number, number];
    const size = bounds.getSize(new THREE.Vector3());
    const largest = Math.max(size.getComponent(u), size.getComponent(v));
    const step = Math.max(1, niceStep(largest * (1 + 2 * GRID_MARGIN_SHARE), MAX_GRID_LINES));
    // Whole steps of the grid, so its lines stay on cell boundaries.
    const margin = step * Math.ceil((GRID_MARGIN_SHARE * largest) / step);
    const area = bounds.clone();
    for (const a of [u, v]) {
      area.min.setComponent(a, bounds.min.getComponent(a) - margin);
      area.max.setComponent(a, bounds.max.getComponent(a) + margin);
    }
    const level = (FAR_SIDE[normal] === 'min' ? bounds.min : bounds.max).getComponent(normal);
    // The lines from a grid point at the area's corner, where the grid is
    // placed: a WebGL float of a coordinate near 2^30 is a multiple of 64
    // (see setCellOrigin in cells.ts).
    const origin = area.min.clone().floor();
    const grid: number[] = [];
    const line = (a: THREE.Vector3, b: THREE.Vector3) => grid.push(a.x - origin.x, a.y - origin.y, a.z - origin.z, b.x - origin.x, b.y - origin.y, b.z - origin.z);
    for (const [along, across] of [
      [u, v],
      [v, u],
    ] as const) {
      for (let t = area.min.getComponent(along); t <= area.max.getComponent(along) + 1e-9; t += step) {
        const a = area.min.clone().setComponent(normal, level).setComponent(along, t);
        line(a, a.clone().setComponent(across, area.max.getComponent(across)));
      }
    }
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.Float32BufferAttribute(grid, 3));
    // First and leaving no depth: whatever the path draws is over it.
    this.#grid = new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ color: PALETTE.grid, depthWrite: false }));
    this.#grid.position.copy(origin);
    this.#grid.renderOrder = -1;
    this.add(this.#grid);
  }

  /**
   * Shows each axis's tick labels as closely as they fit on screen as
   * `camera` sees them in a view `widthPx` by `heightPx`: every one, or every
   * 2nd, 5th, 10th... counted down from the axis's last, which always shows.
   * Each axis's spacing follows its own length, so one far shorter than the
   * longest (z to 8 beside x to 300, a program 5 mm wide and 120 mm long)
   * had its labels piled into a blot. Called before every render of the
   * labels, as the camera moves.
   */
  showLegibleTicks(camera: THREE.Camera, widthPx: number, heightPx: number): void {
    for (const ticks of this.#ticks) {
      // Each label's point on screen, CSS pixels.
      const points = ticks.map(({ label }) => {
        const p = label.getWorldPosition(new THREE.Vector3()).project(camera);
        return { x: (p.x * widthPx) / 2, y: (p.y * heightPx) / 2 };
      });
      // Two labels clear each other side by side, or one above the other.
      const apart = (i: number, j: number) =>
        Math.abs(points[i]!.x - points[j]!.x) >= (ticks[i]!.widthPx + ticks[j]!.widthPx) / 2 + TICK_SPACE_PX ||
        Math.abs(points[i]!.y - points[j]!.y) >= TICK_HEIGHT_PX + TICK_SPACE_PX;
      const fits = (every: number) => {
        for (let i = ticks.length - 1 - every; i >= 0; i -= every) if (!apart(i, i + every)) return false;
        return true;
      };
      // 1, 2, 5, 10, 20, 50...: the first that fits, else every label but the last is left out.
      let every = 1;
      for (let n = 1; every < ticks.length && !fits(every); n++) every = [1, 2, 5][n % 3]! * 10 ** Math.floor(n / 3);
      ticks.forEach(({ label }, i) => (label.visible = (ticks.length - 1 - i) % every === 0));
    }
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
