// Builds the core to WebAssembly for the page and the worker: www/pkg/ (wasm-pack, --target web).
import { execSync } from 'node:child_process';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const cargoBin = join(process.env.HOME || '/root', '.cargo', 'bin');
if (!process.env.PATH.split(':').includes(cargoBin)) process.env.PATH = `${cargoBin}:${process.env.PATH}`;
const cmd = 'wasm-pack build --target web --release --out-dir www/pkg --no-typescript --no-pack -- --no-default-features';
console.log(`[build] ${cmd}`);
execSync(cmd, { stdio: 'inherit', cwd: root });
