// createSettledTask (core/framework/render-loop.js): figures computed once a drag pauses, against a scripted clock.
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { createSettledTask } from '../../src/core/framework/render-loop.js';

beforeEach(() => vi.useFakeTimers({ toFake: ['setTimeout', 'clearTimeout', 'performance'] }));
afterEach(() => vi.useRealTimers());

describe('createSettledTask', () => {
  it('runs once, quietMs after the last of a burst of changes', () => {
    const run = vi.fn();
    const task = createSettledTask(run, { quietMs: 100, maxWaitMs: 1000 });
    for (let i = 0; i < 5; i++) {
      task.schedule();
      vi.advanceTimersByTime(30);
    }
    expect(run).not.toHaveBeenCalled();
    vi.advanceTimersByTime(70); // 100 ms after the last change
    expect(run).toHaveBeenCalledTimes(1);
    vi.advanceTimersByTime(1000);
    expect(run).toHaveBeenCalledTimes(1);
  });
  it('runs at least every maxWaitMs during a drag that never pauses', () => {
    const run = vi.fn();
    const task = createSettledTask(run, { quietMs: 100, maxWaitMs: 300 });
    for (let i = 0; i < 20; i++) {
      task.schedule();
      vi.advanceTimersByTime(50);
    } // 1000 ms of changes every 50 ms
    expect(run).toHaveBeenCalledTimes(3);
  });
  it('flush() runs a pending task at once and only then; cancel() drops it', () => {
    const run = vi.fn();
    const task = createSettledTask(run);
    task.flush();
    expect(run).not.toHaveBeenCalled();
    task.schedule();
    task.flush();
    expect(run).toHaveBeenCalledTimes(1);
    vi.advanceTimersByTime(1000);
    expect(run).toHaveBeenCalledTimes(1);
    task.schedule();
    task.cancel();
    vi.advanceTimersByTime(1000);
    expect(run).toHaveBeenCalledTimes(1);
  });
});
