// A measured BRDF as the material lab's material: a MERL file read in the fit worker (never on the page's
// thread), its table as a 3-D texture (measured.glsl), and a GGX fit whose lobe steers the lab's samples.
// Until the fit is in, the lab samples with the state's α (any lobe gives the same answer, only noisier).
import { createFitClient } from '../measured-brdf/fit-client.js';
import { tableTexture } from '../measured-brdf/spheres.js';

/** onChange(): a table or its fit arrived; onError(message): a file was refused (the last table stays). */
export function createMeasuredMaterial({ onChange, onError }) {
  let current = null; // { name, key, texture, fit }
  let client = null;
  let loads = 0;

  const fitGgx = (c, entry) =>
    c.fit(['ggx'], {}, (msg) => {
      if (msg.type !== 'fitted' || current !== entry) return;
      entry.fit = msg.result;
      onChange();
    });

  return {
    get current() {
      return current;
    },
    /** Reads `buffer` (a MERL file named `name`) in a new worker; only if it parses does it replace the table. */
    load(name, buffer) {
      const next = createFitClient();
      const ticket = ++loads;
      next
        .parse(buffer)
        .then((result) => {
          if (ticket !== loads) return next.dispose();
          client?.dispose();
          current?.texture.dispose();
          client = next;
          current = { name, key: `${name}:${ticket}`, texture: tableTexture(result.half), fit: null };
          onChange();
          return fitGgx(next, current);
        })
        .catch((e) => {
          if (client !== next) next.dispose();
          onError(`${name}: ${e.message} Kept the material shown before.`);
        });
    },
    /** The GPU copy went with the context: upload it again on the next draw. */
    reupload() {
      if (current) current.texture.needsUpdate = true;
    },
    dispose() {
      loads++;
      client?.dispose();
      current?.texture.dispose();
    },
  };
}
