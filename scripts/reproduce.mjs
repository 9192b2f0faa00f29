#!/usr/bin/env node
// The seed reports' tables, reproduced with Planarium beside the reports' own figures:
// report 000 (time per official ASV file), report 001 (its samplers and tree variants table),
// report 003 (standard and bidirectional RRT on a polygon and a 3-link chain) and report 004
// (the Technion arm: E1/E2 × goal bias, and inspection at coverage 0.5 and 0.75).
//
//   npm run reproduce                 builds the CLI, writes docs/reproducing-the-reports.md (~N min)
//   node scripts/reproduce.mjs [--quick] [--out FILE] [--bin PATH] [--only 001]
//     --bin: use that CLI, no build; --only: run one report and replace its section in the
//     existing FILE (the other sections and the head stay as they were).
//
// --quick runs 2 seeds per row with short limits (the test uses it); the document is made without it.
// Every number comes from the native CLI's JSON (`planarium plan … --json`, `planarium bench …
// --json-file`); the report 004 costs in the report's unit are recomputed here from the path.

import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { REPORTS } from './reproduce/reports.mjs';
import { ci95, fkCost, mean, median, std, t975, welch } from './reproduce/measure.mjs';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const args = process.argv.slice(2);
const flag = (name) => args.includes(name);
const value = (name, dflt) => {
  const i = args.indexOf(name);
  return i >= 0 && i + 1 < args.length ? args[i + 1] : dflt;
};
const quick = flag('--quick');
const only = value('--only', null);
const selected = only === null ? REPORTS : REPORTS.filter((r) => r.id === `report ${only}`);
if (!selected.length) throw new Error(`--only ${only}: no such report (known: ${REPORTS.map((r) => r.id.slice(7)).join(', ')})`);
const out = resolve(value('--out', join(root, 'docs', 'reproducing-the-reports.md')));
const bin = resolve(value('--bin', join(root, 'target', 'release', 'planarium')));
if (!args.includes('--bin')) {
  // `npm run reproduce` from a fresh clone: build the CLI first (a no-op when it is up to date).
  const PATH = `${join(process.env.HOME || '/root', '.cargo', 'bin')}:${process.env.PATH}`;
  const b = spawnSync('cargo', ['build', '--release', '--bin', 'planarium'], { cwd: root, stdio: 'inherit', env: { ...process.env, PATH } });
  if (b.status !== 0) throw new Error('cargo build --release --bin planarium failed');
}
const scratch = mkdtempSync(join(tmpdir(), 'planarium-reproduce-'));

/** Run the CLI; its stdout, or an error naming the command and its stderr. */
function cli(argv) {
  const r = spawnSync(bin, argv, { encoding: 'utf8', maxBuffer: 1 << 28 });
  if (r.status !== 0) throw new Error(`planarium ${argv.join(' ')} failed (${r.status}): ${r.stderr || r.error}`);
  return r.stdout;
}

/** One planned run's result (the contract's JSON). */
function plan(scenario, flags, seed) {
  return JSON.parse(cli(['plan', scenario, '--json', '--seed', String(seed), ...flags]));
}

/** `bench` with set-ups ({label, flags}) over seeds 1..runs; the report's set-ups with their rows and summaries. */
function bench(scenario, setups, runs, flags) {
  const file = join(scratch, `bench-${scenario}.json`);
  const argv = ['bench', scenario, '--runs', String(runs), '--json-file', file, ...flags];
  for (const s of setups) argv.push('--setup', `${s.label}: ${s.flags}`);
  cli(argv);
  return JSON.parse(readFileSync(file, 'utf8')).setups;
}

/** `bench --course-grade` on `problems`: its printed verdicts (it exits 2 when a problem fails; that is a result too). */
function courseGrade(problems) {
  const r = spawnSync(bin, ['bench', '--course-grade', ...problems], { encoding: 'utf8' });
  if (r.status !== 0 && r.status !== 2) throw new Error(`planarium bench --course-grade failed (${r.status}): ${r.stderr}`);
  return r.stdout.trim();
}

const env = { quick, plan, bench, courseGrade, fkCost, mean, median, std, ci95, t975, welch, seeds: (n) => Array.from({ length: quick ? 2 : n }, (_, i) => i + 1) };

const started = Date.now();
const parts = [];
try {
  for (const report of selected) {
    const t0 = Date.now();
    parts.push(report.run(env));
    console.error(`reproduce: ${report.id} in ${((Date.now() - t0) / 1000).toFixed(1)} s`);
  }
} finally {
  rmSync(scratch, { recursive: true, force: true });
}
const commit = spawnSync('git', ['rev-parse', '--short', 'HEAD'], { cwd: root, encoding: 'utf8' }).stdout?.trim() || 'unknown';
const seconds = ((Date.now() - started) / 1000).toFixed(0);
if (only !== null) {
  // One report's section, replaced in the existing document (from its "## Report NNN" heading to the next).
  const doc = readFileSync(out, 'utf8');
  const heading = `## Report ${only}`;
  const at = doc.indexOf(heading);
  if (at < 0) throw new Error(`${out} has no "${heading}" section to replace`);
  const next = doc.indexOf('\n## Report ', at + heading.length);
  const [first, ...rest] = parts[0].split('\n');
  const note = `\n_This section was regenerated on its own (\`node scripts/reproduce.mjs${quick ? ' --quick' : ''} --only ${only}\`), ${new Date().toISOString().slice(0, 10)}, commit ${commit}, ${seconds} s._`;
  const section = [first, note, ...rest].join('\n');
  writeFileSync(out, doc.slice(0, at) + section + (next < 0 ? '' : doc.slice(next)));
} else {
  const head = `# The reports' tables, reproduced

Made by \`npm run reproduce\` (\`node scripts/reproduce.mjs${quick ? ' --quick' : ''}\`), ${new Date().toISOString().slice(0, 10)}, commit ${commit},
native release build on the project's 2-core machine; ${seconds} s in all. Each table puts the
report's own figures beside Planarium's, with the commands and seeds that made them. Times are wall
clock on a shared machine (±15% run to run); the reports ran on their authors' laptops, in Java or
Python, so compare times by their ratios within a table, and counts (nodes, checks, movements)
directly. Where a report leaves a setting unknown, the section says what was chosen.
${quick ? '\n**Quick mode: 2 seeds per row and short limits; the figures below are not the document\'s.**\n' : ''}`;
  writeFileSync(out, [head, ...parts].join('\n'));
}
console.error(`reproduce: wrote ${out}`);
