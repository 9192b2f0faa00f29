// A small static server for www/ (no dependencies). PORT and HOST may be set in the environment.
// Every response carries the pages' Content-Security-Policy (CSP below), nosniff and no-referrer.
import { createServer } from 'node:http';
import { readFile, stat } from 'node:fs/promises';
import { extname, join, normalize, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';

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

/**
 * Headers for every response: the CSP with frame-ancestors (header-only: embed.html may be framed
 * by any site, the other pages only by the playground's own), no MIME sniffing, no referrer.
 */
export function securityHeaders(file) {
  const framed = /(^|[/\\])embed\.html$/.test(file);
  return {
    'content-security-policy': `${CSP}; frame-ancestors ${framed ? '*' : "'self'"}`,
    'x-content-type-options': 'nosniff',
    'referrer-policy': 'no-referrer',
  };
}

export function serve({ port = 8080, host = '127.0.0.1', dir = root } = {}) {
  const server = createServer(async (req, res) => {
    try {
      const url = new URL(req.url, 'http://x');
      let path = normalize(decodeURIComponent(url.pathname)).replace(/^(\.\.[/\\])+/, '');
      let file = join(dir, path);
      if (!file.startsWith(dir)) { res.writeHead(403, securityHeaders('')).end(); return; }
      if ((await stat(file).catch(() => null))?.isDirectory()) file = join(file, 'index.html');
      const body = await readFile(file);
      res.writeHead(200, {
        'content-type': TYPES[extname(file)] || 'application/octet-stream', 'cache-control': 'no-cache', ...securityHeaders(file),
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
