import { afterEach, describe, expect, it } from 'vitest';
import {
  countFrame,
  mountedWidget,
  publish,
  registerWidget,
  unregisterWidget,
} from '../../src/core/framework/debug-hooks.js';

afterEach(() => {
  delete globalThis.__shadingLab;
});

describe('test hooks (globalThis.__shadingLab, the shape tests and benchmarks read)', () => {
  it('are made on first use with frames and widgets, and hold what the app reports', () => {
    const widget = { getState: () => ({}) };
    registerWidget('lobe', widget);
    countFrame();
    countFrame();
    publish('tour', { index: 2, id: 'ndf-ggx', ready: false });
    expect(globalThis.__shadingLab).toEqual({
      frames: 2,
      widgets: { lobe: widget },
      tour: { index: 2, id: 'ndf-ggx', ready: false },
    });
    expect(mountedWidget('lobe')).toBe(widget);
    unregisterWidget('lobe');
    expect(mountedWidget('lobe')).toBeUndefined();
  });
  it('keep an object seeded before the page loads, counting frames through its setter (bench/pages.js)', () => {
    const seen = [];
    let frames = 0;
    const seeded = {};
    Object.defineProperty(seeded, 'frames', {
      get: () => frames,
      set(v) {
        frames = v;
        seen.push(v);
      },
    });
    globalThis.__shadingLab = seeded;
    countFrame();
    registerWidget('zones', {});
    countFrame();
    expect(globalThis.__shadingLab).toBe(seeded);
    expect(seen).toEqual([1, 2]);
  });
  it('name no prototype member as a mounted widget', () => {
    expect(mountedWidget('constructor')).toBeUndefined();
    expect(mountedWidget('__proto__')).toBeUndefined();
  });
});
