/**
 * A uPlot chart whose cursor is the page's step: a vertical line at the
 * point index shown, moved by the scrubber; clicking the chart picks that
 * point. uPlot was chosen for these charts because it is small (about 50 kB),
 * draws hundreds of thousands of points on a canvas in milliseconds, has no
 * dependencies, and is actively kept; its stepped paths also draw the timing
 * diagram's pulse trains as a logic analyser does.
 */
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';
import { placeReferenceLabels } from './reference-labels.js';
import { widestTickLabel } from './tick-labels.js';

/** Chart height by default, CSS pixels, plot area and axes (the legend is extra). */
const HEIGHT_PX = 170;

export interface ChartSpec {
  /** Accessible name of the chart, also its title. */
  title: string;
  xLabel: string;
  yLabel: string;
  series: uPlot.Series[];
  bands?: uPlot.Band[];
  /** Horizontal reference lines, drawn dashed, each labelled at the left (or at the right, so that two close values stay legible). */
  references?: { value: number; label: string; colour: string; labelAtRight?: boolean }[];
  /** Fixed x range (a window of time the title names); default: fitted to the data. */
  xRange?: [number, number];
  /** Fixed y range; default: fitted to the data. */
  yRange?: [number, number];
  /** Axis values formatter for y. */
  yValues?: uPlot.Axis['values'];
  /** Where y ticks go; default: uPlot's. */
  ySplits?: number[];
  /** Hide uPlot's legend (the timing diagram names its lanes on the axis). */
  legend?: boolean;
  /** Height, CSS pixels, plot area and axes; default HEIGHT_PX. */
  heightPx?: number;
  /** A chart whose x is not the point index (time): a click gives its x here instead of a point index to onPick. */
  pickX?: (x: number) => void;
  /** Text under the chart (a figure caption: what it shows, its source); setCaption changes it. */
  caption?: string;
  /** Called once the plot has been resized to a new width of its container (plotWidthPx is the new one). */
  onResize?: () => void;
  /** Stretches of x not drawn to scale (setBreaks). */
  xBreaks?: XBreak[];
}

/**
 * A stretch of the x axis not drawn to its scale: the timing diagram's pause
 * at an edge of its window, seconds long beside steps a millisecond apart.
 * Drawn hatched over the lines, with `lines` of text in it (the page's own
 * text, which a screen reader and a test read), and no x tick inside it: a
 * tick's value there would be read as to scale.
 */
export interface XBreak {
  fromX: number;
  toX: number;
  /** The label, a line each (none: the box bare); a line wraps at its spaces where the box is narrower than it (a no-break space keeps a value with its unit). */
  lines: string[];
  /** The label as one sentence (its title, and what a screen reader says). */
  description: string;
}

/** A break's box with label `lines` in it, as drawn: the CSS class chart-break, a span a line. */
function breakBox(lines: string[]): HTMLElement {
  const box = document.createElement('div');
  box.className = 'chart-break';
  box.setAttribute('role', 'note');
  setBreakLines(box, lines);
  return box;
}

function setBreakLines(box: HTMLElement, lines: string[]): void {
  box.dataset.lines = lines.join('\n');
  box.replaceChildren(...lines.map((line) => Object.assign(document.createElement('span'), { textContent: line })));
}

/**
 * The widths, CSS pixels and borders included, a break's box can take with
 * label `lines` whole in it: `wrappedPx`, its widest word's (each line
 * wrapped at every space), the least; `unwrappedPx`, its widest line's.
 * Measured in the page's style of the box, laid out in `container` out of
 * sight, so that a box sized by them (the timing diagram's #pauseBoxChoices) holds its text
 * whatever the font.
 */
export function breakLabelWidthsPx(container: HTMLElement, lines: string[]): { wrappedPx: number; unwrappedPx: number } {
  const box = breakBox(lines);
  Object.assign(box.style, { visibility: 'hidden', left: '0', top: '0', bottom: 'auto' });
  container.append(box);
  box.style.width = 'min-content';
  const wrappedPx = box.getBoundingClientRect().width;
  box.style.width = 'max-content';
  const unwrappedPx = box.getBoundingClientRect().width;
  box.remove();
  return { wrappedPx, unwrappedPx };
}

/** The axes' tick labels: uPlot's own size, set here so that the y axis is measured in the font it draws. */
const TICK_FONT = '12px system-ui, sans-serif';
/** The x axis's height, CSS pixels: its ticks and their labels, the title under them (drawXTitle). */
const X_AXIS_PX = 36;
/** The least room between the x axis's title and the canvas's side, CSS pixels. */
const X_TITLE_MARGIN_PX = 2;

