/**
 * Play / pause / first / previous / next / last, the scrubber, the "step k of
 * n" counter, jump to a step, the speed, and their keys (Space, Left/Right
 * arrows, Home/End).
 * All of them only change the state's pointIndex, playing, speed and
 * slowdown; the views follow the state.
 *
 * Playback counts steps per second, every step alike; or, for a G-code
 * program with the slowdown set, it runs in machine time (MachineClock): the
 * steps come at their planned instants, slowed down.
 */
import { grouped } from '../format.js';
import { formatSeconds } from '../gcode/time-format.js';
import { type AppState, SLOWDOWNS, SPEEDS_STEPS_PER_SECOND } from '../state/app-state.js';
import type { Store } from '../state/store.js';
import { MachineClock, type PlannedInstants } from './machine-clock.js';

export interface TimelineElements {
  first: HTMLButtonElement;
  previous: HTMLButtonElement;
  play: HTMLButtonElement;
  /** The play button's visible text, "Play" or "Pause". */
  playLabel: HTMLElement;
  next: HTMLButtonElement;
  last: HTMLButtonElement;
  scrubber: HTMLInputElement;
  counter: HTMLOutputElement;
  speed: HTMLSelectElement;
  /** The playback clock: steps per second, or machine time slowed down (G-code mode). */
  slowdown: HTMLSelectElement;
  /** The machine-time clock while it plays, and where it stopped. */
  machineTime: HTMLOutputElement;
  /** A mark on the scrubber at one point index (a checked path's first difference): pressing it goes there. */
  marker: HTMLButtonElement;
  /** A form with a number field: submitting it jumps to that step. */
  jump: HTMLFormElement;
  jumpInput: HTMLInputElement;
}

/**
 * The keys an element with `data-own-keys` uses itself, as its
 * aria-keyshortcuts declares them (one list, for assistive technology and
 * for the page): "Shift+ArrowLeft" uses ArrowLeft, "+" is the plus key.
 */
function ownKeys(owner: Element): string[] {
  return (owner.getAttribute('aria-keyshortcuts') ?? '').split(' ').map((shortcut) => (shortcut === '+' ? '+' : shortcut.split('+').at(-1)!));
}

/** Targets whose own keyboard handling must win over the page's keys. */
export function handlesItsOwnKeys(target: EventTarget | null, key: string): boolean {
  // A modal dialog (the keyboard help, the Embed dialog) takes every key:
  // the page behind it is inert, and End or F there moved the path unseen.
  // The page opens every dialog with showModal, so an open one is modal
  // (and [open] is read by every browser, where ':modal' throws in some).
  if (document.querySelector('dialog[open]')) return true;
  if (!(target instanceof HTMLElement)) return false;
  // The view and its handles use the keys they declare (the arrows, Page Up
  // and Down, + and -), and only those: Space, Home, End and ? still play,
  // go and open the help there. A handle is a button, but its press does
  // nothing, so Space left to it as to other buttons did nothing at all.
  const owner = target.closest('[data-own-keys]');
  if (owner) return ownKeys(owner).includes(key);
  // A select, and the options of one open as a styled list (appearance:
  // base-select focuses the option), take arrows, Home/End and Space.
  if (target.isContentEditable || target instanceof HTMLTextAreaElement || target.closest('select')) return true;
  // A range, checkbox or radio button takes arrows, Home/End and Space, but
  // no printable key (so '?' still opens the help there); other inputs edit text.
  if (target instanceof HTMLInputElement) return !['range', 'checkbox', 'radio'].includes(target.type) || key.length !== 1 || key === ' ';
  // Space and Enter press a focused button, and open or close a focused disclosure (<summary>).
  return (target instanceof HTMLButtonElement || target.localName === 'summary') && (key === ' ' || key === 'Enter');
}

