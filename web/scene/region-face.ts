/**
 * The exit face of one decision of Wang's method of discriminate regions,
 * in the 3D view (Wang Fig. 4): the unit cell the step crossed (its corners
 * are grid points: the point before the step and the candidates A-D), its
 * exit face split into the regions a-d by the segments e-h, the point where
 * the ideal line crosses the exit plane, and the corner the step went to
 * (the current cell's center).
 *
 * Everything is placed from the core's columns (region, corner, faceU,
 * faceV and the axes they run along, read by exitFaceOf) and the two points
 * of the step; the page derives none of it. The crossing can lie off the
 * face, up to half a cell (the faceU column's doc): the regions are
 * quadrants of the exit plane, so they are drawn on past the face, fainter.
 *
 * It is drawn over the cells (overlay-group.ts): the face runs through the
 * centers of the cells it is decided between, where the cubes would hide it.
 */
import * as THREE from 'three';
import type { ExitFace } from '../inspector/decision-figure.js';
import { sceneLabel } from './grid-axes.js';
import { OverlayGroup } from './overlay-group.js';
import { PALETTE } from './palette.js';

/** Each region's quadrant: the signs of (u, v) in it (Wang Fig. 4b: A steps the first passive axis, C the second). */
const REGIONS = [
  { name: 'a', u: 1, v: -1, colour: PALETTE.regionA },
  { name: 'b', u: -1, v: -1, colour: PALETTE.regionB },
  { name: 'c', u: -1, v: 1, colour: PALETTE.regionC },
  { name: 'd', u: 1, v: 1, colour: PALETTE.regionD },
] as const;

/** Where the segments e-h and the center o are labelled, face coordinates: only the one the line crosses is. */
const SEGMENT_LABELS: Record<string, [number, number]> = { e: [0, -0.25], f: [-0.25, 0], g: [0, 0.25], h: [0.25, 0], o: [0, 0] };

/** Each corner's face coordinates, cells from the face's center. */
const CORNERS = { A: [0.5, -0.5], B: [-0.5, -0.5], C: [-0.5, 0.5], D: [0.5, 0.5] } as const;

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
  /** `face` of the step from `before` to `after` (points of the trace, 3 coordinates). */
  constructor(face: ExitFace, before: ArrayLike<number>, after: ArrayLike<number>) {
    super();
    const { uAxis, vAxis } = face;
    const regionLabelClass = (name: string) => `scene-label face-region-label${name === face.region ? ' chosen' : ''}`;
    // The face's center: half a cell past the point before the step along
    // each passive axis, and where the step arrived along the active ones.
    const center = new THREE.Vector3();
    for (let a = 0; a < 3; a++) center.setComponent(a, a === uAxis ? before[a]! + face.uSign / 2 : a === vAxis ? before[a]! + face.vSign / 2 : after[a]!);
    const eu = unit(uAxis, face.uSign);
    const ev = vAxis === undefined ? new THREE.Vector3() : unit(vAxis, face.vSign);
    const at = (u: number, v: number) => center.clone().addScaledVector(eu, u).addScaledVector(ev, v);

    // The unit cell: from the point before the step, one cell along each axis the way it travels.
    const travel = [0, 1, 2].map((a) => (a === uAxis ? face.uSign : a === vAxis ? face.vSign : after[a]! - before[a]!));
    const cellEdges: number[] = [];
    for (let corner = 0; corner < 8; corner++) {
      for (let a = 0; a < 3; a++) {
        if (corner & (1 << a)) continue;
        const p = [0, 1, 2].map((b) => before[b]! + (corner & (1 << b) ? travel[b]! : 0));
        const q = [...p];
        q[a] = q[a]! + travel[a]!;
        cellEdges.push(...p, ...q);
      }
    }
    this.lines(cellEdges, CELL_LINE_PX, PALETTE.axis);

    const corners: [string, number, number][] = [];
    if (face.v === undefined) {
      // One passive axis: the line leaves through the edge B-A where the
      // active axes arrive together; its halves are regions b and a, split
      // at the point e.
      for (const r of REGIONS.filter((r) => r.v < 0)) {
        this.lines([...at(0, 0).toArray(), ...at(r.u / 2, 0).toArray()], EDGE_LINE_PX, r.colour);
        this.lines([...at(r.u / 2, 0).toArray(), ...at(r.u * PLANE_EXTENT, 0).toArray()], FACE_LINE_PX, r.colour, { opacity: PLANE_EDGE_OPACITY });
        this.add(sceneLabel(r.name, regionLabelClass(r.name), at(r.u / 4, 0)));
      }
      corners.push(['A', 0.5, 0], ['B', -0.5, 0]);
    } else {
      for (const r of REGIONS) {
        this.#quad(at(0, 0), at(r.u * PLANE_EXTENT, 0), at(r.u * PLANE_EXTENT, r.v * PLANE_EXTENT), at(0, r.v * PLANE_EXTENT), r.colour, PLANE_OPACITY);
        this.#quad(at(0, 0), at(r.u / 2, 0), at(r.u / 2, r.v / 2), at(0, r.v / 2), r.colour, FACE_OPACITY);
        this.add(sceneLabel(r.name, regionLabelClass(r.name), at(r.u / 4, r.v / 4)));
      }
      // The face's outline, and the segments e-h: the cross through its center o.
      const outline = [
        [-0.5, -0.5, 0.5, -0.5],
        [0.5, -0.5, 0.5, 0.5],
        [0.5, 0.5, -0.5, 0.5],
        [-0.5, 0.5, -0.5, -0.5],
        [0, -0.5, 0, 0.5],
        [-0.5, 0, 0.5, 0],
      ].flatMap(([u1, v1, u2, v2]) => [...at(u1!, v1!).toArray(), ...at(u2!, v2!).toArray()]);
      this.lines(outline, FACE_LINE_PX, PALETTE.ideal);
      for (const [name, [u, v]] of Object.entries(CORNERS)) corners.push([name, u, v]);
    }
    const segmentAt = SEGMENT_LABELS[face.region];
    if (segmentAt) this.add(sceneLabel(face.region, regionLabelClass(face.region), at(...segmentAt)));
    for (const [name, u, v] of corners) {
      this.add(sceneLabel(name, `scene-label face-corner-label${name === face.corner ? ' chosen' : ''}`, at(u * CORNER_LABEL_AT, v * CORNER_LABEL_AT)));
    }

    // The chosen corner, ringed, in the face's plane: the ring faces the
    // remaining axis (an active one), which is normal to the face.
    const normalAxis = [0, 1, 2].find((a) => a !== uAxis && a !== vAxis)!;
    const ringGeometry = new THREE.RingGeometry(CORNER_RING[0], CORNER_RING[1], 40);
    const ring = this.#mesh(ringGeometry, PALETTE.ideal, 1);
    ring.position.set(after[0]!, after[1]!, after[2]!);
    ring.lookAt(ring.position.clone().add(unit(normalAxis, 1)));

    // The crossing: a yellow dot in a black ring, facing the same way.
    const crossing = at(face.u, face.v ?? 0);
    for (const [radius, colour] of [
      [CROSSING_RING, PALETTE.ideal],
      [CROSSING_RADIUS, PALETTE.crossing],
    ] as const) {
      const dot = this.#mesh(new THREE.CircleGeometry(radius, 32), colour, 1);
      dot.position.copy(crossing);
      dot.lookAt(crossing.clone().add(unit(normalAxis, 1)));
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
