// onFileDrop on stand-ins for a zone and a file input (Node's EventTarget; the browser tests drop real files on
// the measured-BRDF zone, the material lab and the exercises page).
import { describe, expect, it } from 'vitest';
import { onFileDrop } from '../../src/core/ui/file-drop.js';

const zoneElement = () => {
  const classes = new Set();
  const classList = { add: (c) => classes.add(c), remove: (c) => classes.delete(c), has: (c) => classes.has(c) };
  return Object.assign(new EventTarget(), { classList, classes });
};
const drag = (type, { types = [], files = [] } = {}) =>
  Object.assign(new Event(type, { cancelable: true }), { dataTransfer: { types, files } });
const setUp = (options = {}) => {
  const zone = zoneElement();
  const taken = [];
  const stop = onFileDrop(zone, (file) => taken.push(file), options);
  return { zone, taken, stop };
};

describe('onFileDrop', () => {
  it('lights the zone for a drag of files and takes the first file dropped, cancelling the browser’s own drop', () => {
    const { zone, taken } = setUp();
    const over = drag('dragover', { types: ['Files'] });
    zone.dispatchEvent(over);
    expect(over.defaultPrevented).toBe(true);
    expect(zone.classList.has('dragging')).toBe(true);
    const drop = drag('drop', { types: ['Files'], files: ['a.binary', 'b.binary'] });
    zone.dispatchEvent(drop);
    expect(drop.defaultPrevented).toBe(true);
    expect(zone.classList.has('dragging')).toBe(false);
    expect(taken).toEqual(['a.binary']);
  });

  it('leaves a drag without files (text, a link) to the browser: no highlight, nothing taken', () => {
    const { zone, taken } = setUp({ highlight: 'drop-target' });
    const over = drag('dragover', { types: ['text/plain'] });
    zone.dispatchEvent(over);
    const drop = drag('drop', { types: ['text/plain'] });
    zone.dispatchEvent(drop);
    expect([over.defaultPrevented, drop.defaultPrevented, zone.classes.size, taken.length]).toEqual([
      false,
      false,
      0,
      0,
    ]);
  });

  it('takes a file chosen in the input, ignores an emptied choice, and stops listening once disposed', () => {
    const input = Object.assign(new EventTarget(), { files: ['x.json'] });
    const { zone, taken, stop } = setUp({ input });
    input.dispatchEvent(new Event('change'));
    input.files = [];
    input.dispatchEvent(new Event('change'));
    expect(taken).toEqual(['x.json']);
    stop();
    input.files = ['y.json'];
    input.dispatchEvent(new Event('change'));
    zone.dispatchEvent(drag('drop', { types: ['Files'], files: ['z.json'] }));
    expect(taken).toEqual(['x.json']);
  });
});
