/**
 * Where a chart's reference lines (the largest distance, the rule's bound)
 * put their labels: above their line, else below it, else on a row above or
 * below another line or label, the nearest to their own line that leaves
 * the text clear of every label placed and of every line. Two lines a few
 * pixels apart (a largest distance of 0.6580 under a bound of 0.7071) then
 * have their labels on one row, or one over the other, beside the two lines
 * rather than across one: checked against the labels alone, "largest" sat
 * on the bound's line and the bound's label on the largest's line.
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
 * The baseline of each label, in the order given: the first, nearest its
 * line, of `gap` above or `gap` plus `textHeight` below a line or a label
 * already placed (its own line first) where the label is inside the plot,
 * crosses no line and covers no label; when none is, `gap` above its line.
 * Labels are placed from the top line down: one at the plot's top can only
 * go below its line, and takes that room before the next line's label,
 * which can still go above or below its own. `inset`: the labels' distance
 * from the plot's side.
 */
export function placeReferenceLabels(labels: readonly ReferenceLabel[], box: PlotBox, textHeight: number, gap: number, inset: number): number[] {
  const lineYs = labels.map((l) => l.lineY);
  const placed: Rect[] = [];
  const baselines: number[] = [];
  const topDown = labels.map((_, i) => i).sort((a, b) => lineYs[a]! - lineYs[b]!);
  for (const i of topDown) {
    const label = labels[i]!;
    const left = label.atRight ? box.left + box.width - inset - label.width : box.left + inset;
    const rect = (baseline: number): Rect => ({ left, right: left + label.width, top: baseline - textHeight, bottom: baseline });
    const fits = (baseline: number) => {
      const r = rect(baseline);
      return (
        r.top >= box.top &&
        r.bottom <= box.top + box.height &&
        !lineYs.some((y) => y >= r.top && y <= r.bottom) &&
        !placed.some((p) => overlaps(p, r))
      );
    };
    const own = [label.lineY - gap, label.lineY + gap + textHeight];
    const others = [...lineYs.flatMap((y) => [y - gap, y + gap + textHeight]), ...placed.flatMap((p) => [p.top - gap, p.bottom + gap + textHeight])];
    others.sort((a, b) => Math.abs(a - label.lineY) - Math.abs(b - label.lineY));
    baselines[i] = [...own, ...others].find(fits) ?? own[0]!;
    placed.push(rect(baselines[i]!));
  }
  return baselines;
}
