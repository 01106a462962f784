/** The page's elements, found by id and checked to be of the kind the code expects. */

/** The element `#id`, which must be a `kind`. */
export function byId<T extends HTMLElement>(id: string, kind: new () => T): T {
  const element = document.getElementById(id);
  if (!(element instanceof kind)) throw new Error(`the page has no <${kind.name}> #${id}`);
  return element;
}
