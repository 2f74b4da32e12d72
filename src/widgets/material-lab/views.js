// The material lab's views besides its canvas (src/lab/lab-view.js draws the images and captions).

/**
 * The readout under the images (the approximation's cost and error, the centre's radiance), read out politely when it
 * changes, and a button named `buttonText` that calls `onButton()`.
 */
export function createReadout(buttonText, onButton) {
  const element = Object.assign(document.createElement('div'), { className: 'lab-readout' });
  const figures = document.createElement('div');
  figures.setAttribute('aria-live', 'polite');
  const button = Object.assign(document.createElement('button'), { type: 'button', textContent: buttonText });
  button.className = 'lab-head-on';
  button.addEventListener('click', onButton);
  element.append(figures, button);
  return {
    element,
    show(html) {
      figures.innerHTML = html;
    },
  };
}
