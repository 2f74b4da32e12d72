// embed.html?w=NAME&...: one widget alone, no page chrome, filling its frame.
import '../styles.css';
import { mountWidget } from '../core/widget-host.js';
import { WIDGETS, isWidgetName } from '../widgets/registry.js';
import { showBlockingMessage } from '../core/notice.js';

const root = document.getElementById('embed');
const name = new URLSearchParams(location.search).get('w');
if (isWidgetName(name)) {
  document.title = `${WIDGETS[name].title} — Shading Lab`;
  mountWidget(root, name);
} else {
  const known = Object.keys(WIDGETS).join(', ');
  showBlockingMessage(root, name ? `There is no widget called “${name}”.` : 'No widget named.', `Use embed.html?w=NAME with one of: ${known}.`);
}