export class Timeline {
  readonly #e: TimelineElements;
  readonly #store: Store<AppState>;
  /** Steps of the trace shown, or undefined while there is none. */
  #steps: number | undefined;
  #frame: number | undefined;
  /** Playback time not yet turned into whole steps, in seconds. */
  #carrySeconds = 0;
  #lastFrameMs = 0;
  /** The program whose planned instants machine-time playback follows, if one is shown. */
  #instants: PlannedInstants | undefined;
  /** Machine-time playback under way. */
  #machine: MachineClock | undefined;
  /** The clock time of the last step machine-time playback showed, seconds. */
  #machineSeconds: number | undefined;
  /** The point index #machineSeconds goes with. */
  #machinePoint: number | undefined;
  /** Counts the instants asked for a point chosen while paused, so that only the latest answer shows. */
  #instantAsked = 0;
  /** The point index the marker stands at, or undefined for no marker. */
  #markerPoint: number | undefined;

  constructor(elements: TimelineElements, store: Store<AppState>) {
    this.#e = elements;
    this.#store = store;
    for (const speed of SPEEDS_STEPS_PER_SECOND) {
      elements.speed.append(new Option(`${speed} steps/s`, String(speed)));
    }
    elements.first.addEventListener('click', () => this.#go(0));
    elements.previous.addEventListener('click', () => this.#go(this.#store.state.pointIndex - 1));
    elements.next.addEventListener('click', () => this.#go(this.#store.state.pointIndex + 1));
    elements.last.addEventListener('click', () => this.#go(this.#steps ?? 0));
    elements.play.addEventListener('click', () => this.#togglePlay());
    elements.marker.addEventListener('click', () => this.#go(this.#markerPoint ?? 0));
    elements.scrubber.addEventListener('input', () => this.#go(elements.scrubber.valueAsNumber));
    elements.speed.addEventListener('change', () => store.update({ speed: Number(elements.speed.value) }));
    elements.slowdown.append(new Option('steps/s (Speed)', ''));
    for (const slowdown of SLOWDOWNS) {
      elements.slowdown.append(new Option(slowdown === 1 ? 'machine time, real' : `machine time, ${slowdown}× slower`, String(slowdown)));
    }
    elements.slowdown.addEventListener('change', () => store.update({ slowdown: elements.slowdown.value === '' ? null : Number(elements.slowdown.value) }));
    elements.jump.addEventListener('submit', (event) => {
      event.preventDefault();
      const wanted = elements.jumpInput.valueAsNumber;
      if (Number.isInteger(wanted)) this.#go(wanted);
    });
    document.addEventListener('keydown', (event) => this.#key(event));
    store.subscribe(() => this.#render());
    this.#render();
  }

  /** The trace's step count (undefined: no trace, controls disabled); clamps the point shown to it. */
  setSteps(steps: number | undefined): void {
    this.#steps = steps;
    const { pointIndex } = this.#store.state;
    if (steps !== undefined && pointIndex > steps) this.#store.update({ pointIndex: steps });
    if (!steps) this.#store.update({ playing: false });
    this.#render();
  }

  /** Puts the marker at point index `pointIndex`, saying `label` (undefined: no marker). */
  setMarker(pointIndex: number | undefined, label = ''): void {
    this.#markerPoint = pointIndex;
    const marker = this.#e.marker;
    marker.title = label;
    marker.setAttribute('aria-label', label);
    this.#render();
  }

  /** The planned instants of the program shown (undefined: none, or not a program): machine-time playback follows them. */
  setClock(instants: PlannedInstants | undefined): void {
    if (instants === this.#instants) return;
    this.#instants = instants;
    this.#stopMachine();
    this.#machineSeconds = this.#machinePoint = undefined;
    this.#render();
  }

  #stopMachine(): void {
    this.#machine?.stop();
    this.#machine = undefined;
  }

  /**
   * Machine time from the current point on: from where the clock stopped
   * when it was paused there (in a dwell, or between two slow steps), else
   * from the point's instant, once known. Resumed from the point's instant,
   * the clock went back (4.0 s paused in a dwell, 2.8 s a moment after Play).
   */
  #startMachine(instants: PlannedInstants): MachineClock {
    const { pointIndex } = this.#store.state;
    const paused = this.#machinePoint === pointIndex ? this.#machineSeconds : undefined;
    const startSeconds = paused === undefined ? instants.secondsAtPoint(pointIndex) : Promise.resolve(paused);
    return new MachineClock(instants, startSeconds, (pointIndex, seconds) => {
      const steps = this.#steps ?? 0;
      const next = Math.min(pointIndex, steps);
      this.#machineSeconds = seconds;
      this.#machinePoint = next;
      // On to the program's end in time, not its last step: a dwell after
      // the last move is played too (playback stopped at its start).
      this.#store.update({ pointIndex: next, playing: next < steps || seconds < instants.durationSeconds });
      // Shown even when the step did not change (the state then is the same, and no render follows).
      this.#renderMachineTime();
    });
  }

  #go(pointIndex: number): void {
    if (this.#steps === undefined) return;
    this.#store.update({ pointIndex: Math.min(Math.max(0, pointIndex), this.#steps), playing: false });
  }

  #togglePlay(): void {
    // No path, or one of no steps: nothing to play.
    if (!this.#steps) return;
    const { playing, pointIndex, slowdown } = this.#store.state;
    if (playing) {
      this.#store.update({ playing: false });
      return;
    }
    // Play at the end starts over, as media players do; in machine time the
    // end is the program's, so a pause in a dwell after the last step resumes
    // the clock there (it started the program over).
    const instants = this.#instants;
    const inClosingDwell = slowdown !== null && instants !== undefined && this.#machinePoint === pointIndex && (this.#machineSeconds ?? instants.durationSeconds) < instants.durationSeconds;
    const atEnd = pointIndex >= this.#steps && !inClosingDwell;
    this.#store.update({ playing: true, pointIndex: atEnd ? 0 : pointIndex });
  }

  #key(event: KeyboardEvent): void {
    if (event.defaultPrevented || event.altKey || event.ctrlKey || event.metaKey) return;
    if (handlesItsOwnKeys(event.target, event.key)) return;
    const { pointIndex } = this.#store.state;
    const actions: Record<string, () => void> = {
      ' ': () => this.#togglePlay(),
      ArrowLeft: () => this.#go(pointIndex - 1),
      ArrowRight: () => this.#go(pointIndex + 1),
      Home: () => this.#go(0),
      End: () => this.#go(this.#steps ?? 0),
    };
    const action = actions[event.key];
    if (!action) return;
    event.preventDefault();
    action();
  }

  #tick(nowMs: number): void {
    const { playing, pointIndex, speed } = this.#store.state;
    if (!playing || this.#steps === undefined) return;
    // A long gap (a hidden tab) is not caught up on: at most a quarter second counts.
    const elapsedSeconds = Math.min(nowMs - this.#lastFrameMs, 250) / 1000;
    this.#lastFrameMs = nowMs;
    const { slowdown } = this.#store.state;
    if (slowdown !== null && this.#instants) {
      this.#machine ??= this.#startMachine(this.#instants);
      this.#machine.advance(elapsedSeconds, slowdown);
      this.#frame = requestAnimationFrame((t) => this.#tick(t));
      return;
    }
    this.#stopMachine();
    this.#carrySeconds += elapsedSeconds;
    const steps = Math.floor(this.#carrySeconds * speed);
    this.#carrySeconds -= steps / speed;
    if (steps > 0) {
      const next = Math.min(pointIndex + steps, this.#steps);
      this.#store.update({ pointIndex: next, playing: next < this.#steps });
    }
    if (this.#store.state.playing) this.#frame = requestAnimationFrame((t) => this.#tick(t));
  }

  #render(): void {
    const { pointIndex, playing, speed } = this.#store.state;
    const e = this.#e;
    const steps = this.#steps ?? 0;
    const none = this.#steps === undefined;
    // aria-disabled, not disabled: a disabled button drops keyboard focus, so
    // pressing Next up to the last step would leave the user nowhere.
    for (const b of [e.first, e.previous]) b.setAttribute('aria-disabled', String(none || pointIndex === 0));
    for (const b of [e.next, e.last]) b.setAttribute('aria-disabled', String(none || pointIndex === steps));
    e.play.disabled = e.scrubber.disabled = none;
    // A path of no steps has nothing to play: said, as the step buttons say
    // theirs, without disabling it (a disabled button drops keyboard focus).
    e.play.setAttribute('aria-disabled', String(steps === 0));
    e.playLabel.textContent = playing ? 'Pause' : 'Play';
    e.play.title = playing ? 'Pause (Space)' : 'Play (Space)';
    e.play.dataset.playing = String(playing);
    e.jumpInput.max = e.scrubber.max = String(steps);
    e.jumpInput.disabled = none;
    e.scrubber.value = String(pointIndex);
    // No path (its input refused): the step a link asked for waits for one; "Step 3 of 0" read as a bug.
    // Thousands grouped, as the time charts' totals are: "Step 0 of 49999336" had to be counted by eye.
    const text = none ? 'No path' : `Step ${grouped(pointIndex)} of ${grouped(steps)}`;
    e.scrubber.setAttribute('aria-valuetext', text);
    e.counter.value = text;
    // Announcing every step of playback would drown a screen reader.
    e.counter.setAttribute('aria-live', playing ? 'off' : 'polite');
    // Over the scrubber's track, where its thumb stands at that point (the thumb's center runs from half a thumb in).
    const marked = this.#markerPoint;
    e.marker.hidden = none || marked === undefined;
    if (marked !== undefined) {
      e.marker.dataset.pointIndex = String(marked);
      e.marker.style.left = `calc(var(--thumb) / 2 + (100% - var(--thumb)) * ${steps > 0 ? Math.min(marked, steps) / steps : 0})`;
    }
    e.speed.value = String(speed);
    e.slowdown.value = String(this.#store.state.slowdown ?? '');
    this.#renderMachineTime();

    if (playing && this.#frame === undefined) {
      this.#carrySeconds = 0;
      this.#lastFrameMs = performance.now();
      this.#frame = requestAnimationFrame((t) => this.#tick(t));
    } else if (!playing && this.#frame !== undefined) {
      cancelAnimationFrame(this.#frame);
      this.#frame = undefined;
      this.#stopMachine();
    }
  }

  /**
   * The machine-time readout: shown while machine time is chosen for a
   * program. A point chosen while paused (a step button, the scrubber, a
   * chart) reads the instant that point is reached, asked of the worker;
   * until it comes the readout keeps the last one.
   */
  #renderMachineTime(): void {
    const out = this.#e.machineTime;
    const instants = this.#instants;
    const { slowdown, playing, pointIndex } = this.#store.state;
    out.hidden = slowdown === null || !instants;
    if (!instants) return;
    if (slowdown !== null && !playing && pointIndex !== this.#machinePoint) {
      const asked = ++this.#instantAsked;
      this.#machinePoint = pointIndex;
      instants.secondsAtPoint(pointIndex).then(
        (seconds) => {
          if (asked !== this.#instantAsked || instants !== this.#instants || this.#store.state.playing) return;
          this.#machineSeconds = seconds;
          this.#renderMachineTime();
        },
        // The program was replaced or its worker lost: nothing to show for
        // it, and the point is asked again when next shown.
        () => {
          if (asked === this.#instantAsked) this.#machinePoint = undefined;
        },
      );
    }
    const seconds = this.#machineSeconds;
    // At the start the readout says what is ahead: how long the program takes.
    out.value = !seconds ? `machine time: the program takes ${formatSeconds(instants.durationSeconds)}` : `machine time ${formatSeconds(seconds)} of ${formatSeconds(instants.durationSeconds)}`;
    if (seconds === undefined) delete out.dataset.seconds;
    else out.dataset.seconds = String(seconds);
  }
}
