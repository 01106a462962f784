/**
 * A path's cells, scrubbed to a point index without rebuilding: showing
 * point k only moves the drawings' ranges.
 * - visited: cells 0..k-1, solid;
 * - ahead: cells k+1..steps, faint, so the learner sees where the path is
 *   going while the solid cells show what the algorithm has decided so far;
 * - the current cell k, larger, with its edges outlined.
 *
 * Full drawing (below lightDrawingCells() cells and LIGHT_DRAWING_SPAN grid
 * units): every cell is a cube, drawn straight from the trace's points;
 * `ahead` holds the points in reverse order, as cubes are drawn from the
 * start of their buffer.
 *
 * Lighter drawing (at or above either): the whole path as points, one for
 * every `every`-th cell so that at most SAMPLED_POINTS are drawn (a path
 * that long is far finer than the screen when framed whole), plus every
 * cell as a cube within NEAR_CELLS steps of the current one, where a learner
 * zooms in. The near window is rebuilt (a few kilobytes) when the current
 * point nears its edge. A path that long comes to the page as that sample
 * alone (PointsSent in the worker's protocol): the near window's points are
 * asked of the worker, and the current cell, when it is not a sampled one,
 * is drawn once they arrive.
 *
 * A path may also have a line through its cells' centers (PathStyle.centers:
 * a learner's, whose smaller cells run inside the rule's). It is drawn as the
 * cubes are: through every cell in the full drawing, through the cells near
 * the current one in the lighter drawing, made again with them. Through all
 * of a learner's 1,498,841 points it was a line of as many vertices, which
 * a software GPU took 0.7 to 1.6 s to draw in every frame.
 */
import * as THREE from 'three';
import type { IdealLine } from '../core/types.js';
import { idealLineOf } from '../ideal-line.js';
import { Cells, lightDrawingCells } from './cells.js';
import { IdealPath } from './ideal-path.js';
import { drawnLight } from './light-drawing.js';
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
const NEAR_CELLS = 2_000;

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
export function sampled(points: Int32Array, dims: number, every: number): Int32Array {
  const rows = Math.ceil(points.length / dims / every);
  const out = new Int32Array(rows * dims);
  for (let r = 0; r < rows; r++) {
    for (let a = 0; a < dims; a++) out[r * dims + a] = points[r * every * dims + a]!;
  }
  return out;
}

/**
 * A path's points as the view holds them (the page's RemoteTrace is one):
 * all of them, or every n-th with the others asked for by range.
 */
export interface PathPoints {
  readonly dims: number;
  /** The path's last point index. */
  readonly steps: number;
  /** Point indices 0, pointsEvery, 2 · pointsEvery, ..., flat with stride dims (every point when pointsEvery is 1). */
  readonly sampledPoints: Int32Array;
  readonly pointsEvery: number;
  /** Point index k's coordinates when they are among sampledPoints, else undefined. */
  point(pointIndex: number): ArrayLike<number> | undefined;
  /** Points fromPoint..toPoint, flat with stride dims. */
  pointsInRange(fromPoint: number, toPoint: number): Promise<Int32Array>;
}

/** PathPoints over points the page holds whole (a learner's). */
export function heldPoints(points: Int32Array, dims: number): PathPoints {
  return {
    dims,
    steps: points.length / dims - 1,
    sampledPoints: points,
    pointsEvery: 1,
    point: (pointIndex) => points.subarray(pointIndex * dims, (pointIndex + 1) * dims),
    pointsInRange: (fromPoint, toPoint) => Promise.resolve(points.slice(fromPoint * dims, toPoint * dims)),
  };
}

export interface PathStyle {
  /** Colour of visited cells. */
  visited: string;
  /** Edge of visited and ahead cells, grid units. */
  cellSize?: number;
  /** Cells drawn over what is drawn before them (CellStyle.onTop): the second path of an overlaid comparison. */
  onTop?: boolean;
  /**
   * A line through the cells' centers, when the path has one, drawn in the
   * visited colour (see the file's comment). The full drawing draws `whole`,
   * through every cell (idealLineOf the path's points, made off the main
   * thread); the lighter drawing makes its own through the cells near the
   * current one, and is given none (null: the worker makes a learner's only
   * for a path drawn whole, LearnerCheck in web/worker/protocol.ts).
   */
  centers?: { whole: IdealLine | null };
}

