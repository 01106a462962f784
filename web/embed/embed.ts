/**
 * The page in a course author's own material:
 * - embedded (?embed=1), the view and the playback with the current step's
 *   reason under them (off with ?explain=0), and an "Open in voxpath" link
 *   to the same state in the full page;
 * - in the full page, the Embed button: the <iframe> snippet of the state
 *   on screen, at the address the page is served from, ready to copy.
 * Both links are the permalink (state/query.ts) of the state as it is.
 */
import { type AppState, tracedAlgorithms, type Catalogue, comparedValues, experimentAlgorithm } from '../state/app-state.js';
import { GCODE_URL_LIMIT, stateToQuery } from '../state/query.js';
import type { Store } from '../state/store.js';
import { staleness } from '../state/stale.js';
import { formatPoint, grouped } from '../format.js';

export interface EmbedElements {
  /** Embedded: the link to the same state in the full page, in the views' corner. */
  open: HTMLAnchorElement;
  /** Where the link stands in experiment mode, which has no view: the stage, above the tables. */
  stage: HTMLElement;
  /** Full page: the button that shows the snippet, and its dialog. */
  button: HTMLButtonElement;
  dialog: HTMLDialogElement;
  snippet: HTMLTextAreaElement;
  /** Why the snippet may not show what is on screen (a program too long for a link). */
  note: HTMLElement;
  copy: HTMLButtonElement;
  /** Says whether the copy worked. */
  copied: HTMLElement;
}

/** The frame's size in the snippet, CSS pixels: the view and the playback read well in it. */
const FRAME = { width: 640, height: 480 };

/** Where the page is served, without its query: the address the links start from. */
function pageAddress(): string {
  return window.location.href.replace(/[?#].*$/, '');
}

/** The full page's (embed false) or the embedded view's (embed true) link to `state`. */
export function stateLink(state: AppState, embed: boolean): string {
  return `${pageAddress()}?${stateToQuery({ ...state, embed }, { gcodeLimit: GCODE_URL_LIMIT })}`;
}

/** Text for an HTML attribute value in double quotes. */
function attribute(text: string): string {
  return text.replaceAll('&', '&amp;').replaceAll('"', '&quot;').replaceAll('<', '&lt;');
}

/** The frame's title, which a screen reader announces: what it shows. */
function frameTitle(state: AppState, catalogue: Catalogue): string {
  const names = tracedAlgorithms(state, catalogue.algorithms).map((a) => a.title);
  const { from, to } = state.options;
  const move = Array.isArray(from) && Array.isArray(to) ? `, ${formatPoint(from)} to ${formatPoint(to)}` : '';
  switch (state.mode) {
    case 'trace':
      return `${names[0]}${move}, step by step (voxpath)`;
    case 'compare': {
      const itself = comparedValues(state, catalogue.algorithms);
      return itself ? `${names[0]}, ${itself.option} ${itself.values.join(' and ')} compared${move} (voxpath)` : `${names.join(' and ')} compared${move} (voxpath)`;
    }
    case 'gcode':
      return 'A G-code program stepped on a grid (voxpath)';
    case 'experiment':
      return `Random lines traced by ${experimentAlgorithm(state, catalogue).title} (voxpath)`;
  }
}

/** The <iframe> element that embeds `state`. */
function iframeSnippet(state: AppState, catalogue: Catalogue): string {
  return (
    `<iframe src="${attribute(stateLink(state, true))}"\n` +
    `        title="${attribute(frameTitle(state, catalogue))}"\n` +
    `        width="${FRAME.width}" height="${FRAME.height}" style="border: 0" loading="lazy"></iframe>`
  );
}

export function embedding(store: Store<AppState>, catalogue: Catalogue, e: EmbedElements): void {
  const views = e.open.parentElement!;
  const render = () => {
    const state = store.state;
    document.body.classList.toggle('no-explain', !state.explain);
    if (state.embed) {
      e.open.href = stateLink(state, false);
      // The views are hidden in experiment mode, and the link with them (it had no size there).
      const home = state.mode === 'experiment' ? e.stage : views;
      if (e.open.parentElement !== home) {
        if (home === e.stage) home.prepend(e.open);
        else home.append(e.open);
      }
    }
    if (e.dialog.open) {
      e.snippet.value = iframeSnippet(state, catalogue);
      const limit = grouped(GCODE_URL_LIMIT);
      const note =
        staleness() !== undefined
          ? 'The inputs were not traced as they are (see the message by them), so the frame may not show what is on screen: mend them first (or run a cancelled run to its end).'
          : state.mode === 'gcode' && state.gcode.length > GCODE_URL_LIMIT
          ? `This program is longer than a link holds (${limit} characters), so the frame would open on the sample program: shorten it to embed it.`
          : state.mode === 'trace' && state.learnerPoints.length > GCODE_URL_LIMIT
            ? `Your points are longer than a link holds (${limit} characters), so the frame shows the path without them: fewer points (or a shorter move) embed with them.`
            : '';
      e.note.hidden = note === '';
      e.note.textContent = note;
    }
  };
  e.button.addEventListener('click', () => {
    e.copied.textContent = '';
    e.dialog.showModal();
    render();
    e.snippet.select();
  });
  e.copy.addEventListener('click', async () => {
    try {
      await navigator.clipboard.writeText(e.snippet.value);
      e.copied.textContent = 'Copied.';
    } catch {
      // No clipboard (an insecure page, a refusal): selected, to copy by hand.
      e.snippet.select();
      e.copied.textContent = 'Selected: copy it with Ctrl+C (⌘C).';
    }
  });
  store.subscribe(render);
  render();
}
