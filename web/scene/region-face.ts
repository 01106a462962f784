/**
 * The exit face of one decision of Wang's method of discriminate regions,
 * in the 3D view (Wang Fig. 4): the unit cell the step crossed (its corners
 * are grid points: the point before the step and the candidates A-D), its
 * exit face split into the regions a-d by the segments e-h, the point where
 * the ideal line crosses the exit plane, and the corner the step went to
 * (the current cell's center).
 *
 * Everything is placed from the core's picture of the step (ExitFace: the
 * face's center and axes, its regions, segments and corners, the crossing,
 * the unit cell); the inspector's figure draws the same value. The crossing
 * can lie off the face, up to half a cell: the regions are quadrants of the
 * exit plane, so they are drawn on past the face, fainter.
 *
 * It is drawn over the cells (overlay-group.ts): the face runs through the
 * centers of the cells it is decided between, where the cubes would hide it.
 */
import * as THREE from 'three';
import type { ExitFace } from '../core/types.js';
import { sceneLabel } from './grid-axes.js';
import { OverlayGroup } from './overlay-group.js';
import { PALETTE } from './palette.js';

/** Each region's colour, by name. */
const REGION_COLOURS: Record<string, string> = { a: PALETTE.regionA, b: PALETTE.regionB, c: PALETTE.regionC, d: PALETTE.regionD };

/** How far the plane around the face is drawn, cells from its center: the crossing lies within (-1, 1). */
const PLANE_EXTENT = 1;
/** Opacity of a region on the face, and on the plane around it. */
const FACE_OPACITY = 0.55;
const PLANE_OPACITY = 0.16;
/** Opacity of an exit edge's continuation past the edge (one passive axis). */
const PLANE_EDGE_OPACITY = 0.5;
/** Corner labels sit at this multiple of their corner's face coordinates: just past the corner. */
const CORNER_LABEL_AT = 1.45;
/** Line widths, CSS pixels: the face's outline and segments e-h, an exit edge's halves (one passive axis), the unit cell's edges. */
const FACE_LINE_PX = 2.5;
const EDGE_LINE_PX = 6;
const CELL_LINE_PX = 1.5;
/** Radius of the crossing's dot and of its black ring, cells. */
const CROSSING_RADIUS = 0.075;
const CROSSING_RING = 0.105;
/** The chosen corner's ring, inner and outer radius, cells. */
const CORNER_RING: [number, number] = [0.13, 0.19];

const unit = (axis: number, sign: number) => new THREE.Vector3().setComponent(axis, sign);

