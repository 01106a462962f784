// A minimal static file server that serves a folder under a URL sub-path, the
// way a project site is published (https://host/some/path/). The browser tests
// serve the production build with it (tests/browser/global-setup.ts), which
// proves that the site's relative asset URLs and the .wasm load from anywhere.
// Also usable by hand on the output of `npm run build`:
//
//   node scripts/static-server.mjs [dir=dist] [prefix=/voxpath/] [port=0]
//
// Plain Node, no dependencies.
import { createReadStream, statSync } from 'node:fs';
import { createServer } from 'node:http';
import { extname, join, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';

// Browsers check these two: WebAssembly.instantiateStreaming needs
// application/wasm, and module scripts need a JavaScript MIME type.
/** @type {Record<string, string>} */
const MIME = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.wasm': 'application/wasm',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json',
  '.map': 'application/json',
  '.svg': 'image/svg+xml',
  '.png': 'image/png',
  '.jpg': 'image/jpeg',
  '.ico': 'image/x-icon',
  '.txt': 'text/plain; charset=utf-8',
  '.woff2': 'font/woff2',
};

/**
 * Serves `dir` under `prefix` on 127.0.0.1. Anything outside the prefix is 404.
 * @param {{ dir: string, prefix?: string, port?: number }} options
 * @returns {Promise<{ url: string, close: () => Promise<void> }>} url ends with the prefix
 */
export async function serveStatic({ dir, prefix = '/voxpath/', port = 0 }) {
  const root = resolve(dir);
  const base = `/${prefix.split('/').filter(Boolean).join('/')}/`.replace(/^\/\/$/, '/');
  const server = createServer((req, res) => {
    /** @param {number} status @param {string} text */
    const reply = (status, text) => {
      res.writeHead(status, { 'content-type': 'text/plain; charset=utf-8' }).end(`${text}\n`);
    };
    if (req.method !== 'GET' && req.method !== 'HEAD') return reply(405, 'method not allowed');
    let path;
    try {
      path = decodeURIComponent(new URL(req.url ?? '/', 'http://localhost').pathname);
    } catch {
      return reply(400, 'bad request');
    }
    if (`${path}/` === base) {
      res.writeHead(301, { location: base }).end();
      return;
    }
    if (!path.startsWith(base)) return reply(404, 'not found');
    let file = resolve(root, `.${path.slice(base.length - 1)}`);
    if (file !== root && !file.startsWith(root + sep)) return reply(404, 'not found');
    try {
      if (statSync(file).isDirectory()) file = join(file, 'index.html');
      const { size } = statSync(file);
      res.writeHead(200, {
        'content-type': MIME[extname(file).toLowerCase()] ?? 'application/octet-stream',
        'content-length': size,
        'cache-control': 'no-store',
      });
      if (req.method === 'HEAD') res.end();
      else createReadStream(file).pipe(res);
    } catch {
      reply(404, 'not found');
    }
  });
  await new Promise((done, failed) => {
    server.once('error', failed);
    server.listen(port, '127.0.0.1', () => done(undefined));
  });
  const address = server.address();
  if (address === null || typeof address === 'string') throw new Error('server has no TCP address');
  return {
    url: `http://127.0.0.1:${address.port}${base}`,
    close: () => {
      server.closeAllConnections();
      return new Promise((done) => server.close(() => done()));
    },
  };
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const [dir = 'dist', prefix = '/voxpath/', port = '0'] = process.argv.slice(2);
  const { url } = await serveStatic({ dir, prefix, port: Number(port) });
  console.log(`serving ${resolve(dir)} at ${url} (Ctrl-C stops)`);
}
