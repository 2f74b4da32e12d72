// embed.html?w=NAME&...: one widget alone, no page chrome, filling its frame. In an iframe it speaks the
// postMessage protocol of src/core/framework/embed-protocol.js with its parent, if the parent's origin is allowed
// (`origins=`, a comma list; the widget's own origin always is), and tells it the height of its content.
// `presenter=1`: the presenter view for slides, the widget's views only (no control panel), filling the frame.
// `locked=KEY,KEY`: settings the reader (and a parent's `set`) cannot change, as an exercise fixes them.
import '../styles.css';
import { mountOrExplain } from '../core/framework/widget-failure.js';
import { connectEmbedProtocol, parseAllowedOrigins } from '../core/framework/embed-protocol.js';
import { WIDGETS, isWidgetName } from '../widgets/registry.js';
import { createNoticeArea, showBlockingMessage } from '../core/framework/notice.js';
import { showValue } from '../core/framework/state.js';
import { snapshotWidget } from '../core/framework/snapshot.js';

const root = document.getElementById('embed');
document.getElementById('embed-fallback')?.remove(); // the app runs: the words for blocked scripts go
const params = new URLSearchParams(location.search);
const name = params.get('w');
const presenter = params.get('presenter') === '1';
const framed = window.parent !== window;
document.body.classList.toggle('presenter', presenter);
document.body.classList.toggle('in-frame', framed);
if (isWidgetName(name)) {
  document.title = `${WIDGETS[name].title} — Shading Lab`;
  const notices = createNoticeArea(root);
  const { origins, notices: originProblems } = parseAllowedOrigins(params.get('origins'), location.origin);
  if (originProblems.length) notices.show(originProblems);
  let link = null;
  // the protocol starts once the widget is up, at the first try or a retry (a failure says so in the frame)
  const connect = (instance, widget) => {
    if (!framed) return;
    const capture = () => snapshotWidget(root.querySelector('.widget'));
    // the presenter view fills whatever frame it is given: no height of its own to report
    const content = presenter ? null : root;
    const { schema } = widget;
    link = connectEmbedProtocol({ name, schema, instance, widgetRoot: root, origins, notices, capture, content });
    link.ready();
  };
  const locked = (params.get('locked') ?? '').split(',').filter(Boolean);
  const onStateChange = () => link?.userChanged();
  await mountOrExplain(root, name, { widgets: WIDGETS, onStateChange, locked }, connect);
} else {
  const known = Object.keys(WIDGETS).join(', ');
  const what = name ? `There is no widget called ${showValue(name)}.` : 'No widget named.';
  showBlockingMessage(root, what, `Use embed.html?w=NAME with one of: ${known}.`);
}
