// The material lab's views besides its canvas (src/lab/lab-view.js draws the images and captions).

/**
 * The readout under the images (the approximation's cost and error, the centre's radiance), read out politely when it
 * changes, and a button for each of `buttons` ({ text, className, onClick }): the lab's starting points.
 */
export function createReadout(buttons) {
  const element = Object.assign(document.createElement('div'), { className: 'lab-readout' });
  const figures = document.createElement('div');
  figures.setAttribute('aria-live', 'polite');
  element.append(figures);
  for (const { text, className, onClick } of buttons) {
    const button = Object.assign(document.createElement('button'), { type: 'button', textContent: text, className });
    button.addEventListener('click', onClick);
    element.append(button);
  }
  return {
    element,
    show(html) {
      figures.innerHTML = html;
    },
  };
}
