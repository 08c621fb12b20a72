import { defineConfig } from 'vitest/config';

// The app lives in web/, static assets (sample meshes) in public/; the WASM core is built into
// build/wasm/ by scripts/build-wasm.sh and imported from there.
export default defineConfig({
  root: 'web',
  publicDir: '../public',
  base: './',
  build: { outDir: '../dist', emptyOutDir: true, target: 'es2022' },
  worker: { format: 'es' },
  server: { port: 5173, strictPort: false },
  preview: { port: 4173 },
  test: {
    root: '.',
    include: ['tests/unit/**/*.test.ts'],
    testTimeout: 120_000,
    hookTimeout: 120_000,
    pool: 'forks',
  },
});
