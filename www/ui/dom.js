// One small DOM helper shared by the panels: el('label', {text: 'Seed', htmlFor: 'seed'}, child…).
// Text goes in with textContent, never as HTML.
export const el = (tag, props = {}, ...children) => {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(props)) {
    if (k === 'text') node.textContent = v;
    else if (k in node) node[k] = v;
    else node.setAttribute(k, v);
  }
  for (const c of children) if (c) node.append(c);
  return node;
};
