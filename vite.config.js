import { defineConfig } from 'vite';
import { resolve } from 'node:path';

// Every HTML page is an entry; relative base so the built site works from any static host and sub-path.
const pages = ['index', 'embed', 'brdf', 'microfacets', 'fresnel', 'ndf', 'visibility', 'parity'];

export default defineConfig({
  base: './',
  build: {
    target: 'es2022',
    chunkSizeWarningLimit: 700, // three.js alone is ~540 kB and is shared by every 3-D page
    rollupOptions: { input: Object.fromEntries(pages.map((p) => [p, resolve(import.meta.dirname, `${p}.html`)])) },
  },
});
