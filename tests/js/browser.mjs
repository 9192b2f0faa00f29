// Shared by the browser tests: serve www/ on a free port and launch Debian's chromium headless
// (playwright-core, a fresh profile per launch, no network beyond loopback).
import { chromium } from 'playwright-core';
import { serve } from '../../scripts/serve.mjs';

export const CHROMIUM_ARGS = ['--no-sandbox', '--disable-gpu', '--disable-background-networking',
  '--disable-component-update', '--no-first-run', '--disable-sync'];

/** Start the static server and the browser; returns {server, browser, base, close()}. */
export async function startBrowser() {
  const server = await serve({ port: 0 });
  const base = `http://127.0.0.1:${server.address().port}/`;
  const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args: CHROMIUM_ARGS });
  const close = async () => {
    await browser.close();
    await new Promise((resolve) => server.close(resolve));
  };
  return { server, browser, base, close };
}
