// Runs every test: the repository's own checks (scripts/check-repo.mjs: nothing read outside the
// clone, the third-party notices current, every golden fingerprint named in CHANGELOG.md; and
// scripts/check-names.mjs: the page keys on capabilities, never on planner or robot names), ESLint's
// recommended rules on the JavaScript (eslint.config.mjs), tsc --checkJs (tsconfig.json;
// www/worker/tsconfig.json for the workers), rustfmt (rustfmt.toml), clippy with warnings as
// errors, native cargo tests, one untimed pass of the micro-benchmarks, the core compiled to wasm
// under Node (wasm-pack test --node), and the JavaScript tests (the wasm build in Node, the worker
// protocol, the page in headless chromium). Set-up first, so a fresh machine needs nothing else.
//
// Every stage runs even after one fails (a stage whose prerequisite failed is skipped and says
// which), and the run ends with one line per stage and a non-zero exit if any failed: one failure
// never hides the others.
import { spawnSync } from 'node:child_process';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const env = { ...process.env, PATH: `${join(process.env.HOME || '/root', '.cargo', 'bin')}:${process.env.PATH}` };

/** The stages in order: a name, the command, and the stages it needs to have passed. */
const STAGES = [
  { name: 'set-up', cmd: 'node scripts/setup.mjs --browser' },
  { name: 'repository checks', cmd: 'node scripts/check-repo.mjs', needs: ['set-up'] },
  { name: 'eslint', cmd: 'node node_modules/eslint/bin/eslint.js --max-warnings 0 .', needs: ['set-up'] },
  // tsc --checkJs needs the core's types (www/pkg/planarium.d.ts, from wasm-pack): build first.
  { name: 'wasm build', cmd: 'node scripts/build.mjs', needs: ['set-up'] },
  // No planner name or robot kind compared or listed in www/ (the names read from the wasm build).
  { name: 'names in www/', cmd: 'node scripts/check-names.mjs', needs: ['wasm build'] },
  { name: 'tsc (pages)', cmd: 'node node_modules/typescript/bin/tsc -p .', needs: ['wasm build'] },
  { name: 'tsc (workers)', cmd: 'node node_modules/typescript/bin/tsc -p www/worker', needs: ['wasm build'] },
  { name: 'rustfmt', cmd: 'cargo fmt --check', needs: ['set-up'] },
  { name: 'rustfmt (fuzz)', cmd: 'cargo fmt --check --manifest-path fuzz/Cargo.toml', needs: ['set-up'] },
  { name: 'clippy', cmd: 'cargo clippy --all-targets --release -- -D warnings', needs: ['set-up'] },
  // --no-fail-fast: every test binary runs even after one fails, so one failure hides no other.
  { name: 'cargo test', cmd: 'cargo test --release --no-fail-fast', needs: ['set-up'] },
  // The micro-benchmarks once each, untimed (criterion's --test): they must keep working.
  { name: 'benchmarks, untimed', cmd: 'cargo bench --bench core -- --test', needs: ['set-up'] },
  { name: 'wasm tests in Node', cmd: 'wasm-pack test --node --release -- --no-default-features', needs: ['set-up'] },
  { name: 'JavaScript tests', cmd: 'node --test --test-concurrency=1 tests/js/', needs: ['wasm build'] },
];

const results = new Map();
for (const stage of STAGES) {
  const missing = (stage.needs || []).filter((n) => results.get(n)?.result !== 'passed');
  if (missing.length) {
    results.set(stage.name, { result: `skipped (${missing.join(', ')} did not pass)`, seconds: 0 });
    console.log(`\n[test] ${stage.name}: skipped, ${missing.join(', ')} did not pass`);
    continue;
  }
  console.log(`\n[test] ${stage.cmd}`);
  const t = Date.now();
  const r = spawnSync(stage.cmd, { shell: true, stdio: 'inherit', cwd: root, env });
  const result = r.status === 0 ? 'passed' : `FAILED (${r.status ?? r.signal ?? r.error})`;
  results.set(stage.name, { result, seconds: (Date.now() - t) / 1000 });
}

const width = Math.max(...STAGES.map((s) => s.name.length));
console.log('\n[test] summary');
for (const { name } of STAGES) {
  const { result, seconds } = results.get(name);
  console.log(`[test]   ${name.padEnd(width)}  ${result}${seconds ? `  (${seconds.toFixed(0)} s)` : ''}`);
}
const failed = [...results.values()].filter((r) => r.result !== 'passed').length;
console.log(failed ? `[test] ${failed} of ${STAGES.length} stages did not pass` : `[test] all ${STAGES.length} stages passed`);
process.exit(failed ? 1 : 0);