/**
 * Draws the x axis's title `text` where uPlot draws an axis's label, in the
 * band under the x axis's tick labels (the axis `sizePx` tall): centred under
 * the plot, or, where that would take it past the canvas's side, moved in
 * to stand X_TITLE_MARGIN_PX inside it. uPlot centres it under the plot
 * whatever its width, which in a narrow chart put its end past the canvas's
 * right side, cut: the timing diagram's 'planned instant (ms)' under its
 * 82 px plot, the lane names' axis at its left, in a page under 272 px.
 */
function drawXTitle(u: uPlot, text: string, sizePx: number): void {
  const ctx = u.ctx;
  // uPlot's own font for an axis's label: bold, the ticks' size.
  ctx.font = `bold ${12 * devicePixelRatio}px system-ui, sans-serif`;
  ctx.fillStyle = '#000';
  ctx.textAlign = 'center';
  ctx.textBaseline = 'top';
  const halfPx = ctx.measureText(text).width / 2;
  const marginPx = X_TITLE_MARGIN_PX * devicePixelRatio;
  const centre = u.bbox.left + u.bbox.width / 2;
  const x = Math.max(halfPx + marginPx, Math.min(centre, ctx.canvas.width - halfPx - marginPx));
  ctx.fillText(text, Math.round(x), Math.round(u.bbox.top + u.bbox.height + sizePx * devicePixelRatio));
}

/** uPlot's tick length and its gap from tick to label, CSS pixels (its defaults, which the axes keep). */
const TICK_PX = 10;
const TICK_GAP_PX = 5;
/**
 * The least room between y ticks, CSS pixels. uPlot steps its tick interval
 * by at most 2 (1, 2, 2.5, 5, 10), so an interval is under twice this, and a
 * chart's plot, 87 px tall, holds two ticks at least; at uPlot's 30,
 * -7,000 to 8,000 took 10,000 and showed only its 0.
 */
const Y_TICK_SPACE_PX = 20;

let measuring: CanvasRenderingContext2D | undefined;

/**
 * The y axis's width for the tick labels it has: a fixed width cut
 * 1,000,000,010 to 000,000,000 at the canvas's edge, and put the axis's
 * title on a 1,000. `values` is null while uPlot first lays the chart out;
 * it then asks again with the labels. The widest stands 2 px clear of the title.
 */
function yAxisSize(_u: uPlot, values: (string | null)[] | null): number {
  const widest = Math.max(0, ...(values ?? []).map((v) => (v ? tickWidthPx(v) : 0)));
  return TICK_PX + TICK_GAP_PX + Math.ceil(widest) + 2;
}

/** The width of tick label `text`, px, in TICK_FONT. */
function tickWidthPx(text: string): number {
  measuring ??= document.createElement('canvas').getContext('2d')!;
  measuring.font = TICK_FONT;
  return measuring.measureText(text).width;
}

/** Least room between two x ticks' labels, px. */
const X_TICK_GAP_PX = 14;

/** The room an x tick needs, px (uPlot's axis `space`): its widest label's width and a gap, at least uPlot's 50. */
function xTickSpace(_u: uPlot, _axis: number, min: number, max: number): number {
  return Math.max(50, Math.ceil(tickWidthPx(widestTickLabel(min, max))) + X_TICK_GAP_PX);
}

/** A chart's least width, CSS pixels, where its container is wide enough for it (chartWidthPx). */
const MIN_WIDTH_PX = 200;

/**
 * The chart's width in `container`, CSS pixels: the container's less 4, at
 * least MIN_WIDTH_PX, but never past the container's side; MIN_WIDTH_PX
 * while it is hidden (no width). At MIN_WIDTH_PX whatever the container, a
 * chart in a page 240 to 242 px wide (the inspector's content box 197.5 to
 * 199.5 px) ran past it into the panel's padding, by 2.5 px at 240. The
 * container's own width, not clientWidth, which rounds 197.5 up to 198.
 */
function chartWidthPx(container: HTMLElement): number {
  const containerPx = container.getBoundingClientRect().width;
  if (containerPx === 0) return MIN_WIDTH_PX;
  return Math.min(Math.floor(containerPx), Math.max(MIN_WIDTH_PX, container.clientWidth - 4));
}

/** The colour of the step cursor (the page's accent, as the scrubber). */
const CURSOR_COLOUR = '#d55e00';

/** How long a click holds a chart in place on screen (holdInPlace): the step's detail comes from the worker in a frame or two. */
const HOLD_MS = 1000;

/** The nearest ancestor of `element` that scrolls vertically, else the page's scrolling element. */
function scrollerOf(element: HTMLElement): HTMLElement {
  for (let e = element.parentElement; e; e = e.parentElement) {
    const { overflowY } = getComputedStyle(e);
    if (overflowY === 'auto' || overflowY === 'scroll') return e;
  }
  return document.scrollingElement as HTMLElement;
}