export class RegionFace extends OverlayGroup {
  /** `face` of the step that reached `reached` (the corner it went to, 3 coordinates). */
  constructor(face: ExitFace, reached: ArrayLike<number>) {
    super();
    // Drawn from the corner reached, where the overlay is placed: a WebGL
    // float of a coordinate near 2^30 is a multiple of 64 (setCellOrigin,
    // cells.ts), and the face is a cell wide.
    const origin = new THREE.Vector3(reached[0], reached[1], reached[2]);
    this.position.copy(origin);
    const { uAxis, vAxis } = face;
    const regionLabelClass = (name: string) => `scene-label face-region-label${name === face.region ? ' chosen' : ''}`;
    const center = new THREE.Vector3().fromArray(face.center).sub(origin);
    const eu = unit(uAxis.axis, uAxis.sign);
    // With one passive axis the face is its edge: v does not move off it.
    const ev = vAxis === null ? new THREE.Vector3() : unit(vAxis.axis, vAxis.sign);
    const at = (u: number, v: number) => center.clone().addScaledVector(eu, u).addScaledVector(ev, v);

    // The unit cell: the box between its two opposite corners.
    const [near, far] = face.cell;
    const cellEdges: number[] = [];
    for (let corner = 0; corner < 8; corner++) {
      for (let a = 0; a < 3; a++) {
        if (corner & (1 << a)) continue;
        const p = [0, 1, 2].map((b) => (corner & (1 << b) ? far[b]! : near[b]!) - origin.getComponent(b));
        const q = [...p];
        q[a] = far[a]! - origin.getComponent(a);
        cellEdges.push(...p, ...q);
      }
    }
    this.lines(cellEdges, CELL_LINE_PX, PALETTE.axis);

    for (const r of face.regions) {
      const [qu, qv] = r.quadrant;
      const colour = REGION_COLOURS[r.name]!;
      if (vAxis === null) {
        // The exit edge B-A: its halves are regions b and a.
        this.lines([...at(0, 0).toArray(), ...at(qu / 2, 0).toArray()], EDGE_LINE_PX, colour);
        this.lines([...at(qu / 2, 0).toArray(), ...at(qu * PLANE_EXTENT, 0).toArray()], FACE_LINE_PX, colour, { opacity: PLANE_EDGE_OPACITY });
        this.add(sceneLabel(r.name, regionLabelClass(r.name), at(qu / 4, 0)));
      } else {
        this.#quad(at(0, 0), at(qu * PLANE_EXTENT, 0), at(qu * PLANE_EXTENT, qv * PLANE_EXTENT), at(0, qv * PLANE_EXTENT), colour, PLANE_OPACITY);
        this.#quad(at(0, 0), at(qu / 2, 0), at(qu / 2, qv / 2), at(0, qv / 2), colour, FACE_OPACITY);
        this.add(sceneLabel(r.name, regionLabelClass(r.name), at(qu / 4, qv / 4)));
      }
    }
    if (vAxis !== null) {
      // The face's outline, and the segments e-h: the cross through its center o.
      const corner = (name: string) => face.corners.find((c) => c.name === name)!.at;
      const outline = [...['B', 'A', 'D', 'C'].map(corner), corner('B')];
      const lines = outline.slice(1).flatMap((to, i) => [...at(...outline[i]!).toArray(), ...at(...to).toArray()]);
      for (const s of face.segments.filter((s) => s.from.some((c, i) => c !== s.to[i]))) lines.push(...at(...s.from).toArray(), ...at(...s.to).toArray());
      this.lines(lines, FACE_LINE_PX, PALETTE.ideal);
    }
    // The segment (or center) the line crosses is labelled at its middle.
    const crossed = face.segments.find((s) => s.name === face.region);
    if (crossed) this.add(sceneLabel(crossed.name, regionLabelClass(crossed.name), at((crossed.from[0] + crossed.to[0]) / 2, (crossed.from[1] + crossed.to[1]) / 2)));
    for (const c of face.corners) {
      const [u, v] = c.at;
      this.add(sceneLabel(c.name, `scene-label face-corner-label${c.name === face.corner ? ' chosen' : ''}`, at(u * CORNER_LABEL_AT, v * CORNER_LABEL_AT)));
    }

    // The chosen corner, ringed, in the face's plane: the ring faces the
    // remaining axis (an active one), which is normal to the face.
    const normalAxis = [0, 1, 2].find((a) => a !== uAxis.axis && a !== vAxis?.axis)!;
    const ringGeometry = new THREE.RingGeometry(CORNER_RING[0], CORNER_RING[1], 40);
    const ring = this.#mesh(ringGeometry, PALETTE.ideal, 1);
    // At the corner reached, the origin; turned from facing z to the normal.
    const facing = new THREE.Quaternion().setFromUnitVectors(unit(2, 1), unit(normalAxis, 1));
    ring.quaternion.copy(facing);

    // The crossing: a yellow dot in a black ring, facing the same way.
    const crossing = at(...face.crossing);
    for (const [radius, colour] of [
      [CROSSING_RING, PALETTE.ideal],
      [CROSSING_RADIUS, PALETTE.crossing],
    ] as const) {
      const dot = this.#mesh(new THREE.CircleGeometry(radius, 32), colour, 1);
      dot.position.copy(crossing);
      dot.quaternion.copy(facing);
    }
  }

  /** A flat quadrilateral p0 p1 p2 p3 in `colour` (not drawn when `opacity` is 0). */
  #quad(p0: THREE.Vector3, p1: THREE.Vector3, p2: THREE.Vector3, p3: THREE.Vector3, colour: string, opacity: number): void {
    if (opacity === 0) return;
    const geometry = new THREE.BufferGeometry().setFromPoints([p0, p1, p2, p0, p2, p3]);
    this.#mesh(geometry, colour, opacity);
  }

  #mesh(geometry: THREE.BufferGeometry, colour: string, opacity: number): THREE.Mesh {
    const material = new THREE.MeshBasicMaterial({ color: colour, transparent: true, opacity, side: THREE.DoubleSide, depthTest: false, depthWrite: false });
    const mesh = new THREE.Mesh(geometry, material);
    // Later parts over earlier ones: the plane, the face, the ring, the dot.
    mesh.renderOrder = this.nextRenderOrder();
    this.add(mesh);
    this.track(geometry, material);
    return mesh;
  }
}
