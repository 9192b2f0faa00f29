// Compare's "Run 20 seeds" table: per set-up the success and the medians of time, nodes and
// checks over every run, of the path's length over the solved ones (run/summary.js); the better
// set-up per metric is marked ★ (higher success, lower medians; none on a tie or without values).
// Built with DOM calls and textContent.

import { summarise } from '../run/summary.js';
import { el } from './dom.js';

/** A number for the table: whole numbers as they are, else 4 significant digits. */
function num(v) {
  if (v === null || !Number.isFinite(v)) return '—';
  return Number.isInteger(v) ? String(v) : Number(v.toPrecision(4)).toString();
}

/**
 * Fill `table`'s body from `rows` ([rows of A, rows of B]: {seed, solved, time_ms, nodes, checks,
 * cost}); returns {per: [summary of A, of B], better: {metric: 'a' | 'b' | null}}.
 * @param {HTMLTableElement} table @param {any[][]} rows
 */
export function fillSeedsTable(table, rows) {
  // medians of time, nodes and checks over every run, of the path's length over the solved ones
  const per = rows.map((list) => {
    const s = summarise(list.map((r) => ({ ...r, length: r.cost })), { overAll: ['time_ms', 'nodes', 'checks'], overSolved: ['length'] });
    return { runs: s.runs, solved: s.solved, success: s.success, ...s.medians };
  });
  // the better set-up per metric: higher success, lower medians; none on a tie or without values
  /** @type {Array<[string, string, (p: any) => string, number]>} key, label, shown as, sign (1: higher is better) */
  const METRICS = [
    ['success', 'success', (p) => `${Math.round(100 * p.success)}% (${p.solved}/${p.runs})`, 1],
    ['time_ms', 'time (ms)', (p) => num(p.time_ms), -1],
    ['nodes', 'nodes', (p) => num(p.nodes), -1],
    ['checks', 'checks', (p) => num(p.checks), -1],
    ['length', 'path length (solved)', (p) => num(p.length), -1],
  ];
  const better = {};
  for (const [key, , , sign] of METRICS) {
    const [a, b] = per.map((p) => p[key]);
    better[key] = a === null || b === null ? (a === null && b === null ? null : a === null ? 'b' : 'a')
      : a === b ? null : (sign * (a - b) > 0 ? 'a' : 'b');
  }
  table.tBodies[0].replaceChildren(...METRICS.map(([key, label, show]) => {
    const tr = el('tr', {}, el('th', { scope: 'row', text: label }));
    per.forEach((p, i) => {
      const mark = better[key] === 'ab'[i];
      const td = el('td', { text: `${show(p)}${mark ? ' ★' : ''}`, className: mark ? 'better' : '' });
      if (mark) td.title = `Set-up ${'AB'[i]} is better here`;
      tr.append(td);
    });
    return tr;
  }));
  return { per, better };
}
