// The benchmark's results table in the homework's form: per set-up the success and, for time,
// nodes, checks and path cost, the mean ± standard deviation beside the median (the core's
// summaries: sample std, costs over the solved runs), the smoothed cost's median last. The same
// rows copy as a Markdown table or a LaTeX tabular (booktabs), for a report. Built with DOM calls
// and textContent; the copies escape what Markdown and LaTeX would read as markup.

import { el } from './dom.js';

/** A number for the table (as the course table's): whole numbers as they are, from 100 up one decimal, else 4 significant digits; '—' for none. */
export function num(v) {
  if (v === null || v === undefined || !Number.isFinite(v)) return '—';
  if (Number.isInteger(v)) return String(v);
  return Math.abs(v) >= 100 ? v.toFixed(1) : Number(v.toPrecision(4)).toString();
}

/** Mean ± std of a summary ({mean, std, n}), '—' without values. */
export function meanStd(m) {
  return m && m.n ? `${num(m.mean)} ± ${num(m.std)}` : '—';
}

/**
 * The table's columns: [heading, cell of a set-up's {label, summary}].
 * @type {Array<[string, (s: any) => string]>}
 */
const COLUMNS = [
  ['set-up', (s) => s.label],
  ['success', (s) => `${(100 * s.summary.success_rate).toFixed(0)}% (${s.summary.solved}/${s.summary.runs})`],
  ['time (ms) mean ± std', (s) => meanStd(s.summary.time_ms)],
  ['time median', (s) => num(s.summary.time_ms?.median)],
  ['nodes mean ± std', (s) => meanStd(s.summary.nodes)],
  ['nodes median', (s) => num(s.summary.nodes?.median)],
  ['checks mean ± std', (s) => meanStd(s.summary.checks)],
  ['checks median', (s) => num(s.summary.checks?.median)],
  ['cost mean ± std', (s) => meanStd(s.summary.cost)],
  ['cost median', (s) => num(s.summary.cost?.median)],
  ['smoothed cost median', (s) => num(s.summary.smoothed_cost?.median)],
];

/**
 * The columns in an arm course's own unit (report 004's: the norm of the stacked link-end
 * differences, summed; `summary.cost_fk`), shown only when some set-up's runs have it.
 * @type {Array<[string, (s: any) => string]>}
 */
const FK_COLUMNS = [
  ['cost (fk) mean ± std', (s) => meanStd(s.summary.cost_fk)],
  ['cost (fk) median', (s) => num(s.summary.cost_fk?.median)],
  ['smoothed cost (fk) median', (s) => num(s.summary.smoothed_cost_fk?.median)],
];

/** The caption's note when the table has the fk columns. */
export const FK_NOTE = "cost (fk): the Technion course's unit (report 004), the norm of the stacked link-end differences summed over the path";

/**
 * The table's text: {head: [heading], rows: [[cell]]} of the core's exported set-ups
 * ([{label, summary}]).
 * @param {any[]} setups @returns {{head: string[], rows: string[][], caption?: string}}
 */
export function resultRows(setups) {
  const cols = setups.some((s) => s.summary.cost_fk?.n > 0) ? [...COLUMNS, ...FK_COLUMNS] : COLUMNS;
  return { head: cols.map(([h]) => h), rows: setups.map((s) => cols.map(([, cell]) => cell(s))) };
}

/** Fill `table` (its thead and tbody) with `rows`: the first cell of a row is its heading. */
export function fillTable(table, { head, rows }) {
  table.tHead.replaceChildren(el('tr', {}, ...head.map((h) => el('th', { scope: 'col', text: h }))));
  table.tBodies[0].replaceChildren(...rows.map((r) => el('tr', {}, ...r.map((c, i) => el(i ? 'td' : 'th', i ? { text: c } : { scope: 'row', text: c })))));
}

const mdCell = (t) => String(t).replace(/\\/g, '\\\\').replace(/\|/g, '\\|').replace(/\s+/g, ' ');

/** The table as Markdown (GitHub's pipe table), `caption` as a line above it. */
export function toMarkdown({ head, rows }, caption = '') {
  const line = (cells) => `| ${cells.map(mdCell).join(' | ')} |`;
  const rule = `|${head.map((_, i) => (i ? ' ---: ' : ' --- ')).join('|')}|`;
  return `${caption ? `${mdCell(caption)}\n\n` : ''}${[line(head), rule, ...rows.map(line)].join('\n')}\n`;
}

const TEX = { '\\': '\\textbackslash{}', '&': '\\&', '%': '\\%', $: '\\$', '#': '\\#', _: '\\_', '{': '\\{', '}': '\\}', '~': '\\textasciitilde{}', '^': '\\textasciicircum{}' };

/** Text as LaTeX: its special characters escaped, ± and — as math and an em dash. */
export function texCell(t) {
  return String(t).replace(/[\\&%$#_{}~^]/g, (c) => TEX[c]).replace(/±/g, '$\\pm$').replace(/—/g, '---').replace(/…/g, '\\dots{}');
}

/** The table as a LaTeX table (booktabs rules), `caption` as its caption. */
export function toLatex({ head, rows }, caption = '') {
  const line = (cells) => `    ${cells.map(texCell).join(' & ')} \\\\`;
  return [
    '\\begin{table}[ht]',
    '  \\centering',
    ...(caption ? [`  \\caption{${texCell(caption)}}`] : []),
    `  \\begin{tabular}{l${'r'.repeat(head.length - 1)}}`,
    '    \\toprule',
    line(head),
    '    \\midrule',
    ...rows.map(line),
    '    \\bottomrule',
    '  \\end{tabular}',
    '\\end{table}',
    '',
  ].join('\n');
}
