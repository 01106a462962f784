// The charts' reference labels (web/charts/reference-labels.ts): "largest"
// and "bound" never sit on each other nor on a line, however close their lines are.
import { describe, expect, it } from 'vitest';
import { placeReferenceLabels } from '../web/charts/reference-labels.js';
import { widestTickLabel } from '../web/charts/tick-labels.js';

const BOX = { left: 50, top: 10, width: 220, height: 150 };
const TEXT = 11;
const GAP = 4;

describe('reference labels', () => {
  it('stand above their lines when those are apart', () => {
    const baselines = placeReferenceLabels(
      [
        { lineY: 120, width: 90, atRight: false },
        { lineY: 60, width: 150, atRight: true },
      ],
      BOX,
      TEXT,
      GAP,
      4,
    );
    expect(baselines).toEqual([116, 56]);
  });

  it('put the second below its line when both lines are at one height and the labels would meet', () => {
    // largest = bound (a path at its bound): 90 + 150 px of labels in a 220 px plot.
    const baselines = placeReferenceLabels(
      [
        { lineY: 60, width: 90, atRight: false },
        { lineY: 60, width: 150, atRight: true },
      ],
      BOX,
      TEXT,
      GAP,
      4,
    );
    expect(baselines).toEqual([56, 75]);
  });

  it('keep both above when the labels fit side by side', () => {
    const baselines = placeReferenceLabels(
      [
        { lineY: 60, width: 60, atRight: false },
        { lineY: 62, width: 60, atRight: true },
      ],
      BOX,
      TEXT,
      GAP,
      4,
    );
    expect(baselines).toEqual([56, 58]);
  });

  it('go below a line at the top of the plot', () => {
    expect(placeReferenceLabels([{ lineY: 14, width: 90, atRight: false }], BOX, TEXT, GAP, 4)).toEqual([29]);
  });

  it('keep off the other line: two lines 5 px apart at the top of the plot have their labels under both', () => {
    // largest 0.6578 under a bound of 0.7071: "largest" above its line stood on the bound's line.
    const lines = (largest: number, bound: number) => [
      { lineY: 25, width: largest, atRight: false },
      { lineY: 20, width: bound, atRight: true },
    ];
    // Side by side when they fit, one over the other when not.
    expect(placeReferenceLabels(lines(60, 60), BOX, TEXT, GAP, 4)).toEqual([40, 40]);
    expect(placeReferenceLabels(lines(90, 150), BOX, TEXT, GAP, 4)).toEqual([55, 40]);
  });
});

describe('x tick labels', () => {
  it('are sized by the widest label the range can take, decimals and separators included', () => {
    // A 1,200 s program seen 100 ms at a time: its ticks read 1,050.025 and
    // the like, which a fixed 50 px ran together.
    expect(widestTickLabel(1050, 1050.1)).toBe('1,050.100');
    expect(widestTickLabel(9875, 9876)).toBe('9,876.00');
    expect(widestTickLabel(0, 10000)).toBe('10,000');
    // The sign kept, and at most 3 decimals, as uPlot writes them.
    expect(widestTickLabel(-1000, 0)).toBe('-1,000');
    expect(widestTickLabel(-3, 2)).toBe('-3.00');
    expect(widestTickLabel(1050, 1050.001)).toBe('1,050.001');
    // A range of one value takes the labels of a span of 1.
    expect(widestTickLabel(5, 5)).toBe('5.00');
  });
});
