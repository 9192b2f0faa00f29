// The static site: a copy of www/ (with the wasm build in pkg/) in dist/, ready for any static
// host under any sub-path. Run `npm run build` (set-up, wasm build, then this), or this alone once
// www/pkg/ is built. `--out DIR` writes elsewhere (DIR must be empty, missing, or an earlier copy).
//
// Every URL in the pages and modules is relative (a check below fails the build otherwise), so the
// folder works as https://example.org/, https://example.org/notes/planarium/ or file-free hosts
// alike; the planning worker is a module worker from the same folder, so it must be served from
// the same origin as the page that shows it.
import { cpSync, existsSync, mkdirSync, readdirSync, readFileSync, rmSync, statSync } from 'node:fs';
import { dirname, join, relative, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';
import { CSP_META } from './serve.mjs';
import { precompress, PRECOMPRESSED } from './precompress.mjs';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const www = join(root, 'www');
const args = process.argv.slice(2);
const outArg = args.includes('--out') ? args[args.indexOf('--out') + 1] : null;
const out = resolve(outArg || join(root, 'dist'));
const fail = (m) => { console.error(`[dist] ${m}`); process.exit(1); };

for (const f of ['planarium.js', 'planarium_bg.wasm']) {
  if (!existsSync(join(www, 'pkg', f))) fail(`www/pkg/${f} is missing: build the core first (node scripts/build.mjs, or npm run build).`);
}
if (out === root || out === www || root.startsWith(out + sep) || out.startsWith(www + sep)) fail(`refusing to write into ${out}`);
if (existsSync(out)) {
  const entries = readdirSync(out);
  const earlier = entries.includes('embed.html') && entries.includes('worker');
  if (entries.length && !earlier) fail(`${out} is not empty and not an earlier copy of the playground; pick another --out`);
  rmSync(out, { recursive: true, force: true });
}
mkdirSync(out, { recursive: true });

// Left out: tests, and the wasm build's own bookkeeping.
const skip = (name) => /\.test\.m?js$/.test(name) || name === 'tests' || name === '.gitignore' || name === 'package.json'
  || name === 'README.md' || (name.endsWith('.d.ts') && name !== 'planarium-playground.d.ts'); // the element's types are shipped
cpSync(www, out, {
  recursive: true,
  filter: (src) => src === www || !skip(src.split(sep).pop()),
});

// Brotli and gzip copies beside the module and its glue (scripts/precompress.mjs), made afresh from
// the copy: a host that serves precompressed files (nginx's gzip_static and brotli_static, Caddy's
// `precompressed`, Netlify and Cloudflare Pages compress on their own) sends a third of the wasm.
for (const f of PRECOMPRESSED) {
  const { raw, br, gz } = precompress(join(out, f));
  console.log(`[dist] ${f}: ${(raw / 1024).toFixed(0)} KiB; ${f}.br ${(br / 1024).toFixed(0)} KiB, ${f}.gz ${(gz / 1024).toFixed(0)} KiB`);
}

// The licences: Planarium's own and the third-party notices (scripts/notices.mjs), for whoever copies
// the folder onto a course site.
for (const f of ['LICENSE-MIT', 'LICENSE-APACHE', 'THIRD_PARTY_NOTICES.md']) {
  if (!existsSync(join(root, f))) fail(`${f} is missing`);
  cpSync(join(root, f), join(out, f));
}

// Every URL relative: no "/…" (root of the host) and no "http(s)://" in src/href, imports, workers or fetches;
// every page with the CSP <meta> and nothing inline.
const problems = [];
let files = 0, bytes = 0;
function walk(dir) {
  for (const name of readdirSync(dir)) {
    const path = join(dir, name);
    const st = statSync(path);
    if (st.isDirectory()) { walk(path); continue; }
    files++;
    bytes += st.size;
    if (!/\.(html|m?js|css)$/.test(name)) continue;
    const text = readFileSync(path, 'utf8');
    // a static host sends no CSP header: each page must carry the policy itself, and no inline script or style
    if (name.endsWith('.html')) {
      if (!text.includes(CSP_META)) {
        problems.push(`${relative(out, path)}: no <meta http-equiv="Content-Security-Policy"> with the policy of scripts/serve.mjs`);
      }
      if (/<script(?![^>]*\bsrc=)[^>]*>|<style\b|\sstyle\s*=|\son[a-z]+\s*=/i.test(text)) {
        problems.push(`${relative(out, path)}: an inline script, style or event handler (the CSP forbids them)`);
      }
    }
    const rules = [
      [/\b(?:src|href|data-src)\s*=\s*["'](\/[^/"']|\/\/|https?:)/g, 'an absolute src/href'],
      [/\bimport\s*(?:[\w{}*\s,]+from\s*)?["'](\/|https?:)/g, 'an absolute import'],
      [/\bimport\(\s*["'](\/|https?:)/g, 'an absolute dynamic import'],
      [/\bnew\s+(?:URL|Worker)\(\s*["'](\/|https?:)/g, 'an absolute URL or worker'],
      [/\bfetch\(\s*["'](\/|https?:)/g, 'an absolute fetch'],
      [/url\(\s*["']?(\/|https?:)/g, 'an absolute CSS url()'],
    ];
    for (const [re, what] of rules) {
      for (const m of text.matchAll(re)) {
        const line = text.slice(0, m.index).split('\n').length;
        problems.push(`${relative(out, path)}:${line}: ${what}: ${m[0]}`);
      }
    }
  }
}
walk(out);
if (problems.length) fail(`URLs must be relative for a static host under any sub-path, pages must carry the CSP:\n  ${problems.join('\n  ')}`);
console.log(`[dist] ${files} files, ${(bytes / 1024).toFixed(0)} KiB → ${relative(process.cwd(), out) || '.'}`);
console.log('[dist] copy that folder to any static host (it must serve .wasm; application/wasm is best); open index.html or embed.html#scenario=narrow');
