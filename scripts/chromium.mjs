// Where the browser tests find Chromium, and how they launch it. Shared by
// scripts/setup.mjs (which installs Chromium when it is missing),
// tests/browser/harness.ts and bench/page-gcode.bench.ts (which launch it),
// so all agree on which binary is used and how.
// Plain Node, no dependencies: setup.mjs imports it before `npm install`.
import { accessSync, constants } from 'node:fs';
import { delimiter, join } from 'node:path';

/** Environment variable that names the Chromium (or Chrome) binary to use. */
const CHROMIUM_ENV = 'VOXPATH_CHROMIUM';

/** Printed when no browser is found and none can be installed. */
export const CHROMIUM_HINT =
  `no Chromium found: install it (Debian/Ubuntu: sudo apt-get install chromium) or set ${CHROMIUM_ENV}=/path/to/chromium`;

// Names used by Debian (chromium), Ubuntu/Fedora (chromium-browser) and
// Google's packages; the first one found on PATH or in the fixed list wins.
const NAMES = ['chromium', 'chromium-browser', 'google-chrome', 'google-chrome-stable'];
const FIXED = [
  '/usr/bin/chromium',
  '/usr/bin/chromium-browser',
  '/usr/bin/google-chrome',
  '/usr/bin/google-chrome-stable',
  '/snap/bin/chromium',
  '/Applications/Google Chrome.app/Contents/MacOS/Google Chrome',
];

/** @param {string} file */
function isExecutable(file) {
  try {
    accessSync(file, constants.X_OK);
    return true;
  } catch {
    return false;
  }
}

/**
 * Path of the Chromium binary to test with, or null when there is none.
 * An explicit VOXPATH_CHROMIUM that is not executable is an error rather than
 * a silent fallback, so a typo cannot make the tests use another browser.
 * @returns {string | null}
 */
export function findChromium() {
  const chosen = process.env[CHROMIUM_ENV];
  if (chosen) {
    if (!isExecutable(chosen)) throw new Error(`${CHROMIUM_ENV}=${chosen} is not an executable file`);
    return chosen;
  }
  const onPath = (process.env.PATH ?? '')
    .split(delimiter)
    .filter(Boolean)
    .flatMap((dir) => NAMES.map((name) => join(dir, name)));
  return [...FIXED, ...onPath].find(isExecutable) ?? null;
}

// Headless and offline-friendly: without the background-networking flags,
// Chromium keeps trying to reach Google's hosts, which this network refuses;
// --no-sandbox because Chromium's sandbox does not run as root (CI is root).
// WebGL: --disable-gpu leaves WebGL on SwiftShader (software, through ANGLE
// on Vulkan), which works here for three.js. Chromium has deprecated that
// automatic fallback and prints a console warning about it unless
// --enable-unsafe-swiftshader is given; playwright-core passes that flag by
// default too, but it is named here so the harness does not depend on it.
/** The flags Chromium is launched with, by the browser tests and the page bench. */
export const CHROMIUM_ARGS = [
  '--headless',
  '--no-sandbox',
  '--disable-gpu',
  '--enable-unsafe-swiftshader',
  '--disable-background-networking',
  '--disable-component-update',
  '--no-first-run',
  '--disable-quic',
  '--disable-sync',
];
