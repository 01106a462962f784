/** The keyboard help: '?' or its button opens it, Escape (the dialog's own) closes it. */
import { handlesItsOwnKeys } from '../timeline/timeline.js';

export function wireHelp(help: HTMLDialogElement, open: HTMLButtonElement): void {
  open.addEventListener('click', () => help.showModal());
  document.addEventListener('keydown', (event) => {
    if (event.key === '?' && !handlesItsOwnKeys(event.target, event.key) && !help.open) {
      event.preventDefault();
      help.showModal();
    }
  });
}
