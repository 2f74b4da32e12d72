// ESLint (flat config): the recommended rules, the house's line and function lengths, and the boundaries
// between rooms (DESIGN.md, "Layout"): src/math imports nothing of the app; the shared core imports no widget,
// page or lab; user-written terms (src/core/custom) import only the math and the GPU layer; a widget imports no
// page; only debug-hooks.js touches the test hooks (globalThis.__shadingLab).
import js from '@eslint/js';
import globals from 'globals';

const APP = ['core', 'widgets', 'pages', 'lab', 'exercises', 'tour', 'embedding', 'measured'];
const forbid = (rooms, why) => ({
  patterns: [{ regex: `(^|/)(${rooms.join('|')})/`, message: why }],
});

export default [
  { ignores: ['dist/**', 'node_modules/**', 'public/**', 'docs/**', 'bench/results/**', '**/*.data.js'] },
  js.configs.recommended,
  {
    languageOptions: {
      ecmaVersion: 2025,
      sourceType: 'module',
      globals: { ...globals.browser, ...globals.node, ...globals.worker },
    },
    rules: {
      'max-len': ['error', { code: 120, ignoreUrls: true }],
      'no-unused-vars': ['error', { argsIgnorePattern: '^_', caughtErrors: 'none' }],
    },
  },
  {
    files: ['src/**/*.js'],
    rules: { 'max-lines-per-function': ['error', { max: 80, skipBlankLines: true, skipComments: true }] },
  },
  {
    files: ['src/math/**/*.js'],
    rules: {
      'no-restricted-imports': [
        'error',
        {
          paths: ['three', 'lil-gui', 'uplot', 'katex'].map((name) => ({ name, message: 'src/math is pure math.' })),
          ...forbid(
            APP.filter((r) => r !== 'math'),
            'src/math imports nothing of the app.',
          ),
        },
      ],
    },
  },
  {
    files: ['src/core/**/*.js', 'src/lab/**/*.js'],
    rules: {
      'no-restricted-imports': ['error', forbid(['widgets', 'pages'], 'Shared code imports no widget or page.')],
    },
  },
  {
    files: ['src/core/framework/**/*.js'],
    rules: {
      'no-restricted-imports': ['error', forbid(['widgets', 'pages', 'lab'], 'The framework imports no widget.')],
    },
  },
  {
    // user-written terms (issue 13): the slots, checks and GPU evaluation know the math and the GPU layer only
    files: ['src/core/custom/**/*.js'],
    rules: {
      'no-restricted-imports': [
        'error',
        forbid(
          ['framework', 'ui', 'widgets', 'pages', 'lab', 'exercises', 'tour', 'embedding'],
          'src/core/custom imports src/math and src/core/gpu only.',
        ),
      ],
    },
  },
  {
    // the test hooks have one owner; the rest of the app calls its functions
    files: ['src/**/*.js'],
    ignores: ['src/core/framework/debug-hooks.js'],
    rules: {
      'no-restricted-properties': [
        'error',
        { object: 'globalThis', property: '__shadingLab', message: 'Use src/core/framework/debug-hooks.js.' },
        { object: 'window', property: '__shadingLab', message: 'Use src/core/framework/debug-hooks.js.' },
      ],
    },
  },
  {
    files: ['src/widgets/**/*.js'],
    rules: { 'no-restricted-imports': ['error', forbid(['pages'], 'A widget imports no page.')] },
  },
];
