// The lecturers' modules without a browser: the element's iframe URL, the plugin's slide markup, and the
// element speaking the same protocol as embed.html.
import { describe, expect, it } from 'vitest';
import { MESSAGE_PREFIX, parseMessage } from '../../src/core/framework/embed-protocol.js';
import { PREFIX, frameUrl } from '../../src/embedding/shading-lab-widget.js';
import { isPresenter, parseWidgetSpec } from '../../src/embedding/reveal-plugin.js';

describe('<shading-lab-widget> iframe URL', () => {
  it('uses the protocol of src/core/framework/embed-protocol.js', () => {
    expect(PREFIX).toBe(MESSAGE_PREFIX);
    expect(parseMessage({ type: `${PREFIX}snapshot`, id: 'el-1' })).toEqual({ kind: 'snapshot', id: 'el-1' });
  });

  it('names the widget, carries the state and allows the embedding page’s origin (not its own)', () => {
    const url = frameUrl(
      'https://lab.example.org/course/embed.html',
      'fresnel-zones',
      'mode=zones-lh&lightTheta=120',
      'https://slides.example.com',
    );
    expect(url.origin + url.pathname).toBe('https://lab.example.org/course/embed.html');
    expect(Object.fromEntries(url.searchParams)).toEqual({
      w: 'fresnel-zones',
      mode: 'zones-lh',
      lightTheta: '120',
      origins: 'https://slides.example.com',
    });
    const same = frameUrl(
      'embed.html',
      'ndf-explorer',
      null,
      'https://lab.example.org',
      'https://lab.example.org/course/deck.html',
    );
    expect(same.href).toBe('https://lab.example.org/course/embed.html?w=ndf-explorer');
    // a file:// page
    expect(frameUrl('https://lab.example.org/embed.html', 'media', '', 'null').searchParams.has('origins')).toBe(false);
  });

  it('asks for the presenter view (presenter=1) only when told to', () => {
    const of = (presenter) =>
      frameUrl('https://lab.example.org/embed.html', 'media', '', 'https://lab.example.org', undefined, presenter);
    expect(of(true).searchParams.get('presenter')).toBe('1');
    expect(of(false).searchParams.has('presenter')).toBe(false);
  });
});

describe('reveal plugin markup', () => {
  it('data-shading-lab="name?query" splits at the first ?', () => {
    expect(parseWidgetSpec('fresnel-zones?mode=zones-lh&lightTheta=120')).toEqual({
      name: 'fresnel-zones',
      query: 'mode=zones-lh&lightTheta=120',
    });
    expect(parseWidgetSpec(' ndf-explorer ')).toEqual({ name: 'ndf-explorer', query: '' });
    expect(parseWidgetSpec('media?a=1?b')).toEqual({ name: 'media', query: 'a=1?b' });
  });
});

describe('reveal plugin: the presenter view', () => {
  const section = (dataset) => ({ dataset });
  it('follows the deck’s presenter option unless the slide says otherwise (data-shading-lab-presenter)', () => {
    expect(isPresenter(section({}), false)).toBe(false);
    expect(isPresenter(section({}), true)).toBe(true);
    expect(isPresenter(section({ shadingLabPresenter: '' }), false)).toBe(true);
    expect(isPresenter(section({ shadingLabPresenter: 'false' }), true)).toBe(false);
  });
});