/**
 * Keeps `element` where it is on screen for HOLD_MS, while what is above it
 * in its scrolling panel changes size, unless the user scrolls meanwhile (a
 * scroll this did not make: the wheel, the scrollbar, the keys): a chart
 * clicked at step 0 made the inspector draw the step's decision figure above
 * the charts, which pushed the chart clicked out of sight (314 px at 1280 x
 * 800). The browser's own scroll anchoring does not act at the top of a
 * panel, where the inspector starts.
 */
function holdInPlace(element: HTMLElement): void {
  const scroller = scrollerOf(element);
  // The page's own scrolling element sends its scroll events to the window.
  const scrolled: EventTarget = scroller === document.scrollingElement ? window : scroller;
  const top = element.getBoundingClientRect().top;
  let held = scroller.scrollTop;
  const observer = new ResizeObserver(() => {
    const moved = element.getBoundingClientRect().top - top;
    if (Math.abs(moved) < 1) return;
    scroller.scrollTop += moved;
    held = scroller.scrollTop;
  });
  for (const child of scroller.children) observer.observe(child);
  const onScroll = () => {
    if (Math.abs(scroller.scrollTop - held) >= 1) release();
  };
  const release = () => {
    observer.disconnect();
    scrolled.removeEventListener('scroll', onScroll);
  };
  scrolled.addEventListener('scroll', onScroll, { passive: true });
  setTimeout(release, HOLD_MS);
}

export class StepChart {
  readonly #plot: uPlot;
  readonly #figure: HTMLElement;
  readonly #resize: ResizeObserver;
  /** The cursor's x: the point index, or on a chart over time its instant. */
  #cursorX = 0;
  #breaks: XBreak[] = [];
  /** One box per break, over the plot, placed on every draw. */
  #breakBoxes: HTMLElement[] = [];

