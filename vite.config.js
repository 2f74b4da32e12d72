import { defineConfig } from 'vite';
import { resolve } from 'node:path';

// Every HTML page is an entry; relative base so the built site works from any static host and sub-path.
const pages = ['index', 'embed', 'media', 'surfaces', 'brdf', 'microfacets', 'fresnel', 'ndf', 'visibility', 'diffuse', 'rendering', 'performance', 'parity', 'exercises', 'tour', 'gallery', 'wall'];

// Modules for other people's pages, built with stable names at the top of dist/ (README, "Embedding"): the
// <shading-lab-widget> element (no three.js in it) and the reveal.js plugin on top of it.
const modules = { 'shading-lab-widget': 'src/embedding/shading-lab-widget.js', 'shading-lab-reveal': 'src/embedding/reveal-plugin.js' };

const HEAD = `
    <meta charset="utf-8" />
    <meta name="viewport" content="width=device-width, initial-scale=1" />
    <link rel="icon" href="favicon.svg" type="image/svg+xml" />`;

/**
 * The chrome every page shares, written once: the head's meta tags, and the site header. A page's
 * <body data-crumb="…"> gets the header with that crumb; a body without data-crumb (embed) gets none.
 */
function pageChrome() {
  return {
    name: 'shading-lab-page-chrome',
    transformIndexHtml(html) {
      const withHead = html.replace(/<head>/, `<head>${HEAD}`);
      return withHead.replace(/<body([^>]*)data-crumb="([^"]*)"([^>]*)>/, (_, a, crumb, b) => {
        const nav = crumb ? `<nav aria-label="Chapter"><a href="./">All chapters</a> · <span>${crumb}</span></nav>` : '';
        const subtitle = crumb ? '' : '<span class="subtitle">an interactive companion to <em>Background: Physics and Math of Shading</em> (Naty Hoffman, SIGGRAPH 2013)</span>';
        return `<body${a}${b}>\n    <header class="site-header"><a class="brand" href="./">Shading Lab</a>${nav}${subtitle}</header>`;
      });
    },
  };
}

export default defineConfig({
  base: './',
  plugins: [pageChrome()],
  build: {
    target: 'es2022',
    chunkSizeWarningLimit: 700, // three.js alone is ~540 kB and is shared by every 3-D page
    rollupOptions: {
      input: {
        ...Object.fromEntries(pages.map((p) => [p, resolve(import.meta.dirname, `${p}.html`)])),
        ...Object.fromEntries(Object.entries(modules).map(([name, file]) => [name, resolve(import.meta.dirname, file)])),
      },
      preserveEntrySignatures: 'allow-extension', // the modules keep their exports
      output: { entryFileNames: (chunk) => (chunk.name in modules ? '[name].js' : 'assets/[name]-[hash].js') },
    },
  },
});
