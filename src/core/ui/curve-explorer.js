// The arrangement ndf-explorer and visibility-explorer share: a widget shell whose view holds the plots, then the
// spheres, then the table; curves derived from the state, redrawn when a key they read changes; the spheres and
// their description redrawn on every change. The table (figures only) follows once a drag pauses: its numbers
// may cost more than a frame (ndf-explorer's integrals), and the spheres' frame should not wait for them.
import { createWidgetShell } from '../framework/widget-shell.js';
import { createSettledTask } from '../framework/render-loop.js';

/**
 * @param {HTMLElement} container
 * @param {object} options
 * @param {object} options.shell createWidgetShell's options
 * @param {string} options.title
 * @param {(state: object) => void} [options.onStateChange]
 * @param {string[]} options.curveKeys the state keys the curves read
 * @param {(state: object) => any[]} options.curvesOf
 * @param {{ plots: Function, spheres: Function, table: Function }} options.views their create functions
 * @param {(plots: any, curves: any[], state: object) => void} options.drawCurves the plots, when the curves change
 * @param {(plots: any, changed: string[], curves: any[], state: object) => void} [options.afterChange] more
 *   redrawing of the plots, after the curves' and before the spheres'
 * @param {(curves: any[], state: object) => string} options.describeSpheres
 */
export function createCurveExplorer(container, options) {
  const { title, onStateChange, curveKeys, curvesOf, views, drawCurves, afterChange, describeSpheres } = options;
  const shell = createWidgetShell(container, options.shell);
  const plotHolder = document.createElement('div');
  shell.view.append(plotHolder);
  let curves = curvesOf(shell.state);
  const plots = views.plots(plotHolder, curves, shell.state);
  const spheres = views.spheres(shell.view);
  const table = views.table(shell.view);
  const tableLater = createSettledTask(() => table.draw(curves));

  const drawSpheres = () => {
    spheres.draw(curves, shell.state);
    shell.describe(describeSpheres(curves, shell.state), spheres.canvas);
  };
  const onChanged = (changed) => {
    if (changed.some((k) => curveKeys.includes(k))) {
      curves = curvesOf(shell.state);
      drawCurves(plots, curves, shell.state);
      tableLater.schedule();
    }
    afterChange?.(plots, changed, curves, shell.state);
    drawSpheres();
  };
  table.draw(curves);
  drawSpheres();
  const update = shell.connect({ title, onChanged, onStateChange });

  return {
    shell,
    plots,
    spheres,
    update,
    /** The curves drawn now (they are replaced, not mutated, when the state changes). */
    curves: () => curves,
    /** Derives the curves again and redraws all, as a change of every curve key would (a user's term ran). */
    refresh: () => onChanged(curveKeys),
    dispose() {
      tableLater.cancel();
      plots.dispose();
      spheres.dispose();
      shell.dispose();
    },
  };
}