  /** Builds the chart in `container` with `data` (x first); `onPick` gets the point index clicked. */
  constructor(container: HTMLElement, spec: ChartSpec, data: uPlot.AlignedData, onPick: (pointIndex: number) => void) {
    this.#figure = document.createElement('figure');
    this.#figure.className = 'chart';
    this.#figure.setAttribute('aria-label', spec.title);
    container.append(this.#figure);
    const references = spec.references ?? [];
    // No x tick, label or grid line inside a break (its values are not to scale).
    const outsideBreaks = (_u: uPlot, splits: number[]) => splits.map((v) => (this.#breaks.some((b) => v > b.fromX && v < b.toX) ? null : v));
    const opts: uPlot.Options = {
      title: spec.title,
      width: chartWidthPx(container),
      height: spec.heightPx ?? HEIGHT_PX,
      // A line's rows are not drawn as points (uPlot draws hollow circles
      // on a series of few rows, which read as the speed chart's junction
      // dots); a series that wants points says so.
      series: [{ label: spec.xLabel }, ...spec.series.map((series) => ({ points: { show: false }, ...series }))],
      bands: spec.bands,
      scales: { x: spec.xRange ? { time: false, range: spec.xRange } : { time: false }, y: spec.yRange ? { range: spec.yRange } : {} },
      axes: [
        // The title's room kept (uPlot's 30 px under the axis), its text drawn by drawXTitle.
        { label: '', size: X_AXIS_PX, font: TICK_FONT, space: xTickSpace, filter: outsideBreaks, grid: { filter: outsideBreaks }, ticks: { filter: outsideBreaks } },
        { label: spec.yLabel, size: yAxisSize, space: Y_TICK_SPACE_PX, font: TICK_FONT, values: spec.yValues, splits: spec.ySplits && (() => spec.ySplits!) },
      ],
      legend: { show: spec.legend ?? true, live: false },
      cursor: { drag: { x: false, y: false }, points: { show: false } },
      hooks: {
        draw: [
          (u) => {
            const ctx = u.ctx;
            ctx.save();
            ctx.lineWidth = 1.5 * devicePixelRatio;
            ctx.setLineDash([6 * devicePixelRatio, 4 * devicePixelRatio]);
            ctx.font = `${11 * devicePixelRatio}px system-ui, sans-serif`;
            // The baselines placed below are alphabetic ones, each label's
            // descenders within its gap: uPlot leaves the context at its axis
            // values' 'middle', which drew each label half a line low, across
            // the line it stood above.
            ctx.textBaseline = 'alphabetic';
            const lineYs = references.map((r) => Math.round(u.valToPos(r.value, 'y', true)));
            const baselines = placeReferenceLabels(
              references.map((r, i) => ({ lineY: lineYs[i]!, width: ctx.measureText(r.label).width, atRight: r.labelAtRight ?? false })),
              u.bbox,
              11 * devicePixelRatio,
              4 * devicePixelRatio,
              4 * devicePixelRatio,
            );
            references.forEach((r, i) => {
              const y = lineYs[i]!;
              ctx.strokeStyle = r.colour;
              ctx.beginPath();
              ctx.moveTo(u.bbox.left, y);
              ctx.lineTo(u.bbox.left + u.bbox.width, y);
              ctx.stroke();
              ctx.fillStyle = r.colour;
              ctx.textAlign = r.labelAtRight ? 'right' : 'left';
              const labelX = r.labelAtRight ? u.bbox.left + u.bbox.width - 4 * devicePixelRatio : u.bbox.left + 4 * devicePixelRatio;
              ctx.fillText(r.label, labelX, baselines[i]!);
            });
            ctx.setLineDash([]);
            const x = Math.round(u.valToPos(this.#cursorX, 'x', true));
            ctx.strokeStyle = CURSOR_COLOUR;
            ctx.lineWidth = 2 * devicePixelRatio;
            ctx.beginPath();
            ctx.moveTo(x, u.bbox.top);
            ctx.lineTo(x, u.bbox.top + u.bbox.height);
            ctx.stroke();
            drawXTitle(u, spec.xLabel, X_AXIS_PX);
            ctx.restore();
            this.#placeBreaks(u);
          },
        ],
      },
    };
    this.#breaks = spec.xBreaks ?? [];
    this.#plot = new uPlot(opts, data, this.#figure);
    // Laid out now rather than at uPlot's next microtask, so that plotWidthPx is the plot's from the
    // start: its axes' sizes are only measured then (the timing diagram's plot read 216 px, not 174).
    this.#plot.batch(() => {});
    this.setCaption(spec.caption ?? '');
    this.#plot.over.addEventListener('click', () => {
      const left = this.#plot.cursor.left;
      if (left === undefined || left < 0) return;
      const x = this.#plot.posToVal(left, 'x');
      holdInPlace(container);
      if (spec.pickX) spec.pickX(x);
      else onPick(Math.round(x));
    });
    this.#resize = new ResizeObserver(() => {
      const width = chartWidthPx(container);
      if (width === this.#plot.width) return;
      this.#plot.setSize({ width, height: spec.heightPx ?? HEIGHT_PX });
      spec.onResize?.();
    });
    this.#resize.observe(container);
  }

  /** Moves the step cursor to `pointIndex`. */
  showPoint(pointIndex: number): void {
    this.showX(pointIndex);
  }

  /** Moves the cursor to `x` (on a chart over time: an instant). */
  showX(x: number): void {
    if (x === this.#cursorX) return;
    this.#cursorX = x;
    this.#plot.redraw(false, false);
  }

  /** The plot's width, CSS pixels (the chart's less its y axis). */
  get plotWidthPx(): number {
    return this.#plot.bbox.width / devicePixelRatio;
  }

  /** Replaces the text under the chart; none for ''. */
  setCaption(text: string): void {
    let caption = this.#figure.querySelector('figcaption');
    if (!text) {
      caption?.remove();
      return;
    }
    caption ??= this.#figure.appendChild(document.createElement('figcaption'));
    caption.textContent = text;
  }

  /** Replaces the breaks, drawn from the next draw on (setData's). */
  setBreaks(breaks: XBreak[]): void {
    this.#breaks = breaks;
  }

  /** Lays the breaks' boxes over the plot, where their x is now. */
  #placeBreaks(u: uPlot): void {
    while (this.#breakBoxes.length > this.#breaks.length) this.#breakBoxes.pop()!.remove();
    this.#breaks.forEach((b, i) => {
      let box = this.#breakBoxes[i];
      if (!box) {
        box = breakBox(b.lines);
        u.over.append(box);
        this.#breakBoxes.push(box);
      }
      const leftPx = u.valToPos(b.fromX, 'x');
      box.style.left = `${leftPx}px`;
      box.style.width = `${u.valToPos(b.toX, 'x') - leftPx}px`;
      box.title = b.description;
      box.setAttribute('aria-label', b.description);
      if (box.dataset.lines !== b.lines.join('\n')) setBreakLines(box, b.lines);
    });
  }

  /** Replaces the data (same series), keeping the cursor; laid out at once, as when made, so that plotWidthPx is the new layout's. */
  setData(data: uPlot.AlignedData): void {
    this.#plot.batch(() => this.#plot.setData(data));
  }

  destroy(): void {
    this.#resize.disconnect();
    this.#plot.destroy();
    this.#figure.remove();
  }
}
