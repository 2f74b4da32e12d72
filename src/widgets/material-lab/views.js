// The material lab's views besides its canvas (src/lab/lab-view.js draws the images and captions).

/** The readout under the images (the approximation's cost and error), read out politely when it changes. */
export function createReadout() {
  const element = Object.assign(document.createElement('div'), { className: 'lab-readout' });
  element.setAttribute('aria-live', 'polite');
  return {
    element,
    show(html) {
      element.innerHTML = html;
    },
  };
}