/** What a path hands three.js to draw: cells as points, cells as cubes, and vertices of its centers' line. */
export interface DrawnCounts {
  points: number;
  cubes: number;
  lineVertices: number;
}

/**
 * Cubes for cells first..first + count - 1 of a path (`run`, their points):
 * visited from the start, ahead reversed; and `centers`, the line through
 * them, when the path has one.
 */
class CubeRun {
  readonly first: number;
  readonly count: number;
  readonly #run: Int32Array;
  readonly #dims: number;
  readonly visited: Cells;
  readonly ahead: Cells;
  readonly line: IdealPath | undefined;
  readonly lineVertices: number;

  constructor(run: Int32Array, dims: number, first: number, bounds: THREE.Box3, style: PathStyle, centers: IdealLine | undefined) {
    this.first = first;
    this.count = run.length / dims;
    this.#run = run;
    this.#dims = dims;
    const cellSize = style.cellSize ?? CELL_SIZE;
    const onTop = style.onTop;
    this.visited = new Cells(run, dims, { colour: style.visited, cellSize, opacity: 1, onTop }, false, bounds);
    this.ahead = new Cells(reversed(run, dims), dims, { colour: PALETTE.ahead, cellSize, opacity: 0.22, onTop }, false, bounds);
    this.line = centers && new IdealPath(centers, style.visited);
    this.lineVertices = centers ? centers.xyz.length / 3 : 0;
  }

  /** The drawings of the run, to add to a scene or take out of it. */
  get objects(): THREE.Object3D[] {
    return this.line ? [this.visited, this.ahead, this.line] : [this.visited, this.ahead];
  }

  /** Point index k's coordinates, when the run holds it. */
  point(pointIndex: number): Int32Array | undefined {
    const r = pointIndex - this.first;
    return r >= 0 && r < this.count ? this.#run.subarray(r * this.#dims, (r + 1) * this.#dims) : undefined;
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
    this.line?.dispose();
  }
}

/** A window of point indices first..first + count - 1. */
interface Window {
  first: number;
  count: number;
}

export class VoxelPath extends THREE.Group {
  readonly #path: PathPoints;
  readonly #count: number;
  readonly #bounds: THREE.Box3;
  readonly #style: PathStyle;
  /** Called when cells asked of the worker have arrived and are drawn (the view draws again). */
  readonly #onSettled: () => void;
  /** All cells as cubes (full drawing), or the cubes near the current point (lighter drawing). */
  #cubes: CubeRun | undefined;
  /** The near window asked of the worker and not yet arrived (lighter drawing of a path sent as a sample). */
  #asked: Window | undefined;
  #pointIndex = 0;
  #disposed = false;
  /** Lighter drawing: every #every-th cell as a point, visited and ahead sharing one buffer. */
  readonly #sampled: { visited: Cells; ahead: Cells; every: number } | undefined;
  readonly #current: THREE.Group;
  /** True when the path is drawn the lighter way (see the file's comment). */
  readonly light: boolean;

