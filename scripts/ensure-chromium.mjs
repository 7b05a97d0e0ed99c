/**
 * Makes sure the browser tests have a Chromium: $CHROMIUM_PATH, or Debian's chromium. Installs Debian's package when
 * run as root; otherwise stops with what to install. Playwright's own browser download is not used.
 */
import { execSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { chromiumPath } from './chromium-path.mjs';

const path = chromiumPath();
if (process.env.CHROMIUM_PATH && !existsSync(path)) {
  console.error(`CHROMIUM_PATH is set to ${path}, but there is no file there. Point it at a Chromium or Chrome binary.`);
  process.exit(1);
}
if (!existsSync(path)) {
  const isRoot = typeof process.getuid === 'function' && process.getuid() === 0;
  if (!isRoot) {
    console.error(
      'No Chromium found for the browser tests.\n' +
        '  Install it:   sudo apt-get update && sudo apt-get install -y chromium\n' +
        '  or point to one:   CHROMIUM_PATH=/path/to/chromium npm test',
    );
    process.exit(1);
  }
  console.log("No Chromium found: installing Debian's chromium package (apt-get install -y chromium)…");
  execSync('apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y chromium', { stdio: 'inherit' });
  if (!existsSync(chromiumPath())) {
    console.error('apt-get finished but no Chromium binary appeared at /usr/bin/chromium.');
    process.exit(1);
  }
}
console.log(`Browser tests use ${chromiumPath()}`);
