// Writes THIRD_PARTY_NOTICES.md: the licences and notices of everything Planarium ships that others
// made. That is the Rust crates compiled into the core (the wasm module the page and dist/ carry,
// and the native command line), read from Cargo.lock through `cargo metadata`, each with the
// licence files its published package holds; the npm packages the page loads at run time (none:
// package.json has only devDependencies, the tools that build and test it); and the data the
// built-in scenarios were made from, with the licence text a data set's licence asks to travel
// with it (read from the copy in data/).
//
//   node scripts/notices.mjs            write the file
//   node scripts/notices.mjs --check    exit 1 when the file is not what the lock files give now
//
// Build-time code is left out: procedural macros (serde_derive, wasm-bindgen-macro, …) run in the
// compiler and put none of their own code into the output, and dev-dependencies never ship. The
// native command line is listed for x86_64-unknown-linux-gnu (the machine kind the project builds
// on), so the file is the same on every such machine.
import { execFileSync } from 'node:child_process';
import { existsSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
export const NOTICES = join(root, 'THIRD_PARTY_NOTICES.md');

/**
 * The data the project ships in its built-in scenarios, with where each came from; `licence`, when
 * the data's licence must be reproduced, is its licence file in the repository.
 * @type {{what: string, source: string, licence?: string}[]}
 */
const DATA = [
  {
    what: 'the vehicle-chain ("ASV") problems: the built-ins `asv-3-easy`, `asv-3`, `asv-7-easy`, `asv-7` '
      + '(and the map of `asv-7-long-gap` and `asv-15`)',
    source: 'the official problem files 3ASV-easy, 3ASV, 7ASV-easy and 7ASV of UQ COMP3702 (2017), public course '
      + 'support code; numbers converted to the scenario format (`tests/data/asv/` holds the files as published)',
  },
  {
    what: 'the manipulator course\'s maps: the built-ins `technion-mp` and `technion-ip`',
    source: 'Technion "Algorithmic Motion Planning", homework 3: `map_mp.json` and `map_ip.json`, '
      + 'converted to the scenario format (`tests/data/technion-hw3/` holds the files as published)',
  },
  {
    what: 'the kinematic chain in a horn: the built-ins `horn-10` and `horn-20`',
    source: 'the problem of OMPL\'s `KinematicChainBenchmark` demo (BSD licence; the problem\'s geometry is restated, '
      + 'no OMPL code is included)',
  },
  {
    what: 'the Unimation Puma 560: the built-ins `puma-rbo-wall` and `puma-boxes` (the Puma 560\'s kinematics and convex '
      + 'link hulls, and the Robotics Library\'s boxes example)',
    source: 'the Robotics Library (rl, https://github.com/roboticslibrary/rl, `examples/`, commit 91df9f2), BSD 2-Clause, '
      + '© 2009 Markus Rickert; `data/rl-puma560/` holds the files as published, `scripts/convert-rl.mjs` converts them',
    licence: 'data/rl-puma560/LICENSE.md',
  },
];

function cargoMetadata(args) {
  const out = execFileSync('cargo', ['metadata', '--format-version', '1', '--locked', ...args],
    { cwd: root, encoding: 'utf8', maxBuffer: 1 << 28, stdio: ['ignore', 'pipe', 'inherit'] });
  return JSON.parse(out);
}

/** The crates whose code is compiled into the output, from the root along normal dependencies. */
function runtimeCrates(meta) {
  const byId = new Map(meta.packages.map((p) => [p.id, p]));
  const nodes = new Map(meta.resolve.nodes.map((n) => [n.id, n]));
  const rootId = meta.resolve.root;
  const seen = new Set();
  const stack = [rootId];
  while (stack.length) {
    const id = stack.pop();
    if (seen.has(id)) continue;
    const pkg = byId.get(id);
    if (id !== rootId && pkg.targets.some((t) => t.kind.includes('proc-macro'))) continue;
    seen.add(id);
    for (const d of nodes.get(id).deps) {
      if (d.dep_kinds.some((k) => k.kind === null)) stack.push(d.pkg);
    }
  }
  seen.delete(rootId);
  return [...seen].map((id) => byId.get(id));
}

const LICENCE_FILE = /^(licen[cs]e|copying|copyright|notice|unlicense)/i;

/** The licence files a crate's published package holds, as {name, text}. */
function licenceFiles(pkg) {
  const dir = dirname(pkg.manifest_path);
  const names = readdirSync(dir).filter((n) => LICENCE_FILE.test(n)).sort();
  if (pkg.license_file && !names.includes(pkg.license_file)) names.push(pkg.license_file);
  return names.filter((n) => existsSync(join(dir, n)))
    .map((n) => ({ name: n, text: readFileSync(join(dir, n), 'utf8').replace(/\r\n/g, '\n').replace(/\s+$/, '') }));
}

/** The notices file's text, from the lock files as they are now. */
export function notices() {
  const builds = [
    ['wasm', runtimeCrates(cargoMetadata(['--filter-platform', 'wasm32-unknown-unknown', '--no-default-features']))],
    ['CLI', runtimeCrates(cargoMetadata(['--filter-platform', 'x86_64-unknown-linux-gnu']))],
  ];
  const crates = new Map();
  for (const [build, list] of builds) {
    for (const p of list) {
      const key = `${p.name} ${p.version}`;
      if (!crates.has(key)) crates.set(key, { pkg: p, builds: [] });
      crates.get(key).builds.push(build);
    }
  }
  const sorted = [...crates.values()].sort((a, b) => a.pkg.name.localeCompare(b.pkg.name)
    || a.pkg.version.localeCompare(b.pkg.version, 'en', { numeric: true }));

  // Identical licence texts are printed once, with every crate that ships them.
  const texts = new Map();
  const missing = [];
  for (const { pkg } of sorted) {
    const files = licenceFiles(pkg);
    if (!files.length) missing.push(pkg);
    for (const f of files) {
      if (!texts.has(f.text)) texts.set(f.text, { text: f.text, users: [] });
      texts.get(f.text).users.push(`${pkg.name} ${pkg.version} (${f.name})`);
    }
  }

  // The data's licence texts, after the crates' (so adding data renumbers no crate's text).
  const dataText = new Map();
  for (const d of DATA.filter((x) => x.licence)) {
    const text = readFileSync(join(root, d.licence), 'utf8').replace(/\r\n/g, '\n').replace(/\s+$/, '');
    if (!texts.has(text)) texts.set(text, { text, users: [] });
    texts.get(text).users.push(`the data of ${d.what.split(':')[0]} (\`${d.licence}\`)`);
    dataText.set(d, [...texts.keys()].indexOf(text) + 1);
  }

  const npm = JSON.parse(readFileSync(join(root, 'package.json'), 'utf8'));
  const npmRuntime = Object.keys(npm.dependencies || {});
  const fence = (t) => { const f = '`'.repeat(Math.max(3, ...[...t.matchAll(/`+/g)].map((m) => m[0].length + 1))); return `${f}text\n${t}\n${f}`; };
  const lines = [
    '# Third-party notices',
    '',
    'Planarium is licensed under MIT OR Apache-2.0 (`LICENSE-MIT`, `LICENSE-APACHE`). What it ships that',
    'others made is listed here with their licences. This file is written by `node scripts/notices.mjs`',
    'from `Cargo.lock`, `package.json` and the licence files in `data/`; `npm test` fails when it is out',
    'of date. `npm run build` copies it, with the two licence files, into `dist/`.',
    '',
    '## Rust crates compiled into Planarium',
    '',
    '"wasm": in the WebAssembly core the page runs (`www/pkg/planarium_bg.wasm`; its JavaScript glue',
    '`planarium.js` is generated by wasm-bindgen, listed below). "CLI": in the native command line',
    '(x86_64 Linux). Procedural macros and build tools run only while compiling and are not listed.',
    '',
    '| crate | version | licence | in | repository |',
    '|---|---|---|---|---|',
    ...sorted.map(({ pkg, builds: b }) => `| ${pkg.name} | ${pkg.version} | ${pkg.license || pkg.license_file || 'not stated'} | ${b.join(', ')} | ${pkg.repository || ''} |`),
    '',
    '## npm packages in the page',
    '',
    npmRuntime.length
      ? `The page loads: ${npmRuntime.join(', ')}.`
      : 'None. `package.json` lists only devDependencies (ESLint, TypeScript, binaryen\'s wasm-opt, playwright-core,'
        + '\naxe-core, which the accessibility test injects into the page under test), which build and test the page and'
        + '\nare not shipped.',
    '',
    '## Data',
    '',
    ...DATA.flatMap((d) => [`- **${d.what}**: ${d.source}${dataText.has(d) ? `; its licence is Text ${dataText.get(d)} below` : ''}.`]),
    '',
    '## Licence texts',
    '',
    'Each text below is printed once, after the crates whose published package holds it or the data it came with.',
  ];
  if (missing.length) {
    lines.push('', 'These published packages hold no licence file; their stated licence applies, whose standard text is',
      'in `LICENSE-MIT` or `LICENSE-APACHE` (copyright: the authors named):', '',
      ...missing.map((p) => `- ${p.name} ${p.version}: ${p.license}; authors: ${(p.authors || []).join(', ') || 'not stated'}${p.repository ? ` (${p.repository})` : ''}`));
  }
  let n = 0;
  for (const { text, users } of texts.values()) {
    n++;
    lines.push('', `### Text ${n}`, '', `Shipped by: ${users.join(', ')}.`, '', fence(text));
  }
  return `${lines.join('\n')}\n`;
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const text = notices();
  if (process.argv.includes('--check')) {
    const have = existsSync(NOTICES) ? readFileSync(NOTICES, 'utf8') : '';
    if (have !== text) {
      console.error('[notices] THIRD_PARTY_NOTICES.md is not what Cargo.lock and package.json give now: run node scripts/notices.mjs and commit it');
      process.exit(1);
    }
    console.log('[notices] THIRD_PARTY_NOTICES.md is current');
  } else {
    writeFileSync(NOTICES, text);
    console.log(`[notices] wrote ${NOTICES}`);
  }
}
