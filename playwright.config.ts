import { defineConfig } from '@playwright/test';

// E2E_PORT lets a second run (e.g. a clean clone checked beside a working tree) use another port.
const PORT = Number(process.env.E2E_PORT ?? 4173);

/**
 * End-to-end tests of the production build in Debian's Chromium (no browser downloads). WebGL runs
 * on SwiftShader: with --disable-gpu this Chromium (156) still gives a WebGL2 context through
 * ANGLE/SwiftShader-Vulkan without any --use-angle / --enable-unsafe-swiftshader flag.
 */
export default defineConfig({
  testDir: 'tests/e2e',
  timeout: 90_000,
  expect: { timeout: 30_000 },
  fullyParallel: true,
  workers: 2,
  // A test that passes only on its retry fails the run (listed as flaky): a retry must not make CI green.
  retries: process.env.CI ? 1 : 0,
  failOnFlakyTests: !!process.env.CI,
  forbidOnly: !!process.env.CI,
  reporter: process.env.CI ? [['list'], ['html', { open: 'never' }]] : 'list',
  use: {
    baseURL: `http://localhost:${PORT}`,
    viewport: { width: 1280, height: 720 },
    trace: 'retain-on-failure',
    // A click on a button that never becomes clickable fails with its reason instead of waiting out the test.
    actionTimeout: 30_000,
    launchOptions: {
      executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium',
      args: [
        '--no-sandbox',
        '--disable-gpu',
        '--disable-background-networking',
        '--disable-component-update',
        '--no-first-run',
        '--disable-sync',
        '--disable-quic',
      ],
    },
  },
  webServer: {
    command: `npx vite build && npx vite preview --port ${PORT} --strictPort`,
    url: `http://localhost:${PORT}`,
    reuseExistingServer: !process.env.CI,
    timeout: 180_000,
    stdout: 'ignore',
    stderr: 'pipe',
  },
});
