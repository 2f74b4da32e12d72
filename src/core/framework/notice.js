// Visible, dismissible notices for bad input (URL values, files, missing WebGL2). Never thrown at the user.

/**
 * The event a widget's root sends (bubbling) when an update had values it could not take as they were: its
 * detail is the notices of that update's one coercion (widget-shell.js; locked keys are left out before it, so
 * never reported). The embed protocol passes them on to the parent.
 */
export const STATE_NOTICES = 'shading-lab:state-notices';

export function createNoticeArea(container) {
  const area = document.createElement('div');
  area.className = 'notices';
  area.setAttribute('role', 'status');
  area.setAttribute('aria-live', 'polite');
  container.prepend(area);
  return {
    show(messages, kind = 'warning') {
      for (const text of [].concat(messages)) {
        const item = document.createElement('div');
        item.className = `notice notice-${kind}`;
        const span = document.createElement('span');
        span.textContent = text;
        const close = document.createElement('button');
        close.type = 'button';
        close.className = 'notice-close';
        close.setAttribute('aria-label', 'Dismiss');
        close.textContent = '×';
        close.addEventListener('click', () => item.remove());
        item.append(span, close);
        area.append(item);
      }
    },
    clear() {
      area.replaceChildren();
    },
    element: area,
  };
}

/** A full-size message in place of a view that cannot run (e.g. no WebGL2). */
export function showBlockingMessage(container, title, text) {
  const box = document.createElement('div');
  box.className = 'blocking-message';
  box.setAttribute('role', 'alert');
  const h = document.createElement('strong');
  h.textContent = title;
  const p = document.createElement('p');
  p.textContent = text;
  box.append(h, p);
  container.append(box);
  return box;
}
