// A small static server for www/ (no dependencies). PORT and HOST may be set in the environment.
// Every response says nosniff and no-referrer; Planarium's pages (and the scripts, for the workers)
// also carry the pages' Content-Security-Policy (CSP below). A file with a fresh precompressed copy
// beside it (`f.br`, `f.gz`: scripts/precompress.mjs, written by the wasm build) is sent as that
// copy to a browser whose Accept-Encoding takes it, brotli first (`Vary: Accept-Encoding`).
import { createServer } from 'node:http';
import { readFile, stat } from 'node:fs/promises';
import { extname, join, normalize, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';
import { ENCODINGS, fresh } from './precompress.mjs';

const root = join(dirname(fileURLToPath(import.meta.url)), '..', 'www');
const TYPES = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript; charset=utf-8', '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8', '.json': 'application/json', '.wasm': 'application/wasm', '.png': 'image/png',
  '.svg': 'image/svg+xml',
};

/**
 * The pages' Content-Security-Policy (each .html in www/ carries the same as a <meta>, for static
 * hosts; a test checks they agree): the page's own files only, WebAssembly compiled from them, the
 * module workers, exports as blob: URLs, no plugins, no <base>, no forms.
 */
export const CSP = "default-src 'self'; script-src 'self' 'wasm-unsafe-eval'; worker-src 'self'; style-src 'self'; "
  + "img-src 'self' data: blob:; media-src 'self' blob:; connect-src 'self'; object-src 'none'; base-uri 'none'; form-action 'none'";

/** The <meta> every page of Planarium carries (scripts/dist.mjs and a test check it). */
export const CSP_META = `<meta http-equiv="Content-Security-Policy" content="${CSP}">`;

/**
 * Headers for a response: no MIME sniffing, no referrer, and the CSP with frame-ancestors
 * (header-only: embed.html may be framed by any site, the other pages only by the playground's
 * own). `body`: an .html file's text: it gets the CSP only if it is one of Planarium's pages (it
 * carries CSP_META), not a page of course notes that embeds the playground (with its own styles
 * and scripts, served from here in tests); any other file gets it (it matters for the workers).
 */
export function securityHeaders(file, body = null) {
  const headers = { 'x-content-type-options': 'nosniff', 'referrer-policy': 'no-referrer' };
  if (/\.html$/.test(file) && !(body && String(body).includes(CSP_META))) return headers;
  const framed = /(^|[/\\])embed\.html$/.test(file);
  return { 'content-security-policy': `${CSP}; frame-ancestors ${framed ? '*' : "'self'"}`, ...headers };
}

/**
 * The precompressed copy of `file` to send for a request's Accept-Encoding header: {encoding,
 * path}, or null (send the file as it is). Only an encoding the header names without q=0.
 */
export function negotiate(file, acceptEncoding) {
  const accepted = new Set();
  for (const part of String(acceptEncoding || '').toLowerCase().split(',')) {
    const [name, ...params] = part.trim().split(';').map((t) => t.trim());
    if (name && !params.some((p) => /^q=0(\.0*)?$/.test(p))) accepted.add(name);
  }
  for (const [encoding, suffix] of ENCODINGS) {
    if (accepted.has(encoding) && fresh(file, suffix)) return { encoding, path: `${file}${suffix}` };
  }
  return null;
}

export function serve({ port = 8080, host = '127.0.0.1', dir = root } = {}) {
  const server = createServer(async (req, res) => {
    try {
      const url = new URL(req.url, 'http://x');
      let path = normalize(decodeURIComponent(url.pathname)).replace(/^(\.\.[/\\])+/, '');
      let file = join(dir, path);
      if (!file.startsWith(dir)) { res.writeHead(403, securityHeaders('')).end(); return; }
      if ((await stat(file).catch(() => null))?.isDirectory()) file = join(file, 'index.html');
      const packed = /\.(br|gz)$/.test(file) ? null : negotiate(file, req.headers['accept-encoding']);
      const body = await readFile(packed ? packed.path : file);
      res.writeHead(200, {
        'content-type': TYPES[extname(file)] || 'application/octet-stream', 'cache-control': 'no-cache',
        ...(packed ? { 'content-encoding': packed.encoding, vary: 'Accept-Encoding' } : {}),
        ...securityHeaders(file, packed ? null : body),
      });
      res.end(body);
    } catch {
      res.writeHead(404, { 'content-type': 'text/plain', ...securityHeaders('') }).end('not found');
    }
  });
  return new Promise((resolve) => server.listen(port, host, () => resolve(server)));
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const port = Number(process.env.PORT || 8080);
  const host = process.env.HOST || '127.0.0.1';
  await serve({ port, host });
  console.log(`Planarium is at http://${host}:${port}/`);
}
