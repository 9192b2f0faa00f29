// The repository's own promises, checked by `npm test` before anything is built:
// - nothing the tests, scripts, benchmarks or fuzz targets run reads outside the clone (a public
//   clone has nothing beside it: course files the tests use live in tests/data/);
// - THIRD_PARTY_NOTICES.md is what Cargo.lock and package.json give now (scripts/notices.mjs);
// - the built-in scenarios converted from data/ are what their converter writes now
//   (scripts/convert-rl.mjs: the Puma 560 scenarios from the Robotics Library's files);
// - CHANGELOG.md names every golden fingerprint pinned in tests/golden/runs.json (a figure in
//   someone's course notes changes when one does, so each change is written down);
// - every file of the repository the README, the docs, Cargo.toml, the code's comments and the
//   scenarios name exists (a statement about a moved file is stale);
// - no symbolic link is tracked (a link committed from a working copy, such as node_modules
//   pointing at another checkout, would break a fresh clone's set-up).
import { execFileSync } from 'node:child_process';
import { existsSync, readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { stale as staleConversions } from './convert-rl.mjs';
import { notices, NOTICES } from './notices.mjs';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const problems = [];

// 1. Paths outside the clone: the developers' ../shared, absolute paths of this workplace, or a
//    join that climbs out of the root.
const OUTSIDE = [
  [/\.\.\/shared\b|\bshared\/(data|seeds|docs)\b/, 'names ../shared (copy what it needs into tests/data/)'],
  [/['"`]\/work\//, 'names an absolute path of this machine'],
  [/['"]\.\.['"]\s*,\s*['"]shared['"]/, 'joins a path to ../shared'],
  [/CARGO_MANIFEST_DIR"\),\s*"\/\.\.\//, 'climbs out of the crate root'],
];
const tracked = execFileSync('git', ['ls-files', '--', 'tests', 'scripts', 'benches', 'bench', 'fuzz', '.ci', 'package.json', 'www'],
  { cwd: root, encoding: 'utf8' }).split('\n').filter((f) => f && /\.(rs|m?js|sh|json|toml|cpp|h|py)$|^\.ci\//.test(f));
const self = 'scripts/check-repo.mjs';
for (const file of tracked) {
  if (file === self || file.startsWith('www/pkg/')) continue;
  const lines = readFileSync(join(root, file), 'utf8').split('\n');
  lines.forEach((line, i) => {
    for (const [re, why] of OUTSIDE) if (re.test(line)) problems.push(`${file}:${i + 1}: ${why}: ${line.trim().slice(0, 120)}`);
  });
}

// 2. The notices.
if (readFileSync(NOTICES, 'utf8') !== notices()) {
  problems.push('THIRD_PARTY_NOTICES.md is out of date: run node scripts/notices.mjs and commit it');
}

// 2b. The scenarios converted from data/.
try {
  for (const p of staleConversions()) problems.push(`${p}: run node scripts/convert-rl.mjs and commit it`);
} catch (e) {
  problems.push(`scripts/convert-rl.mjs fails: ${e.message}`);
}

// 3. Every golden fingerprint named in the changelog.
const changelog = readFileSync(join(root, 'CHANGELOG.md'), 'utf8');
const cases = JSON.parse(readFileSync(join(root, 'tests', 'golden', 'cases.json'), 'utf8'));
const runs = JSON.parse(readFileSync(join(root, 'tests', 'golden', 'runs.json'), 'utf8'));
runs.forEach((r, i) => {
  if (!changelog.includes(r.events)) {
    const c = cases[i] || {};
    problems.push(`CHANGELOG.md does not name the golden run ${c.scenario} ${c.planner} seed ${c.seed} (events ${r.events}): `
      + 'say in its "Golden runs" section what changed it');
  }
});

// 4. Files named in prose exist. CHANGELOG.md is history and may name files since moved; the
//    paths below are other projects' files (OMPL's sources, a book's pages in an example).
const ELSEWHERE = new Set(['docs/notes/rrt.md', 'docs/index.md', 'src/ompl/tools/benchmark/src/Benchmark.cpp',
  'src/ompl/base/src/PlannerStatus.cpp']);
const PATH = /(?<![\w./-])((?:src|www|tests|scripts|benches|bench|fuzz|docs|scenarios|data)\/[\w./-]*\w\.(?:rs|js|mjs|md|json|toml|html|css|cpp|sh))\b/g;
const prose = execFileSync('git', ['ls-files', '--', 'README.md', 'docs', 'Cargo.toml', 'src', 'www', 'scenarios', 'data'],
  { cwd: root, encoding: 'utf8' }).split('\n').filter((f) => /\.(md|toml|rs|m?js|json)$/.test(f) && !f.startsWith('www/pkg/'));
for (const file of prose) {
  readFileSync(join(root, file), 'utf8').split('\n').forEach((line, i) => {
    for (const m of line.matchAll(PATH)) {
      if (!ELSEWHERE.has(m[1]) && !existsSync(join(root, m[1]))) problems.push(`${file}:${i + 1}: names ${m[1]}, which is not in the repository`);
    }
  });
}

// 5. No tracked symbolic link (git's mode 120000).
for (const line of execFileSync('git', ['ls-files', '-s'], { cwd: root, encoding: 'utf8' }).split('\n')) {
  if (line.startsWith('120000 ')) problems.push(`${line.split('\t')[1]}: a symbolic link is tracked (git rm --cached it; set-up makes what the clone needs)`);
}

if (problems.length) {
  console.error(`[check-repo] ${problems.length} problem(s):\n${problems.map((p) => `  ${p}`).join('\n')}`);
  process.exit(1);
}
console.log(`[check-repo] ${tracked.length} files read nothing outside the clone; notices current; converted scenarios current; ${runs.length} golden runs named in CHANGELOG.md; `
  + `the files ${prose.length} docs and sources name exist`);
