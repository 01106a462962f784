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
 */
import * as THREE from 'three';
import { Line2 } from 'three/examples/jsm/lines/Line2.js';
import { LineGeometry } from 'three/examples/jsm/lines/LineGeometry.js';
import { LineMaterial } from 'three/examples/jsm/lines/LineMaterial.js';
import type { IdealLine } from '../core/types.js';
import { PALETTE } from './palette.js';

/** Line width, CSS pixels. */
const WIDTH_PX = 3;
/** Polylines longer than this are drawn as a plain line (see above). */
export const FAT_LINE_POINTS = 1_000;

export class IdealPath extends THREE.Group {
  readonly #geometry: THREE.BufferGeometry;
  readonly #materials: THREE.Material[];

  /** `ideal` (a Trace's idealLine(), or idealLineOf a path's cell centers), drawn in `colour`. */
  constructor(ideal: IdealLine, colour: string = PALETTE.ideal) {
    super();
    const { xyz } = ideal;
    // The vertices are from their origin, which places the group: the
    // view's matrices, computed in doubles, take the origin off the camera's
    // position before WebGL's 32-bit floats see either.
    this.position.fromArray(ideal.origin);
    const count = xyz.length / 3;
    // A program that made no move (empty, or stopped at its first line) has
    // no ideal path; a line needs two points (and LineGeometry throws on none).
    if (count < 2) {
      this.#geometry = new THREE.BufferGeometry();
      this.#materials = [];
      return;
    }
    if (count > FAT_LINE_POINTS) {
      // The line's box as it came: three.js would otherwise make two more
      // passes over the vertices to cull it in the first frame (13 ms for a
      // 100,000-line program's 250,000 vertices). A wide line's geometry
      // finds its own.
      const box = new THREE.Box3(new THREE.Vector3(...ideal.min), new THREE.Vector3(...ideal.max));
      this.#geometry = new THREE.BufferGeometry();
      this.#geometry.setAttribute('position', new THREE.BufferAttribute(xyz, 3));
      this.#geometry.boundingBox = box;
      this.#geometry.boundingSphere = box.getBoundingSphere(new THREE.Sphere());
      this.#materials = [new THREE.LineBasicMaterial({ color: colour })];
      const line = new THREE.Line(this.#geometry, this.#materials[0]);
      line.renderOrder = 2;
      this.add(line);
      return;
    }
    const geometry = new LineGeometry();
    geometry.setPositions(xyz);
    this.#geometry = geometry;

    const visible = new LineMaterial({ color: colour, linewidth: WIDTH_PX });
    const hidden = new LineMaterial({
      color: colour,
      linewidth: WIDTH_PX * 0.75,
      dashed: true,
      dashSize: 0.22,
      gapSize: 0.16,
      transparent: true,
      opacity: 0.7,
      // Only where something nearer has already been drawn.
      depthFunc: THREE.GreaterDepth,
      depthWrite: false,
    });
    this.#materials = [visible, hidden];
    for (const material of [visible, hidden]) {
      const line = new Line2(geometry, material);
      line.computeLineDistances();
      // After every cell, transparent ones included, so the depth test sees them all.
      line.renderOrder = 2;
      this.add(line);
    }
  }

  dispose(): void {
    this.#geometry.dispose();
    for (const material of this.#materials) material.dispose();
  }
}
