// Installs whatever is missing, idempotently: the wasm32 target, wasm-bindgen-cli at the exact
// version in Cargo.lock, wasm-pack, the npm packages (binaryen's wasm-opt for the build,
// playwright-core for the browser tests, axe-core for their accessibility check), and with --browser also
// Debian's chromium. Every devDependency missing from node_modules runs `npm install`.
// Everything comes from the package registries (crates.io, npm, Debian); nothing else is fetched.
import { execSync, spawnSync } from 'node:child_process';
import { existsSync, readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const browser = process.argv.includes('--browser');
const log = (m) => console.log(`[setup] ${m}`);

function sh(cmd, opts = {}) {
  log(cmd);
  execSync(cmd, { stdio: 'inherit', cwd: root, ...opts });
}
function out(cmd) {
  const r = spawnSync('sh', ['-c', cmd], { encoding: 'utf8', cwd: root });
  return r.status === 0 ? r.stdout.trim() : null;
}

// Cargo's bin folder on PATH for this process and its children.
const cargoBin = join(process.env.HOME || '/root', '.cargo', 'bin');
if (!process.env.PATH.split(':').includes(cargoBin)) process.env.PATH = `${cargoBin}:${process.env.PATH}`;

// rust-toolchain.toml pins the toolchain by version. A machine whose toolchain is that version
// under another name (rustup's `stable`) gets the version's name linked to it, so nothing is
// downloaded; else rustup installs it. Asked outside the clone, where the pin does not apply.
const pinned = (readFileSync(join(root, 'rust-toolchain.toml'), 'utf8').match(/^channel\s*=\s*"([^"]+)"/m) || [])[1];
if (pinned && out('rustup --version')) {
  const outside = { cwd: dirname(root) === root ? '/' : dirname(root) };
  const ask = (cmd) => { const r = spawnSync('sh', ['-c', cmd], { encoding: 'utf8', ...outside }); return r.status === 0 ? r.stdout.trim() : ''; };
  const installed = ask('rustup toolchain list').split('\n').map((l) => l.split(' ')[0]);
  if (!installed.some((t) => t === pinned || t.startsWith(`${pinned}-`))) {
    const dflt = installed.find((t) => ask(`rustup run ${t} rustc --version`).startsWith(`rustc ${pinned} `));
    const path = dflt && ask(`rustup run ${dflt} rustc --print sysroot`);
    if (path) sh(`rustup toolchain link ${pinned} "${path}"`, outside);
    else sh(`rustup toolchain install ${pinned} --profile minimal --component rustfmt clippy --target wasm32-unknown-unknown`, outside);
  }
}

if (!out('cargo --version')) {
  console.error('[setup] cargo is missing: install the Rust toolchain with rustup first.');
  process.exit(1);
}

const targets = out('rustup target list --installed') || '';
if (!targets.split('\n').includes('wasm32-unknown-unknown')) sh('rustup target add wasm32-unknown-unknown');
// rustfmt and clippy are checked by `npm test`; a minimal toolchain profile lacks them.
const components = out('rustup component list --installed') || '';
for (const c of ['rustfmt', 'clippy']) {
  if (!components.split('\n').some((l) => l.startsWith(`${c}-`))) sh(`rustup component add ${c}`);
}

if (!existsSync(join(root, 'Cargo.lock'))) sh('cargo generate-lockfile');
const lock = readFileSync(join(root, 'Cargo.lock'), 'utf8');
const m = lock.match(/name = "wasm-bindgen"\nversion = "([^"]+)"/);
if (!m) { console.error('[setup] wasm-bindgen not found in Cargo.lock'); process.exit(1); }
const want = m[1];
const have = (out('wasm-bindgen --version') || '').split(' ')[1];
if (have !== want) sh(`cargo install wasm-bindgen-cli --version ${want} --force`);
if (!out('wasm-pack --version')) sh('cargo install wasm-pack');

const npmPackages = Object.keys(JSON.parse(readFileSync(join(root, 'package.json'), 'utf8')).devDependencies || {});
if (npmPackages.some((p) => !existsSync(join(root, 'node_modules', p, 'package.json')))) sh('npm install --no-audit --no-fund');

if (browser) {
  if (!existsSync('/usr/bin/chromium')) {
    const sudo = process.getuid && process.getuid() === 0 ? '' : 'sudo ';
    sh(`${sudo}apt-get update`);
    sh(`${sudo}env DEBIAN_FRONTEND=noninteractive apt-get install -y chromium`);
  }
}
log('ready');
