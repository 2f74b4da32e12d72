// Every file in shaders/, by file name, as text (bundled at build time).
const files = import.meta.glob('../../../shaders/*.glsl', { query: '?raw', import: 'default', eager: true });

export const SHADER_CHUNKS = Object.fromEntries(
  Object.entries(files).map(([path, text]) => [path.slice(path.lastIndexOf('/') + 1), text]),
);
