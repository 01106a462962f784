/**
 * The ideal path, drawn from the core's polyline (the page never derives it).
 * It runs through the cells, so it is drawn twice: solid where nothing hides
 * it, dashed and fainter where a cell is in front, so the learner can follow
 * it through the voxels without losing depth.
 *
 * A polyline of more than FAT_LINE_POINTS points (a helix of many turns) is
 * drawn once, as a plain 1-pixel line: wide lines cost a quad per segment
 * twice over, which a software renderer feels, and at that length the path
 * is thin on screen anyway.
 *
 * Its vertices are drawn from a grid point near the point the view looks at
 * (drawNear, verticesFrom in web/ideal-line.ts), as the cells are
 * (setCellOrigin): from the path's start, the far end of a long path was
 * drawn a tenth of a cell off the cells there. Taking the whole line from
 * there again, now and then, was chosen over pieces of the line each with
 * its own origin, which would be a draw call per few thousand cells
 * (thousands for the page's longest paths, each of which a software
 * renderer feels in every frame), and over taking the vertices from the
 * point looked at in the vertex shader, which would read two attributes
 * per vertex in every frame of a 250,000-vertex program and cannot split
 * the segment a long line is.
 */
import * as THREE from 'three';
import { Line2 } from 'three/examples/jsm/lines/Line2.js';
import { LineGeometry } from 'three/examples/jsm/lines/LineGeometry.js';
import { LineMaterial } from 'three/examples/jsm/lines/LineMaterial.js';
import type { IdealLine } from '../core/types.js';
import { REBASE_CELLS, dashDistances, verticesFrom } from '../ideal-line.js';
import { PALETTE } from './palette.js';

/** Line width, CSS pixels. */
const WIDTH_PX = 3;
/** The hidden part's dashes and the gaps between them, grid units. */
const DASH_CELLS = 0.22;
const GAP_CELLS = 0.16;
/** Polylines longer than this are drawn as a plain line (see above). */
export const FAT_LINE_POINTS = 1_000;

export class IdealPath extends THREE.Group {
  readonly #ideal: IdealLine;
  readonly #fat: boolean;
  #geometry: THREE.BufferGeometry;
  readonly #materials: THREE.Material[];
  readonly #lines: (THREE.Line | Line2)[] = [];

  /** `ideal` (a Trace's idealLine(), or idealLineOf a path's cell centers), drawn in `colour`. */
  constructor(ideal: IdealLine, colour: string = PALETTE.ideal) {
    super();
    this.#ideal = ideal;
    const count = ideal.xyz.length / 3;
    this.#fat = count <= FAT_LINE_POINTS;
    // A program that made no move (empty, or stopped at its first line) has
    // no ideal path; a line needs two points (and LineGeometry throws on none).
    if (count < 2) {
      this.#geometry = new THREE.BufferGeometry();
      this.#materials = [];
      return;
    }
    if (!this.#fat) {
      this.#materials = [new THREE.LineBasicMaterial({ color: colour })];
    } else {
      const visible = new LineMaterial({ color: colour, linewidth: WIDTH_PX });
      const hidden = new LineMaterial({
        color: colour,
        linewidth: WIDTH_PX * 0.75,
        dashed: true,
        dashSize: DASH_CELLS,
        gapSize: GAP_CELLS,
        transparent: true,
        opacity: 0.7,
        // Only where something nearer has already been drawn.
        depthFunc: THREE.GreaterDepth,
        depthWrite: false,
      });
      this.#materials = [visible, hidden];
    }
    this.#geometry = this.#drawnFrom(ideal.origin);
    for (const material of this.#materials) {
      const line = this.#fat ? new Line2(this.#geometry as LineGeometry, material as LineMaterial) : new THREE.Line(this.#geometry, material);
      // After every cell, transparent ones included, so the depth test sees them all.
      line.renderOrder = 2;
      this.#lines.push(line);
      this.add(line);
    }
  }

  /**
   * Keeps the vertices drawn from near `point` (a grid point the view looks
   * at): once it is more than REBASE_CELLS from where they are taken from
   * on some axis, they are taken again from it (verticesFrom).
   */
  drawNear(point: THREE.Vector3): void {
    if (this.#lines.length === 0) return;
    const from = this.position;
    if (Math.max(Math.abs(point.x - from.x), Math.abs(point.y - from.y), Math.abs(point.z - from.z)) <= REBASE_CELLS) return;
    this.#geometry.dispose();
    this.#geometry = this.#drawnFrom(point.toArray());
    for (const line of this.#lines) line.geometry = this.#geometry;
  }

  /** The line's geometry, its vertices taken from the grid point `origin`, where the group is placed. */
  #drawnFrom(origin: [number, number, number]): THREE.BufferGeometry {
    const ideal = this.#ideal;
    // The view's matrices, computed in doubles, take the origin off the
    // camera's position before WebGL's 32-bit floats see either.
    this.position.fromArray(origin);
    const { xyz, splits } = verticesFrom(ideal, origin);
    if (this.#fat) {
      // A wide line's geometry finds its own box. Its distances along the
      // path place the dashes, as Line2.computeLineDistances would, but
      // exact where the learner looks (dashDistances).
      const geometry = new LineGeometry();
      geometry.setPositions(xyz);
      const distances = new THREE.InstancedInterleavedBuffer(dashDistances(ideal, origin, splits, DASH_CELLS + GAP_CELLS), 2, 1);
      geometry.setAttribute('instanceDistanceStart', new THREE.InterleavedBufferAttribute(distances, 1, 0));
      geometry.setAttribute('instanceDistanceEnd', new THREE.InterleavedBufferAttribute(distances, 1, 1));
      return geometry;
    }
    // The line's box as it came, from `origin`: three.js would otherwise
    // make two more passes over the vertices to cull it in the first frame
    // (13 ms for a 100,000-line program's 250,000 vertices). Split points
    // lie on its segments, inside it.
    const shift = new THREE.Vector3().fromArray(ideal.origin).sub(this.position);
    const box = new THREE.Box3(new THREE.Vector3(...ideal.min).add(shift), new THREE.Vector3(...ideal.max).add(shift));
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(xyz, 3));
    geometry.boundingBox = box;
    geometry.boundingSphere = box.getBoundingSphere(new THREE.Sphere());
    return geometry;
  }

  dispose(): void {
    this.#geometry.dispose();
    for (const material of this.#materials) material.dispose();
  }
}
