import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import {
  cancelFrame,
  cancelLater,
  countFrame,
  later,
  requestFrame,
  sampleTarget,
  mountedWidget,
  publish,
  registerWidget,
  unregisterWidget,
  whileLoading,
} from '../../src/core/framework/debug-hooks.js';

// read when this file's import of the module ran (before the afterEach below first cleared them)
const atBoot = structuredClone(globalThis.__shadingLab);

afterEach(() => {
  delete globalThis.__shadingLab;
});

describe('test hooks (globalThis.__shadingLab, the shape tests and benchmarks read)', () => {
  it('are there as soon as the module runs (a page with no widget has them at boot), with nothing pending', () => {
    expect(atBoot).toEqual({ frames: 0, pending: 0, loading: 0, widgets: {} });
  });
  it('are made on first use with frames and widgets, and hold what the app reports', () => {
    const widget = { getState: () => ({}) };
    registerWidget('lobe', widget);
    countFrame();
    countFrame();
    publish('tour', { index: 2, id: 'ndf-ggx', ready: false });
    expect(globalThis.__shadingLab).toEqual({
      frames: 2,
      pending: 0,
      loading: 0,
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
  it('give progressive views their samples, or fewer where a test seeded a cap (maxSamples)', () => {
    expect(sampleTarget(512)).toBe(512);
    globalThis.__shadingLab = { maxSamples: 8 };
    expect([sampleTarget(512), sampleTarget(4)]).toEqual([8, 4]);
    globalThis.__shadingLab.maxSamples = 0; // not a cap
    expect(sampleTarget(512)).toBe(512);
  });
  it('name no prototype member as a mounted widget', () => {
    expect(mountedWidget('constructor')).toBeUndefined();
    expect(mountedWidget('__proto__')).toBeUndefined();
  });
});

describe('pending work (__shadingLab.pending, what tests/browser/helpers.js untilIdle waits out)', () => {
  // Node has no animation frames: one every 16 ms of a scripted clock stands in for the browser's
  beforeEach(() => {
    vi.useFakeTimers({ toFake: ['setTimeout', 'clearTimeout'] });
    vi.stubGlobal('requestAnimationFrame', (callback) => setTimeout(() => callback(0), 16));
    vi.stubGlobal('cancelAnimationFrame', (id) => clearTimeout(id));
  });
  afterEach(() => {
    vi.useRealTimers();
    vi.unstubAllGlobals();
  });
  const pending = () => globalThis.__shadingLab.pending;
  const nextFrame = () => vi.advanceTimersByTime(16);

  it('counts each frame asked for and each timed pause until its callback runs or it is cancelled', () => {
    const ran = [];
    requestFrame(() => ran.push('frame'));
    const dropped = requestFrame(() => ran.push('dropped frame'));
    later(() => ran.push('pause'), 250);
    const cancelled = later(() => ran.push('cancelled pause'), 100);
    expect(pending()).toBe(4);
    cancelFrame(dropped);
    cancelLater(cancelled);
    cancelLater(undefined); // nothing scheduled: nothing changes
    expect(pending()).toBe(2);
    nextFrame();
    expect([ran, pending()]).toEqual([['frame'], 1]);
    vi.advanceTimersByTime(250 - 16 - 1);
    expect(pending()).toBe(1);
    vi.advanceTimersByTime(1);
    expect([ran, pending()]).toEqual([['frame', 'pause'], 0]);
    vi.advanceTimersByTime(1000);
    expect(ran).toEqual(['frame', 'pause']);
  });

  it('is not idle while a callback asks for the next frame (a progressive view refining), idle once it stops', () => {
    let samples = 0;
    const refine = () => {
      samples++;
      if (samples < 3) requestFrame(refine);
    };
    requestFrame(refine);
    const seen = [];
    for (let i = 0; i < 4; i++) {
      nextFrame();
      seen.push(pending());
    }
    expect(samples).toBe(3);
    expect(seen).toEqual([1, 1, 0, 0]);
  });

  it('counts a load (a chunk, a mount) until it settles and the frame after it has run, failed or not', async () => {
    const loading = () => globalThis.__shadingLab.loading;
    let arrive;
    const chunk = whileLoading(new Promise((ok) => (arrive = ok)));
    const failing = whileLoading(Promise.reject(new Error('request aborted')));
    expect([pending(), loading()]).toEqual([2, 2]);
    await expect(failing).rejects.toThrow('request aborted'); // handed back as it was
    // let go, but its frame is asked for first: pending never touches 0 before that frame
    expect([pending(), loading()]).toEqual([2, 1]);
    arrive('module');
    expect(await chunk).toBe('module');
    expect([pending(), loading()]).toEqual([2, 0]);
    nextFrame();
    expect(pending()).toBe(0);
  });
});
