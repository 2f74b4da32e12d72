// The page's side of the fit worker: each request is a promise, progress comes through a callback, and a
// worker error rejects with the worker's message (e.g. what is wrong with a file).
export function createFitClient() {
  const worker = new Worker(new URL('../../measured/fit-worker.js', import.meta.url), { type: 'module' });
  const pending = new Map();
  let next = 0;
  worker.onmessage = ({ data }) => {
    const job = pending.get(data.id);
    if (!job) return;
    if (data.type === 'error') {
      pending.delete(data.id);
      job.reject(new Error(data.message));
    } else if (data.type === 'done') {
      pending.delete(data.id);
      job.resolve(job.result);
    } else if (data.type === 'progress' || data.type === 'fitted') {
      job.onMessage?.(data);
    } else {
      job.result = data;
    }
  };
  const request = (message, transfer = [], onMessage = null) =>
    new Promise((resolve, reject) => {
      const id = ++next;
      pending.set(id, { resolve, reject, onMessage, result: null });
      worker.postMessage({ ...message, id }, transfer);
    });
  return {
    parse: (buffer) => request({ type: 'parse', buffer }, [buffer]),
    synthesize: (model, params) => request({ type: 'synthesize', model, params }),
    fit: (models, options, onMessage) => request({ type: 'fit', models, options }, [], onMessage),
    tabulate: (model, params) => request({ type: 'tabulate', model, params }),
    dispose: () => worker.terminate(),
  };
}