  /** `path`: the path's points as the page holds them; `bounds`: the cells' box. */
  constructor(path: PathPoints, bounds: THREE.Box3, style: PathStyle = { visited: PALETTE.visited }, onSettled: () => void = () => undefined) {
    super();
    const { dims, sampledPoints, pointsEvery } = path;
    this.#path = path;
    this.#count = path.steps + 1;
    this.#bounds = bounds;
    this.#style = style;
    this.#onSettled = onSettled;
    const size = bounds.getSize(new THREE.Vector3());
    this.light = drawnLight(this.#count, Math.max(size.x, size.y, size.z), lightDrawingCells());
    if (this.light) {
      // A path held whole is sampled here; one sent as a sample is drawn as sent.
      const every = pointsEvery > 1 ? pointsEvery : Math.max(1, Math.ceil(this.#count / SAMPLED_POINTS));
      const rows = pointsEvery > 1 ? sampledPoints : sampled(sampledPoints, dims, every);
      const cellSize = style.cellSize ?? CELL_SIZE;
      const onTop = style.onTop;
      const visited = new Cells(rows, dims, { colour: style.visited, cellSize, opacity: 1, onTop }, true, bounds);
      const ahead = new Cells(rows, dims, { colour: PALETTE.ahead, cellSize, opacity: 0.35, onTop }, true, bounds, visited.attribute);
      this.#sampled = { visited, ahead, every };
      this.add(visited, ahead);
    } else {
      this.#setCubes(new CubeRun(this.#held({ first: 0, count: this.#count })!, dims, 0, bounds, style, style.centers?.whole ?? undefined));
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

  /** Where the current cell is, grid units; undefined while its point is on its way from the worker. */
  get currentCell(): THREE.Vector3 | undefined {
    return this.#current.visible ? this.#current.position.clone() : undefined;
  }

  /** Steps of the path (its last point index). */
  get steps(): number {
    return this.#count - 1;
  }

  /** Shows the path after `pointIndex` steps. */
  show(pointIndex: number): void {
    this.#pointIndex = pointIndex;
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
    const p = this.#cubes?.point(pointIndex) ?? this.#path.point(pointIndex);
    // A point neither drawn as a cube nor sampled is on its way (#nearWindow): the current cell shows when it arrives.
    this.#current.visible = p !== undefined;
    if (p) this.#current.position.set(p[0]!, p[1]!, this.#path.dims > 2 ? p[2]! : 0);
  }

  /** The points of `window` when the page holds every point of the path, else undefined (they are asked for). */
  #held(window: Window): Int32Array | undefined {
    const { sampledPoints, pointsEvery, dims } = this.#path;
    return pointsEvery === 1 ? sampledPoints.subarray(window.first * dims, (window.first + window.count) * dims) : undefined;
  }

  /** True when `window` reaches far enough either side of `pointIndex` that its cubes need not be rebuilt yet. */
  #covers(window: Window | undefined, pointIndex: number): boolean {
    const margin = NEAR_CELLS / 2;
    return (
      window !== undefined &&
      pointIndex - window.first >= Math.min(margin, window.first) &&
      window.first + window.count - pointIndex >= Math.min(margin, this.#count - window.first - window.count)
    );
  }

  /**
   * Lighter drawing: cubes for the cells near `pointIndex`, rebuilt when it
   * nears the window's edge. Asked of the worker, one window at a time: its
   * answer is drawn if it holds the current point and the cubes drawn do not
   * reach far enough around it (a late answer never replaces better cubes),
   * and asks again if the point has moved on meanwhile, so fast playback
   * beside a busy worker never queues requests up.
   */
  #nearWindow(pointIndex: number): void {
    if (this.#covers(this.#cubes, pointIndex)) return;
    const first = Math.max(0, pointIndex - NEAR_CELLS);
    const window = { first, count: Math.min(this.#count, pointIndex + NEAR_CELLS + 1) - first };
    const held = this.#held(window);
    if (held) {
      this.#setCubes(this.#nearRun(held, first));
      return;
    }
    if (this.#asked) return;
    this.#asked = window;
    this.#path.pointsInRange(window.first, window.first + window.count).then(
      (points) => {
        this.#asked = undefined;
        if (this.#disposed) return;
        const at = this.#pointIndex;
        if (at >= window.first && at < window.first + window.count && !this.#covers(this.#cubes, at)) {
          this.#setCubes(this.#nearRun(points, window.first));
        }
        this.show(at);
        this.#onSettled();
      },
      () => {
        // The trace went with its worker (a crash, which the page reports): the sample stays drawn.
        this.#asked = undefined;
      },
    );
  }

  /** Lighter drawing: the cubes of the cells from point `first` on (`points`), with the line through them when the path has one. */
  #nearRun(points: Int32Array, first: number): CubeRun {
    const { dims } = this.#path;
    return new CubeRun(points, dims, first, this.#bounds, this.#style, this.#style.centers && idealLineOf(points, dims));
  }

  /** Draws `cubes` in place of the cubes drawn before. */
  #setCubes(cubes: CubeRun): void {
    if (this.#cubes) {
      this.remove(...this.#cubes.objects);
      this.#cubes.dispose();
    }
    this.#cubes = cubes;
    this.add(...cubes.objects);
  }

  /** Keeps the line through the cells' centers, if any, drawn from near `point`, the grid point looked at (IdealPath.drawNear). */
  drawNear(point: THREE.Vector3): void {
    this.#cubes?.line?.drawNear(point);
  }

  /** What the path hands three.js now: for tests and tools, which check a long path is drawn by its sample. */
  get drawnCounts(): DrawnCounts {
    return { points: this.#sampled?.visited.count ?? 0, cubes: this.#cubes?.count ?? 0, lineVertices: this.#cubes?.lineVertices ?? 0 };
  }

  /** Releases the GPU buffers of this path. */
  dispose(): void {
    this.#disposed = true;
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
