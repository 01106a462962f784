/**
 * A path's cells, scrubbed to a point index without touching the GPU
 * buffers: the drawings below are filled once per trace, and showing point k
 * only moves their ranges.
 * - visited: cells 0..k-1, solid;
 * - ahead: cells k+1..steps, faint, so the learner sees where the path is
 *   going while the solid cells show what the algorithm has decided so far;
 * - the current cell k, larger, with its edges outlined.
 *
 * Up to LIGHT_DRAWING_CELLS cells are cubes; `ahead` then holds the points in
 * reverse order (cubes are drawn from the start of their buffer). From
 * LIGHT_DRAWING_CELLS on, both are points sharing the one buffer the worker
 * transferred, each drawing its own range.
 */
import * as THREE from 'three';
import { Cells, LIGHT_DRAWING_CELLS } from './cells.js';
import { PALETTE } from './palette.js';

/** Drawn edge of a path's cell, grid units: a little under 1 so neighbouring cells stay apart. */
const CELL_SIZE = 0.84;
/** Drawn edge of the current cell: a little larger, so it stands out among its neighbours. */
const CURRENT_SIZE = 1.0;

/** Rows of `points` (stride dims) in reverse order. */
function reversed(points: Int32Array, dims: number): Int32Array {
  const out = new Int32Array(points.length);
  const count = points.length / dims;
  for (let k = 0; k < count; k++) out.set(points.subarray(k * dims, (k + 1) * dims), (count - 1 - k) * dims);
  return out;
}

export interface PathStyle {
  /** Colour of visited cells. */
  visited: string;
  /** Edge of visited and ahead cells, grid units. */
  cellSize?: number;
}

export class VoxelPath extends THREE.Group {
  readonly #points: Int32Array;
  readonly #dims: number;
  readonly #count: number;
  readonly #visited: Cells;
  readonly #ahead: Cells;
  readonly #current: THREE.Group;
  /** True when the path is drawn as points (LIGHT_DRAWING_CELLS or more cells). */
  readonly light: boolean;

  /** `points`: flat, stride `dims`, one row per point index (the trace's points); `bounds`: the cells' box. */
  constructor(points: Int32Array, dims: number, bounds: THREE.Box3, style: PathStyle = { visited: PALETTE.visited }) {
    super();
    this.#points = points;
    this.#dims = dims;
    this.#count = points.length / dims;
    this.light = this.#count >= LIGHT_DRAWING_CELLS;
    const cellSize = style.cellSize ?? CELL_SIZE;
    this.#visited = new Cells(points, dims, { colour: style.visited, cellSize, opacity: 1 }, this.light, bounds);
    const ahead = { colour: PALETTE.ahead, cellSize, opacity: 0.22 };
    this.#ahead = this.light
      ? new Cells(points, dims, ahead, true, bounds, this.#visited.attribute)
      : new Cells(reversed(points, dims), dims, ahead, false, bounds);

    const currentBox = new THREE.BoxGeometry(CURRENT_SIZE, CURRENT_SIZE, CURRENT_SIZE);
    this.#current = new THREE.Group();
    this.#current.add(
      new THREE.Mesh(currentBox, new THREE.MeshLambertMaterial({ color: PALETTE.current })),
      new THREE.LineSegments(new THREE.EdgesGeometry(currentBox), new THREE.LineBasicMaterial({ color: PALETTE.ideal })),
    );
    this.add(this.#visited, this.#ahead, this.#current);
  }

  /** Steps of the path (its last point index). */
  get steps(): number {
    return this.#count - 1;
  }

  /** Shows the path after `pointIndex` steps. */
  show(pointIndex: number): void {
    this.#visited.setRange(0, pointIndex);
    const aheadCount = this.#count - 1 - pointIndex;
    this.#ahead.setRange(this.light ? pointIndex + 1 : 0, aheadCount);
    const p = this.#points.subarray(pointIndex * this.#dims, (pointIndex + 1) * this.#dims);
    this.#current.position.set(p[0]!, p[1]!, this.#dims > 2 ? p[2]! : 0);
  }

  /** Releases the GPU buffers of this path. */
  dispose(): void {
    this.#visited.dispose();
    this.#ahead.dispose();
    this.#current.traverse((o) => {
      if (o instanceof THREE.Mesh || o instanceof THREE.LineSegments) {
        o.geometry.dispose();
        (o.material as THREE.Material).dispose();
      }
    });
  }
}
