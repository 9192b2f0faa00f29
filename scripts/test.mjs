// Runs every test: ESLint's recommended rules on the JavaScript (eslint.config.mjs), tsc --checkJs
// (tsconfig.json; www/worker/tsconfig.json for the workers), rustfmt (rustfmt.toml), clippy with
// warnings as errors, native cargo tests, one untimed pass of the
// micro-benchmarks, the core compiled to wasm under Node (wasm-pack test --node),
// and the JavaScript tests (the wasm build in Node, the worker protocol, the page in headless
// chromium). Set-up first, so a fresh machine needs nothing else.
import { execSync } from 'node:child_process';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const run = (cmd) => {
  console.log(`\n[test] ${cmd}`);
  execSync(cmd, { stdio: 'inherit', cwd: root, env: { ...process.env, PATH: `${join(process.env.HOME || '/root', '.cargo', 'bin')}:${process.env.PATH}` } });
};
run('node scripts/setup.mjs --browser');
run('node node_modules/eslint/bin/eslint.js --max-warnings 0 .');
// tsc --checkJs needs the core's types (www/pkg/planarium.d.ts, from wasm-pack): build first.
run('node scripts/build.mjs');
run('node node_modules/typescript/bin/tsc -p .');
run('node node_modules/typescript/bin/tsc -p www/worker');
run('cargo fmt --check');
run('cargo fmt --check --manifest-path fuzz/Cargo.toml');
run('cargo clippy --all-targets --release -- -D warnings');
run('cargo test --release');
// The micro-benchmarks once each, untimed (criterion's --test): they must keep working.
run('cargo bench --bench core -- --test');
run('wasm-pack test --node --release -- --no-default-features');
run('node --test --test-concurrency=1 tests/js/');
