import { availableParallelism } from 'node:os';
import { defineConfig } from 'vitest/config';

export default defineConfig({
  test: {
    include: ['tests/**/*.test.ts'],
    environment: 'node',
    testTimeout: 120_000,
    hookTimeout: 120_000,
    // Vitest's default leaves a core to its main thread, which only waits here: on a 2-core machine that ran the
    // files one at a time.
    maxWorkers: availableParallelism(),
  },
});
