// A WebGL2 context that takes part in the page's context budget (gl-budget.js): it can be given up while its
// view is out of sight and taken back when the view returns. The same context object lives on (lost, then
// restored), so three.js keeps its renderer and re-uploads what it needs; callers redraw from their state.
//
// States: live → releasing (we asked for the loss) → released (loss done; may be restored) → restoring → live.
// A loss we did not ask for (GPU reset) goes to 'lost' until the browser restores the context itself.
import { joinGlBudget } from './gl-budget.js';

// A view within half a screen of the visible area keeps (or takes back) its context, so that it has drawn by
// the time it scrolls in.
const NEAR_SIGHT = 0.5;

function nearSightNow(element) {
  const r = element.getBoundingClientRect();
  const margin = NEAR_SIGHT * innerHeight;
  return r.bottom > -margin && r.right > 0 && r.top < innerHeight + margin && r.left < innerWidth;
}

// The objects of a lost context die with it, but three.js still deletes them when their owner (a render
// target, a geometry) is disposed after the restore, and the browser warns "object does not belong to this
// context". So deletes of objects born before the last restore are skipped. Returns: call on each restore.
const GL_OBJECT_KINDS = [
  'Buffer',
  'Framebuffer',
  'Program',
  'Query',
  'Renderbuffer',
  'Sampler',
  'Shader',
  'Texture',
  'TransformFeedback',
  'VertexArray',
];

function skipStaleDeletes(gl) {
  const born = new WeakMap();
  let generation = 0;
  for (const kind of GL_OBJECT_KINDS) {
    const create = gl[`create${kind}`].bind(gl);
    const remove = gl[`delete${kind}`].bind(gl);
    gl[`create${kind}`] = (...args) => {
      const object = create(...args);
      if (object) born.set(object, generation);
      return object;
    };
    gl[`delete${kind}`] = (object) => {
      if (!object || born.get(object) === generation) remove(object);
    };
  }
  return () => generation++;
}

/**
 * The context of `canvas`, given up and taken back as the canvas moves out of and into sight.
 * hooks: onLost(planned) — the context is gone, GPU content with it; onRestored() — it is back (draw again);
 * onWaiting(waiting) — the view is in sight but no slot is free (more views in sight than the budget).
 * Returns null without WebGL2.
 */
export function createBudgetedContext(canvas, attributes, { onLost, onRestored, onWaiting }) {
  let state = 'live';
  const view = {
    canRelease: () => state === 'live',
    release() {
      state = 'releasing';
      view.holds = false;
      ext.loseContext();
    },
    grant() {
      state = 'restoring';
      slot.held();
      onWaiting(false);
      ext.restoreContext();
    },
  };
  const slot = joinGlBudget(view, nearSightNow(canvas));
  const gl = canvas.getContext('webgl2', attributes);
  if (!gl) {
    slot.freed();
    slot.leave();
    return null;
  }
  const ext = gl.getExtension('WEBGL_lose_context'); // kept: it cannot be fetched while the context is lost
  if (!ext) view.canRelease = () => false; // no way to give it up: it keeps its slot
  const newGeneration = skipStaleDeletes(gl);

  const ask = () => {
    slot.setVisible(view.visible, state === 'released');
    onWaiting(slot.waiting);
  };
  const lost = (e) => {
    e.preventDefault(); // allows the restore
    const planned = state === 'releasing';
    state = planned ? 'released' : 'lost';
    if (!planned) slot.freed();
    onLost(planned);
    if (planned && view.visible) ask(); // it came back into sight while we were giving it up
  };
  const restored = () => {
    newGeneration();
    if (state === 'lost') slot.held(); // the browser restored it by itself
    state = 'live';
    onRestored();
  };
  canvas.addEventListener('webglcontextlost', lost);
  canvas.addEventListener('webglcontextrestored', restored);
  const sight = new IntersectionObserver(
    (entries) => {
      view.visible = entries[entries.length - 1].isIntersecting;
      ask();
    },
    { rootMargin: `${NEAR_SIGHT * 100}% 0px` },
  );

  return {
    gl,
    /**
     * Call once the context's user (three.js) is set up: without a free slot, the context is given up now
     * (it counted in the browser for this moment only) and waits, out of sight or for a free slot.
     */
    start() {
      if (!slot.admitted) view.release();
      sight.observe(canvas);
    },
    /** Whether the context can draw now. */
    get live() {
      return state === 'live';
    },
    dispose() {
      sight.disconnect();
      canvas.removeEventListener('webglcontextlost', lost);
      canvas.removeEventListener('webglcontextrestored', restored);
      // give the context up now rather than when it is garbage-collected: the browser counts it until then
      if (ext && (state === 'live' || state === 'restoring')) ext.loseContext();
      view.holds = false;
      slot.leave();
    },
  };
}
