/**
 * A path's cells, scrubbed to a point index without rebuilding: showing
 * point k only moves the drawings' ranges.
 * - visited: cells 0..k-1, solid;
 * - ahead: cells k+1..steps, faint, so the learner sees where the path is
 *   going while the solid cells show what the algorithm has decided so far;
 * - the current cell k, larger, with its edges outlined.
 *
 * Full drawing (below LIGHT_DRAWING_CELLS cells and LIGHT_DRAWING_SPAN grid
 * units): every cell is a cube, drawn straight from the trace's points;
 * `ahead` holds the points in reverse order, as cubes are drawn from the
 * start of their buffer.
 *
 * Lighter drawing (at or above either): the whole path as points, one for
 * every `every`-th cell so that at most SAMPLED_POINTS are drawn (a path
 * that long is far finer than the screen when framed whole), plus every
 * cell as a cube within NEAR_CELLS steps of the current one, where a learner
 * zooms in. The near window is rebuilt (a few kilobytes) when the current
 * point nears its edge.
 */
import * as THREE from 'three';
import { Cells, LIGHT_DRAWING_CELLS, LIGHT_DRAWING_SPAN } from './cells.js';
import { PALETTE } from './palette.js';

/** Drawn edge of a path's cell, grid units: a little under 1 so neighbouring cells stay apart. */
const CELL_SIZE = 0.84;
/** Drawn edge of the current cell: a little larger, so it stands out among its neighbours. */
const CURRENT_SIZE = 1.0;
/** The lighter drawing's marker of the current cell, CSS pixels: it stays this size however far out the view is. */
const CURRENT_MARKER_PX = 9;
/** The lighter drawing's points along the whole path, at most. */
export const SAMPLED_POINTS = 20_000;
/** The lighter drawing's cubes: every cell within this many steps of the current one. */
export const NEAR_CELLS = 2_000;

/** Rows of `points` (stride dims) in reverse order. */
function reversed(points: Int32Array, dims: number): Int32Array {
  const out = new Int32Array(points.length);
  // Value by value: a subarray and a set per row cost several times the copy.
  for (let from = 0, to = points.length - dims; from < points.length; from += dims, to -= dims) {
    for (let a = 0; a < dims; a++) out[to + a] = points[from + a]!;
  }
  return out;
}

/** Every `every`-th row of `points` (rows 0, every, 2 every, ...). */
function sampled(points: Int32Array, dims: number, every: number): Int32Array {
  const rows = Math.ceil(points.length / dims / every);
  const out = new Int32Array(rows * dims);
  for (let r = 0; r < rows; r++) {
    for (let a = 0; a < dims; a++) out[r * dims + a] = points[r * every * dims + a]!;
  }
  return out;
}

export interface PathStyle {
  /** Colour of visited cells. */
  visited: string;
  /** Edge of visited and ahead cells, grid units. */
  cellSize?: number;
  /** Cells drawn over what is drawn before them (CellStyle.onTop): the second path of an overlaid comparison. */
  onTop?: boolean;
}

/** Cubes for cells first..first + count - 1 of a path: visited from the start, ahead reversed. */
class CubeRun {
  readonly first: number;
  readonly count: number;
  readonly visited: Cells;
  readonly ahead: Cells;

  constructor(points: Int32Array, dims: number, first: number, count: number, bounds: THREE.Box3, style: PathStyle) {
    this.first = first;
    this.count = count;
    const run = points.subarray(first * dims, (first + count) * dims);
    const cellSize = style.cellSize ?? CELL_SIZE;
    const onTop = style.onTop;
    this.visited = new Cells(run, dims, { colour: style.visited, cellSize, opacity: 1, onTop }, false, bounds);
    this.ahead = new Cells(reversed(run, dims), dims, { colour: PALETTE.ahead, cellSize, opacity: 0.22, onTop }, false, bounds);
  }

  /** Shows the run's cells before point `pointIndex` as visited and those after it as ahead. */
  show(pointIndex: number): void {
    const split = Math.min(Math.max(pointIndex - this.first, 0), this.count);
    this.visited.setRange(0, split);
    this.ahead.setRange(0, Math.max(0, this.count - Math.max(split, pointIndex - this.first + 1)));
  }

  dispose(): void {
    this.visited.dispose();
    this.ahead.dispose();
  }
}

export class VoxelPath extends THREE.Group {
  readonly #points: Int32Array;
  readonly #dims: number;
  readonly #count: number;
  readonly #bounds: THREE.Box3;
  readonly #style: PathStyle;
  /** All cells as cubes (full drawing), or the cubes near the current point (lighter drawing). */
  #cubes: CubeRun | undefined;
  /** Lighter drawing: every #every-th cell as a point, visited and ahead sharing one buffer. */
  readonly #sampled: { visited: Cells; ahead: Cells; every: number } | undefined;
  readonly #current: THREE.Group;
  /** True when the path is drawn the lighter way (see the file's comment). */
  readonly light: boolean;

