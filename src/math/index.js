// The public math API: pure float64 JavaScript, the reference every GLSL chunk is tested against.
export * from './color.js';
export * from './fresnel.js';
export * from './ndf.js';
export * from './visibility.js';
export * from './materials.js';
export * from './optical-constants.js';
export * from './zones.js';
export * from './special.js';
export * from './brdf.js';
export * from './integrate.js';
export * from './ndf-width.js';
export * from './half-diff.js';
export * from './diffuse.js';
export * from './media.js';
export * from './microsurface.js';
export * from './lighting.js';
export * from './radiometry.js';
