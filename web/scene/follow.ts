/**
 * "Follow": the views' cameras keep the current cell in sight at a readable
 * zoom as the path plays (SceneView.setFollow), for paths too long to read
 * framed whole. A checkbox in the view's tools and the F key toggle it; the
 * state (and so the link) keeps it.
 */
import type { AppState } from '../state/app-state.js';
import type { Store } from '../state/store.js';
import { handlesItsOwnKeys } from '../timeline/timeline.js';
import type { SceneView } from './scene-view.js';

/** Ties the checkbox, the F key and the views (`views()`: those that exist now) to the state's `follow`. */
export function followControl(store: Store<AppState>, checkbox: HTMLInputElement, views: () => readonly (SceneView | undefined)[]): void {
  const apply = () => {
    checkbox.checked = store.state.follow;
    for (const view of views()) view?.setFollow(store.state.follow);
  };
  checkbox.addEventListener('change', () => store.update({ follow: checkbox.checked }));
  document.addEventListener('keydown', (event) => {
    if (event.key.toLowerCase() !== 'f' || event.altKey || event.ctrlKey || event.metaKey || event.defaultPrevented) return;
    if (handlesItsOwnKeys(event.target, event.key)) return;
    event.preventDefault();
    store.update({ follow: !store.state.follow });
  });
  // Every change: a view made since (the right one, side by side) takes it up too.
  store.subscribe(apply);
  apply();
}