  /** `points`: flat, stride `dims`, one row per point index (the trace's points); `bounds`: the cells' box. */
  constructor(points: Int32Array, dims: number, bounds: THREE.Box3, style: PathStyle = { visited: PALETTE.visited }) {
    super();
    this.#points = points;
    this.#dims = dims;
    this.#count = points.length / dims;
    this.#bounds = bounds;
    this.#style = style;
    const size = bounds.getSize(new THREE.Vector3());
    this.light = this.#count >= LIGHT_DRAWING_CELLS || Math.max(size.x, size.y, size.z) >= LIGHT_DRAWING_SPAN;
    if (this.light) {
      const every = Math.max(1, Math.ceil(this.#count / SAMPLED_POINTS));
      const rows = sampled(points, dims, every);
      const cellSize = style.cellSize ?? CELL_SIZE;
      const onTop = style.onTop;
      const visited = new Cells(rows, dims, { colour: style.visited, cellSize, opacity: 1, onTop }, true, bounds);
      const ahead = new Cells(rows, dims, { colour: PALETTE.ahead, cellSize, opacity: 0.35, onTop }, true, bounds, visited.attribute);
      this.#sampled = { visited, ahead, every };
      this.add(visited, ahead);
    } else {
      this.#cubes = new CubeRun(points, dims, 0, this.#count, bounds, style);
      this.add(this.#cubes.visited, this.#cubes.ahead);
    }

    const currentBox = new THREE.BoxGeometry(CURRENT_SIZE, CURRENT_SIZE, CURRENT_SIZE);
    this.#current = new THREE.Group();
    this.#current.add(
      new THREE.Mesh(currentBox, new THREE.MeshLambertMaterial({ color: PALETTE.current })),
      new THREE.LineSegments(new THREE.EdgesGeometry(currentBox), new THREE.LineBasicMaterial({ color: PALETTE.ideal })),
    );
    if (this.light) {
      // A path drawn as points is framed far out, where the current cube is under a pixel: a marker of a fixed size shows where it is.
      const marker = new THREE.BufferGeometry().setAttribute('position', new THREE.Float32BufferAttribute([0, 0, 0], 3));
      const dot = new THREE.Points(marker, new THREE.PointsMaterial({ color: PALETTE.current, size: CURRENT_MARKER_PX, sizeAttenuation: false }));
      // Over the ideal path (drawn at 2), which passes through it.
      dot.renderOrder = 3;
      this.#current.add(dot);
    }
    this.add(this.#current);
  }

  /** Where the current cell is, grid units. */
  get currentCell(): THREE.Vector3 {
    return this.#current.position.clone();
  }

  /** Steps of the path (its last point index). */
  get steps(): number {
    return this.#count - 1;
  }

  /** Shows the path after `pointIndex` steps. */
  show(pointIndex: number): void {
    if (this.#sampled) {
      const { visited, ahead, every } = this.#sampled;
      // Sampled row r is point r * every.
      const split = Math.ceil(pointIndex / every);
      const rows = Math.ceil(this.#count / every);
      visited.setRange(0, split);
      ahead.setRange(split, rows - split);
      this.#nearWindow(pointIndex);
    }
    this.#cubes?.show(pointIndex);
    const p = this.#points.subarray(pointIndex * this.#dims, (pointIndex + 1) * this.#dims);
    this.#current.position.set(p[0]!, p[1]!, this.#dims > 2 ? p[2]! : 0);
  }

  /** Lighter drawing: cubes for the cells near `pointIndex`, rebuilt when it nears the window's edge. */
  #nearWindow(pointIndex: number): void {
    const cubes = this.#cubes;
    const margin = NEAR_CELLS / 2;
    const inside = cubes && pointIndex - cubes.first >= Math.min(margin, cubes.first) && cubes.first + cubes.count - pointIndex >= Math.min(margin, this.#count - cubes.first - cubes.count);
    if (inside) return;
    if (cubes) {
      this.remove(cubes.visited, cubes.ahead);
      cubes.dispose();
    }
    const first = Math.max(0, pointIndex - NEAR_CELLS);
    const count = Math.min(this.#count, pointIndex + NEAR_CELLS + 1) - first;
    this.#cubes = new CubeRun(this.#points, this.#dims, first, count, this.#bounds, this.#style);
    this.add(this.#cubes.visited, this.#cubes.ahead);
  }

  /** Releases the GPU buffers of this path. */
  dispose(): void {
    this.#cubes?.dispose();
    this.#sampled?.visited.dispose();
    this.#sampled?.ahead.dispose();
    this.#current.traverse((o) => {
      if (o instanceof THREE.Mesh || o instanceof THREE.LineSegments || o instanceof THREE.Points) {
        o.geometry.dispose();
        (o.material as THREE.Material).dispose();
      }
    });
  }
}
