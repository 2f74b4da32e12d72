// createFullscreenPass().render: the target and layer it draws into, as three.js's
// WebGLRenderer.setRenderTarget(target, activeCubeFace = layer of an array target) takes them, and the previous
// target put back afterwards.
import { describe, expect, it } from 'vitest';
import { createFullscreenPass } from '../../src/core/gpu/fullscreen-pass.js';

const recordingRenderer = (previous) => {
  const calls = [];
  return {
    calls,
    getRenderTarget: () => previous,
    setRenderTarget: (...args) => calls.push(['setRenderTarget', ...args]),
    render: (scene) => calls.push(['render', scene.children[0].material]),
  };
};

describe('createFullscreenPass().render', () => {
  it('draws into the layer it is given, then restores the previous target', () => {
    const renderer = recordingRenderer('previous');
    const material = { name: 'filter' };
    createFullscreenPass().render(renderer, material, 'array target', 3);
    expect(renderer.calls).toEqual([
      ['setRenderTarget', 'array target', 3],
      ['render', material],
      ['setRenderTarget', 'previous'],
    ]);
  });
  it('without a target or layer: the canvas, layer 0', () => {
    const renderer = recordingRenderer(null);
    createFullscreenPass().render(renderer, {});
    expect(renderer.calls[0]).toEqual(['setRenderTarget', null, 0]);
  });
});
