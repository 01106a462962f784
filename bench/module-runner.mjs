// Node 20 does not run TypeScript: the benches and the scripts that load
// bench/*.ts go through vite's module runner (vite is already a dependency;
// this is what vitest does).
import { createServer, createServerModuleRunner } from 'vite';

/**
 * A module runner for the repository at `root`, and a function that closes
 * it. No file watcher (watch: null): by default the server watches the whole
 * repository (rust/target and node_modules included) from a thread of this
 * process, which took a core of this 2-core machine while the benches ran:
 * a run of the plain JavaScript Bresenham took 14 ms of CPU time alone and
 * 22 to 94 ms beside the watcher, in CPU time and on the clock alike.
 * @param {string} root
 */
export async function openModuleRunner(root) {
  const server = await createServer({
    configFile: false,
    root,
    logLevel: 'error',
    appType: 'custom',
    server: { middlewareMode: true, hmr: false, ws: false, watch: null },
    optimizeDeps: { noDiscovery: true, include: [] },
  });
  const runner = createServerModuleRunner(server.environments.ssr, { hmr: false });
  return {
    runner,
    close: async () => {
      await runner.close();
      await server.close();
    },
  };
}
