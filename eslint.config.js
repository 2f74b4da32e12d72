// ESLint (flat config): the recommended rules, the house's line and function lengths, and the rooms of the app
// (docs/architecture.md, "Rooms" and "Boundaries"): each room imports only the rooms below it, listed in ROOMS;
// only debug-hooks.js touches the test hooks (globalThis.__shadingLab). tests/unit/rooms-lint.test.js lints an
// import of every room from every room and checks the result against the table in docs/architecture.md.
import js from '@eslint/js';
import globals from 'globals';

// Every room of src/ by the folder name an import path goes through, and what sits outside src/.
const SRC = ['math', 'gpu', 'custom', 'framework', 'ui', 'measured', 'lab', 'widgets', 'exercises', 'tour', 'pages'];
const OUTSIDE = ['bench', 'tests', 'scripts'];
// What each room may import, from the bottom up; everything else of the app is refused. The core's rooms are
// src/core/<name>; the others src/<name>.
// the math and the shared core
const SHARED = ['math', 'gpu', 'custom', 'framework', 'ui'];
export const ROOMS = [
  { room: 'math', files: 'src/math', may: [] },
  { room: 'gpu', files: 'src/core/gpu', may: ['math'] },
  { room: 'custom', files: 'src/core/custom', may: ['math', 'gpu'] },
  { room: 'framework', files: 'src/core/framework', may: ['math', 'gpu', 'custom'] },
  { room: 'ui', files: 'src/core/ui', may: ['math', 'gpu', 'custom', 'framework'] },
  { room: 'measured', files: 'src/measured', may: ['math'] },
  { room: 'lab', files: 'src/lab', may: SHARED },
  { room: 'widgets', files: 'src/widgets', may: [...SHARED, 'measured', 'lab'] },
  { room: 'exercises', files: 'src/exercises', may: [...SHARED, 'measured', 'lab', 'widgets'] },
  { room: 'tour', files: 'src/tour', may: [...SHARED, 'measured', 'lab', 'widgets'] },
  { room: 'pages', files: 'src/pages', may: SRC.filter((r) => r !== 'pages') },
  { room: 'embedding', files: 'src/embedding', may: [] },
];
// An import path that goes through a refused room's folder: '../framework/notice.js', '../../core/ui/plot.js'.
const refuse = ({ room, may }) => ({
  patterns: [
    {
      regex: `(^|/)(${[...SRC, 'embedding', ...OUTSIDE].filter((r) => r !== room && !may.includes(r)).join('|')})/`,
      message: `${room} may import ${may.length ? may.join(', ') : 'nothing of the app'} (docs/architecture.md).`,
    },
  ],
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
    // src/math runs in Node, in workers and in tests as it is: no library of the page either
    files: ['src/math/**/*.js'],
    rules: {
      'no-restricted-imports': [
        'error',
        {
          paths: ['three', 'lil-gui', 'uplot', 'katex'].map((name) => ({ name, message: 'src/math is pure math.' })),
          ...refuse(ROOMS[0]),
        },
      ],
    },
  },
  ...ROOMS.slice(1).map((r) => ({
    files: [`${r.files}/**/*.js`],
    rules: { 'no-restricted-imports': ['error', refuse(r)] },
  })),
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
];
