// Builds the core to WebAssembly for the page and the worker: www/pkg/ (wasm-pack, --target web),
// then optimises the module with binaryen's wasm-opt -O3 from npm (node_modules/.bin), and writes
// its brotli and gzip copies beside it (scripts/precompress.mjs).
// wasm-pack's own wasm-opt step stays off (Cargo.toml): it would fetch a binaryen release from GitHub.
// PLANARIUM_WASM_OPT=0 skips the optimisation for a quicker build while developing.
import { execFileSync, execSync } from 'node:child_process';
import { existsSync, statSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { precompress, PRECOMPRESSED } from './precompress.mjs';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const cargoBin = join(process.env.HOME || '/root', '.cargo', 'bin');
if (!process.env.PATH.split(':').includes(cargoBin)) process.env.PATH = `${cargoBin}:${process.env.PATH}`;
const cmd = 'wasm-pack build --target web --release --out-dir www/pkg --no-pack -- --no-default-features';
console.log(`[build] ${cmd}`);
execSync(cmd, { stdio: 'inherit', cwd: root });

const wasm = join(root, 'www', 'pkg', 'planarium_bg.wasm');
const wasmOpt = join(root, 'node_modules', '.bin', 'wasm-opt');
// Exactly the features rustc enables by default for wasm32-unknown-unknown, so that wasm-opt
// accepts the module and never introduces an instruction a browser of that generation lacks.
const features = ['sign-ext', 'mutable-globals', 'nontrapping-float-to-int', 'bulk-memory', 'reference-types', 'multivalue'];
if (process.env.PLANARIUM_WASM_OPT === '0') {
  console.log('[build] PLANARIUM_WASM_OPT=0: wasm-opt skipped');
} else if (!existsSync(wasmOpt)) {
  console.log('[build] node_modules/.bin/wasm-opt is missing (node scripts/setup.mjs installs it): wasm-opt skipped');
} else {
  const before = statSync(wasm).size;
  const args = ['-O3', ...features.map((f) => `--enable-${f}`), wasm, '-o', wasm];
  console.log(`[build] wasm-opt ${args.join(' ')}`);
  execFileSync(wasmOpt, args, { stdio: 'inherit', cwd: root });
  console.log(`[build] wasm-opt: ${(before / 1024).toFixed(0)} kB → ${(statSync(wasm).size / 1024).toFixed(0)} kB`);
}
// Brotli and gzip copies beside the module and its glue (scripts/precompress.mjs), served by
// scripts/serve.mjs to browsers that accept them.
for (const f of PRECOMPRESSED) {
  const { raw, br, gz } = precompress(join(root, 'www', f));
  console.log(`[build] ${f}: ${(raw / 1024).toFixed(0)} kB, brotli ${(br / 1024).toFixed(0)} kB, gzip ${(gz / 1024).toFixed(0)} kB`);
}
