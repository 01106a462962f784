/**
 * The path's cells. A voxel is the unit cube centred on an integer grid point.
 *
 * Both instance buffers are filled once per trace, sized to the whole path;
 * scrubbing only moves each mesh's `count`, so stepping through a path costs
 * nothing however long it is:
 * - `visited` holds the points in path order, and draws points 0..k-1;
 * - `ahead` holds them in reverse order, and draws points steps..k+1;
 * - point k itself is the highlighted current cell.
 * Cells ahead stay visible but faint, so the learner sees where the path is
 * going while the solid cells show what the algorithm has decided so far.
 */
import * as THREE from 'three';
import { PALETTE } from './palette.js';

/** Drawn edge of a visited cell, grid units: a little under 1 so neighbouring cells stay apart. */
const CELL_SIZE = 0.84;
/** Drawn edge of the current cell: a little larger, so it stands out among its neighbours. */
const CURRENT_SIZE = 1.0;

/** Writes the translation matrix of every point into `matrices`, in path order or reversed. */
function fillTranslations(matrices: Float32Array, points: Int32Array, dims: number, reversed: boolean): void {
  const count = points.length / dims;
  for (let k = 0; k < count; k++) {
    const o = (reversed ? count - 1 - k : k) * 16;
    matrices[o] = matrices[o + 5] = matrices[o + 10] = matrices[o + 15] = 1;
    matrices[o + 12] = points[k * dims]!;
    matrices[o + 13] = points[k * dims + 1]!;
    matrices[o + 14] = dims > 2 ? points[k * dims + 2]! : 0;
  }
}

export class VoxelPath extends THREE.Group {
  readonly #points: Int32Array;
  readonly #dims: number;
  readonly #count: number;
  readonly #visited: THREE.InstancedMesh<THREE.BoxGeometry, THREE.MeshLambertMaterial>;
  readonly #ahead: THREE.InstancedMesh<THREE.BoxGeometry, THREE.MeshBasicMaterial>;
  readonly #current: THREE.Group;

  /** `points`: flat, stride `dims`, one row per point index (the trace's points). */
  constructor(points: Int32Array, dims: number) {
    super();
    this.#points = points;
    this.#dims = dims;
    this.#count = points.length / dims;
    const cell = new THREE.BoxGeometry(CELL_SIZE, CELL_SIZE, CELL_SIZE);

    this.#visited = new THREE.InstancedMesh(cell, new THREE.MeshLambertMaterial({ color: PALETTE.visited }), this.#count);
    fillTranslations(this.#visited.instanceMatrix.array as Float32Array, points, dims, false);

    const aheadMaterial = new THREE.MeshBasicMaterial({ color: PALETTE.ahead, transparent: true, opacity: 0.22, depthWrite: false });
    this.#ahead = new THREE.InstancedMesh(cell, aheadMaterial, this.#count);
    fillTranslations(this.#ahead.instanceMatrix.array as Float32Array, points, dims, true);
    // After the opaque cells, so the faint ones blend over what is behind them.
    this.#ahead.renderOrder = 1;

    for (const mesh of [this.#visited, this.#ahead]) {
      // Bounds over all instances once, not per count change.
      mesh.computeBoundingSphere();
      mesh.computeBoundingBox();
    }

    const currentBox = new THREE.BoxGeometry(CURRENT_SIZE, CURRENT_SIZE, CURRENT_SIZE);
    this.#current = new THREE.Group();
    this.#current.add(
      new THREE.Mesh(currentBox, new THREE.MeshLambertMaterial({ color: PALETTE.current })),
      new THREE.LineSegments(new THREE.EdgesGeometry(currentBox), new THREE.LineBasicMaterial({ color: PALETTE.ideal })),
    );
    this.add(this.#visited, this.#ahead, this.#current);
  }

  /** Shows the path after `pointIndex` steps. */
  show(pointIndex: number): void {
    this.#visited.count = pointIndex;
    this.#ahead.count = this.#count - 1 - pointIndex;
    const p = this.#points.subarray(pointIndex * this.#dims, (pointIndex + 1) * this.#dims);
    this.#current.position.set(p[0]!, p[1]!, this.#dims > 2 ? p[2]! : 0);
  }

  /** Releases the GPU buffers of this path. */
  dispose(): void {
    this.#visited.geometry.dispose();
    this.#visited.material.dispose();
    this.#ahead.material.dispose();
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
