// Runs parseEnvironmentFile over the cases it is sent, in a worker thread, so that a loader stuck in a loop
// fails the test by its time limit instead of hanging the run. Posts [{ name, ok, width, height, mean, error }].
import { parentPort, workerData } from 'node:worker_threads';
import { parseEnvironmentFile } from '../../src/lab/environment-files.js';

const results = workerData.map(({ name, bytes }) => {
  try {
    const { data, width, height } = parseEnvironmentFile(
      name,
      bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength),
    );
    const mean = data.reduce((s, x, i) => (i % 4 === 3 ? s : s + x), 0) / (width * height * 3);
    return { name, ok: true, width, height, mean };
  } catch (e) {
    return { name, ok: false, error: e.message };
  }
});
parentPort.postMessage(results);
