/**
 * The two candidates of one step of Saleem's circle (section 4, eq. 6-7) in
 * the 3D view: the cell the step reached (the current cell) and the cell it
 * did not take, one cell along the slow axis, both outlined; the one taken
 * solid and thicker, the other dashed; each labelled with which candidate it
 * is (stay: only the fast axis stepped; move: the slow axis stepped too) and
 * its residual x² + y² − r², the one taken boxed. With the ideal circle the
 * scene already draws, it shows why the step went where it did: the taken
 * residual is the one nearer 0.
 *
 * Everything is placed from the core's picture of the step (ArcCandidates:
 * each candidate's cell, residual and whether it was taken), the value the
 * inspector's figure draws too; the page derives none of it. In a helix the
 * cells are at the reached point's height.
 *
 * Drawn over the cells (overlay-group.ts), as the exit face is: the taken
 * candidate is the current cell, whose cube would hide its outline.
 */
import * as THREE from 'three';
import type { CSS2DObject } from 'three/examples/jsm/renderers/CSS2DRenderer.js';
import type { ArcCandidates } from '../core/types.js';
import { sceneLabel } from './grid-axes.js';
import { OverlayGroup } from './overlay-group.js';
import { PALETTE } from './palette.js';

/** Half the outline's edge, cells: just outside the unit cube of a cell, so the outline shows around it. */
const HALF_EDGE = 0.56;
/** Outline widths, CSS pixels: the candidate taken, the other. */
const TAKEN_LINE_PX = 4;
const OTHER_LINE_PX = 2.5;
/** Dashes of the other candidate's outline, grid units. */
const DASH = 0.14;
/** Labels sit this far from their cell's center, cells, away from the other candidate (along the slow axis). */
const LABEL_OFFSET = 1.05;

/** "−8": a residual as the label shows it, with a true minus sign. */
const signed = (v: number) => (v < 0 ? `−${-v}` : String(v));

export class ArcCandidateCells extends OverlayGroup {
  /** The two `candidates` of one step (3 coordinates each, or 2 for a circle given in x and y, at z = 0). */
  constructor({ candidates }: ArcCandidates) {
    super();
    const [takenOne, otherOne] = candidates[0].taken ? candidates : [candidates[1], candidates[0]];
    // Drawn from the cell taken, where the overlay is placed: a WebGL float
    // of a coordinate near 2^30 is a multiple of 64 (setCellOrigin, cells.ts).
    this.position.fromArray([...takenOne.cell, 0]);
    const taken = new THREE.Vector3();
    const other = new THREE.Vector3().fromArray([...otherOne.cell, 0]).sub(this.position);
    // One cell along the slow axis: the candidates differ there only.
    const toOther = other.clone().sub(taken);

    this.#outline(other, OTHER_LINE_PX, true);
    this.#outline(taken, TAKEN_LINE_PX, false);
    const otherLabel = sceneLabel(`${otherOne.name}: ${signed(otherOne.residual)}`, 'scene-label candidate-label', other.clone().addScaledVector(toOther, LABEL_OFFSET));
    const takenLabel = sceneLabel(`${takenOne.name}: ${signed(takenOne.residual)}, taken`, 'scene-label candidate-label chosen', taken.clone().addScaledVector(toOther, -LABEL_OFFSET));
    // Zoomed out, the two anchors are a few pixels apart: the label whose
    // anchor is higher on screen stands above it and the other hangs below
    // its own, so they never cover each other (CSS2DObject.center is the
    // anchor within the label). Which anchor is higher depends on the
    // camera, so it is settled at every render (on a tie, the taken one).
    const standAbove = (label: CSS2DObject, partner: CSS2DObject) => {
      label.onBeforeRender = (_renderer, _scene, camera) => {
        const screenY = (o: CSS2DObject) => new THREE.Vector3().setFromMatrixPosition(o.matrixWorld).project(camera).y;
        const [mine, theirs] = [screenY(label), screenY(partner)];
        label.center.set(0.5, mine > theirs || (mine === theirs && label === takenLabel) ? 1 : 0);
      };
    };
    standAbove(otherLabel, takenLabel);
    standAbove(takenLabel, otherLabel);
    this.add(otherLabel, takenLabel);
  }

  /** The twelve edges of the cube of half edge HALF_EDGE around `center`. */
  #outline(center: THREE.Vector3, widthPx: number, dashed: boolean): void {
    const segments: number[] = [];
    const corner = (bits: number) => [0, 1, 2].map((a) => center.getComponent(a) + (bits & (1 << a) ? HALF_EDGE : -HALF_EDGE));
    for (let bits = 0; bits < 8; bits++) {
      for (let a = 0; a < 3; a++) {
        if (!(bits & (1 << a))) segments.push(...corner(bits), ...corner(bits | (1 << a)));
      }
    }
    this.lines(segments, widthPx, PALETTE.candidate, dashed ? { dash: DASH } : {});
  }
}
