import { defineConfig } from 'vite';
import { basename, resolve } from 'node:path';
import { VitePWA } from 'vite-plugin-pwa';
import { chapterPagerHtml } from './src/pages/chapter-pager.js';

// Every HTML page is an entry; relative base so the built site works from any static host and sub-path.
const pages = [
  'index',
  'embed',
  'media',
  'surfaces',
  'brdf',
  'microfacets',
  'fresnel',
  'ndf',
  'visibility',
  'diffuse',
  'rendering',
  'today',
  'performance',
  'parity',
  'exercises',
  'author',
  'tour',
  'gallery',
  'wall',
];

// Modules for other people's pages, built with stable names at the top of dist/ (README, "Embedding"): the
// <shading-lab-widget> element (no three.js in it) and the reveal.js plugin on top of it.
const modules = {
  'shading-lab-widget': 'src/embedding/shading-lab-widget.js',
  'shading-lab-reveal': 'src/embedding/reveal-plugin.js',
};

const HEAD = `
    <meta charset="utf-8" />
    <meta name="viewport" content="width=device-width, initial-scale=1" />
    <link rel="icon" href="favicon.svg" type="image/svg+xml" />`;

/**
 * The chrome every page shares, written once: the head's meta tags, and the site header. A page's
 * <body data-crumb="…"> gets the header with that crumb; a body without data-crumb (embed) gets none. A chapter's
 * page ends its <main> with the links to the previous and next chapter (src/pages/chapter-pager.js).
 */
function pageChrome() {
  return {
    name: 'shading-lab-page-chrome',
    transformIndexHtml(html, { filename }) {
      const pager = chapterPagerHtml(basename(filename));
      const paged = pager ? html.replace('</main>', `  ${pager}\n    </main>`) : html;
      const withHead = paged.replace(/<head>/, `<head>${HEAD}`);
      return withHead.replace(/<body([^>]*)data-crumb="([^"]*)"([^>]*)>/, (_, a, crumb, b) => {
        const nav = crumb
          ? `<nav aria-label="Chapter"><a href="./">All chapters</a> · <span>${crumb}</span></nav>`
          : '';
        const subtitle = crumb
          ? ''
          : '<span class="subtitle">an interactive companion to <em>Background: Physics and Math of Shading</em> ' +
            '(Naty Hoffman, SIGGRAPH 2013)</span>';
        const brand = '<a class="brand" href="./">Shading Lab</a>';
        return `<body${a}${b}>\n    <header class="site-header">${brand}${nav}${subtitle}</header>`;
      });
    },
  };
}

/**
 * The Content-Security-Policy of a built page, one directive a line. Scripts come only from the app's own
 * origin: no inline script, no inline handler, no eval (`user code never runs as JavaScript` is the browser's
 * rule, not only ours). The looser parts, and why:
 * - style-src 'unsafe-inline': lil-gui injects its stylesheet as a <style> element and the widgets' readouts
 *   carry style attributes (swatch colours); CSS cannot run script, so this costs nothing of the above.
 * - img-src data: blob:, font-src data:: lil-gui's font is a data: URL; a canvas saved as PNG goes out through a
 *   blob: URL, and an image decoded in the page may come as data:.
 * - connect-src on exercises.html: `?src=URL` fetches a lecturer's set from any HTTPS host (which must allow
 *   it by CORS) or from a data: URL; every other page fetches only from its own origin.
 * frame-ancestors cannot be set from a <meta> (embedding is governed by the postMessage origin checks).
 */
export function contentSecurityPolicy(page) {
  return [
    "default-src 'self'",
    "script-src 'self'",
    "worker-src 'self'",
    "style-src 'self' 'unsafe-inline'",
    "img-src 'self' data: blob:",
    "font-src 'self' data:",
    `connect-src 'self'${page === 'exercises' ? ' https: data:' : ''}`,
    "object-src 'none'",
    "base-uri 'self'",
    "form-action 'self'",
  ].join('; ');
}

/** Puts the policy in every built page as a <meta>, before any script; the dev server (HMR) is left without. */
function cspMeta() {
  return {
    name: 'shading-lab-csp',
    apply: 'build',
    transformIndexHtml: {
      order: 'post',
      handler(html, { filename }) {
        const policy = contentSecurityPolicy(basename(filename, '.html'));
        const meta = `<meta http-equiv="Content-Security-Policy" content="${policy}" />`;
        return html.replace(/<meta charset="utf-8" \/>/, (charset) => `${charset}\n    ${meta}`);
      },
    },
  };
}

/** Every page loads src/core/framework/offline.js, which registers the service worker (before Vite bundles it). */
function offlineScript() {
  const tag = '    <script type="module" src="/src/core/framework/offline.js"></script>\n  </body>';
  return {
    name: 'shading-lab-offline',
    transformIndexHtml: { order: 'pre', handler: (html) => html.replace('</body>', tag) },
  };
}

// Offline after one visit: Workbox precaches the whole build (pages, chunks, exercises, icons). A page asked for
// with any query (embed.html?w=…, fresnel.html?zones.mode=…) is served from its cached file.
const offline = VitePWA({
  registerType: 'prompt',
  injectRegister: false,
  manifest: {
    name: 'Shading Lab',
    short_name: 'Shading Lab',
    description: 'Interactive companion to “Background: Physics and Math of Shading” (SIGGRAPH 2013)',
    theme_color: '#0b6bcb',
    background_color: '#fbfbfa',
    icons: [{ src: 'favicon.svg', sizes: 'any', type: 'image/svg+xml' }],
  },
  workbox: {
    globPatterns: ['**/*.{html,js,css,svg,png,webp,json,hdr,exr}'],
    ignoreURLParametersMatching: [/.*/],
    maximumFileSizeToCacheInBytes: 4 * 1024 * 1024,
    navigateFallback: null,
  },
});

export default defineConfig({
  base: './',
  plugins: [pageChrome(), cspMeta(), offlineScript(), offline],
  build: {
    target: 'es2022',
    chunkSizeWarningLimit: 700, // three.js alone is ~540 kB and is shared by every 3-D page
    rollupOptions: {
      input: {
        ...Object.fromEntries(pages.map((p) => [p, resolve(import.meta.dirname, `${p}.html`)])),
        ...Object.fromEntries(
          Object.entries(modules).map(([name, file]) => [name, resolve(import.meta.dirname, file)]),
        ),
      },
      preserveEntrySignatures: 'allow-extension', // the modules keep their exports
      output: { entryFileNames: (chunk) => (chunk.name in modules ? '[name].js' : 'assets/[name]-[hash].js') },
    },
  },
});
