// Proves the browser test harness itself, whatever the page shows: the
// production build is served under a sub-path, the page loads its .wasm from
// there without errors, and the harness's Chromium renders WebGL and measures
// screenshots correctly.
import { afterAll, describe, expect, it } from 'vitest';
import { SITE_PREFIX } from './global-setup.js';
import { closeAll, openPage, screenshot, siteUrl } from './harness.js';

afterAll(closeAll);

describe('browser harness', () => {
  it('serves the built site under a sub-path only', async () => {
    const url = new URL(siteUrl());
    expect(url.pathname).toBe(SITE_PREFIX);
    const index = await fetch(url);
    expect(index.status).toBe(200);
    expect(index.headers.get('content-type')).toMatch(/^text\/html/);
    expect(await index.text()).toMatch(/<script[^>]+type="module"/);
    // An asset URL resolved against the root instead of the page would 404.
    expect((await fetch(new URL('/index.html', url))).status).toBe(404);
  });

  it('loads the page and its wasm from the sub-path with no errors', async () => {
    const p = await openPage();
    expect(p.status).toBe(200);
    const wasm = await p.waitForResponse((r) => r.url.endsWith('.wasm'));
    expect(new URL(wasm.url).pathname.startsWith(SITE_PREFIX)).toBe(true);
    expect(wasm.status).toBe(200);
    expect(wasm.contentType).toBe('application/wasm');
    // Give instantiation and the first frames time to report any error.
    await p.page.waitForLoadState('networkidle');
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('renders WebGL2 and measures it in a screenshot', async () => {
    const p = await openPage();
    // A canvas of our own on top of the page: black, with a red quarter drawn
    // by WebGL (scissored clear), so the expected statistics are exact.
    const renderer = await p.page.evaluate(() => {
      const canvas = document.createElement('canvas');
      canvas.id = 'harness-webgl-check';
      canvas.width = 200;
      canvas.height = 100;
      canvas.style.cssText = 'position:fixed;left:0;top:0;width:200px;height:100px;z-index:2147483647';
      document.body.append(canvas);
      const gl = canvas.getContext('webgl2', { antialias: false });
      if (!gl) return null;
      gl.clearColor(0, 0, 0, 1);
      gl.clear(gl.COLOR_BUFFER_BIT);
      gl.enable(gl.SCISSOR_TEST);
      gl.scissor(0, 0, 100, 50);
      gl.clearColor(1, 0, 0, 1);
      gl.clear(gl.COLOR_BUFFER_BIT);
      return String(gl.getParameter(gl.RENDERER));
    });
    expect(renderer, 'WebGL2 is unavailable in the harness Chromium').not.toBeNull();
    const stats = await screenshot(p.page, 'harness-webgl-check', '#harness-webgl-check');
    expect(stats).toMatchObject({ width: 200, height: 100, background: [0, 0, 0, 255], distinctColors: 2 });
    expect(stats.differingFraction).toBeCloseTo(0.25, 3);
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});
