/**
 * What the 3D decision overlays (region-face.ts, arc-candidates.ts) share:
 * wide lines drawn over the cells in the order they are added, and one
 * dispose() for their GPU resources and labels.
 *
 * Over the cells means no depth test: an overlay marks cells and faces that
 * the cubes themselves would hide. Every part is transparent, even when
 * opaque: three draws opaque objects before all transparent ones, so only
 * this way does renderOrder alone set the order.
 */
import * as THREE from 'three';
import { LineMaterial } from 'three/examples/jsm/lines/LineMaterial.js';
import { LineSegments2 } from 'three/examples/jsm/lines/LineSegments2.js';
import { LineSegmentsGeometry } from 'three/examples/jsm/lines/LineSegmentsGeometry.js';
import { CSS2DObject } from 'three/examples/jsm/renderers/CSS2DRenderer.js';

/** Over the cells and the ideal line (renderOrder 2). */
const RENDER_ORDER = 10;

export class OverlayGroup extends THREE.Group {
  readonly #disposables: { dispose(): void }[] = [];

  /** renderOrder of the next part: later parts are drawn over earlier ones. */
  protected nextRenderOrder(): number {
    return RENDER_ORDER + this.children.length;
  }

  /** Frees `resources` with the overlay. */
  protected track(...resources: { dispose(): void }[]): void {
    this.#disposables.push(...resources);
  }

  /**
   * Line segments, flat pairs of xyz end points, `widthPx` wide; `dash`: dash
   * and gap length in grid units, for a dashed line.
   */
  protected lines(segments: number[], widthPx: number, colour: string, { opacity = 1, dash }: { opacity?: number; dash?: number } = {}): void {
    const geometry = new LineSegmentsGeometry().setPositions(segments);
    const dashes = dash === undefined ? {} : { dashed: true, dashSize: dash, gapSize: dash };
    const material = new LineMaterial({ color: colour, linewidth: widthPx, transparent: true, opacity, depthTest: false, depthWrite: false, ...dashes });
    const lines = new LineSegments2(geometry, material);
    // Dashes are laid out along each segment's length.
    if (dash !== undefined) lines.computeLineDistances();
    lines.renderOrder = this.nextRenderOrder();
    this.add(lines);
    this.track(geometry, material);
  }

  dispose(): void {
    for (const d of this.#disposables) d.dispose();
    this.traverse((o) => {
      if (o instanceof CSS2DObject) o.element.remove();
    });
  }
}
