/**
 * Where a chart's reference lines (the largest distance, the rule's bound)
 * put their labels: above their line, or below it when that label would
 * cover one already placed (two lines close together, as a path whose
 * largest distance is at or near its bound), so no label sits on another.
 * Pure geometry, in canvas pixels, so it is tested without a canvas.
 */

export interface ReferenceLabel {
  /** The line's height in the plot, canvas pixels (down is larger). */
  lineY: number;
  /** The label's width, canvas pixels. */
  width: number;
  /** Against the plot's right edge, else its left. */
  atRight: boolean;
}

export interface PlotBox {
  left: number;
  top: number;
  width: number;
  height: number;
}

interface Rect {
  left: number;
  right: number;
  top: number;
  bottom: number;
}

const overlaps = (a: Rect, b: Rect) => a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;

/**
 * The baseline of each label, in the order given: `gap` above its line, or
 * `gap` plus `textHeight` below it when above would cover a label placed
 * before it or leave the plot. `inset`: the labels' distance from the
 * plot's side.
 */
export function placeReferenceLabels(labels: readonly ReferenceLabel[], box: PlotBox, textHeight: number, gap: number, inset: number): number[] {
  const placed: Rect[] = [];
  return labels.map((label) => {
    const left = label.atRight ? box.left + box.width - inset - label.width : box.left + inset;
    const rect = (baseline: number): Rect => ({ left, right: left + label.width, top: baseline - textHeight, bottom: baseline });
    const above = label.lineY - gap;
    const below = label.lineY + gap + textHeight;
    const fits = (baseline: number) => {
      const r = rect(baseline);
      return r.top >= box.top && r.bottom <= box.top + box.height && !placed.some((p) => overlaps(p, r));
    };
    const baseline = fits(above) ? above : fits(below) ? below : above;
    placed.push(rect(baseline));
    return baseline;
  });
}
