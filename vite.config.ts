import { defineConfig } from 'vite';

// The page lives in web/ and is built to dist/ with relative asset URLs
// (base './'), so the built site, .wasm included, works from any static server
// under any sub-path. tests/browser/global-setup.ts builds it with this same
// file and serves it under a sub-path to prove that.
export default defineConfig({
  root: 'web',
  publicDir: '../public',
  base: './',
  build: {
    outDir: '../dist',
    emptyOutDir: true,
    // three.js alone is about 520 kB minified, over vite's default 500 kB
    // warning; the limit still flags real growth of the page's own code.
    chunkSizeWarningLimit: 800,
  },
  server: {
    host: 'localhost',
    port: 5173,
    // Another server on 5173 (say a second checkout) moves this one to 5174.
    strictPort: false,
  },
});
