/** The page's alert banner: one message and one action button, for what stops the page (the core failing to start or crashing). */
import { byId } from './dom.js';

export function showAlert(message: string, actionText: string, action: () => void): void {
  byId('alert-message', HTMLParagraphElement).textContent = message;
  const button = byId('alert-action', HTMLButtonElement);
  button.textContent = actionText;
  button.onclick = action;
  byId('alert', HTMLDivElement).hidden = false;
}

export function hideAlert(): void {
  byId('alert', HTMLDivElement).hidden = true;
}
