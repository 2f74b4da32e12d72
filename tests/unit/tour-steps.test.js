// The tour's step data: ids fit a URL, steps follow the talk's order, every widget exists, and steps for
// widgets not built yet are left out with their section shown as coming.
import { describe, expect, it } from 'vitest';
import { TOUR_SECTIONS, TOUR_STEPS, tourPlan } from '../../src/tour/steps.js';
import { CHAPTERS } from '../../src/pages/chapters.js';
import { isWidgetName } from '../../src/widgets/registry.js';
import { SERIES_COLORS, SERIES_DASHES, seriesStyle } from '../../src/core/ui/palettes.js';

describe('tour steps', () => {
  it('have unique ids that can stand in a URL fragment as they are', () => {
    const ids = TOUR_STEPS.map((s) => s.id);
    expect(new Set(ids).size).toBe(ids.length);
    for (const id of ids) expect(id).toMatch(/^[a-z0-9]+(-[a-z0-9]+)*$/);
  });

  it('follow the talk: sections in order, each step with a title, text and a state object', () => {
    const order = TOUR_SECTIONS.map((s) => s.key);
    const at = TOUR_STEPS.map((s) => order.indexOf(s.section));
    expect(at.every((i) => i >= 0)).toBe(true);
    expect(at).toEqual([...at].sort((a, b) => a - b));
    for (const s of TOUR_STEPS) {
      expect(s.title.length).toBeGreaterThan(3);
      expect(s.text.length).toBeGreaterThan(60);
      expect(typeof s.state).toBe('object');
    }
    expect(order).toEqual(CHAPTERS.filter((c) => c.key !== 'performance').map((c) => c.key));
  });

  it('cover every chapter that has widgets, with registered widgets only, 25 to 50 steps', () => {
    const { steps, sections } = tourPlan(isWidgetName);
    expect(steps).toEqual(TOUR_STEPS); // nothing left out today
    expect(steps.length).toBeGreaterThanOrEqual(25);
    expect(steps.length).toBeLessThanOrEqual(50);
    for (const ch of CHAPTERS.filter((c) => c.widgets && c.key !== 'performance')) {
      expect(sections.find((s) => s.key === ch.key).count, ch.key).toBeGreaterThan(0);
      for (const w of ch.widgets)
        expect(
          steps.some((s) => s.widget === w),
          w,
        ).toBe(true);
    }
  });

  it('leave out a step whose widget is not built yet, and show its section as coming until it is', () => {
    const sections = [...TOUR_SECTIONS, { key: 'next', title: 'A chapter still being written' }];
    const later = { id: 'next-idea', section: 'next', widget: 'future-widget', title: 'Later', state: {}, text: '' };
    const today = tourPlan(isWidgetName, [...TOUR_STEPS, later], sections);
    expect(today.steps.map((s) => s.id)).not.toContain('next-idea');
    expect(today.sections.find((s) => s.key === 'next')).toMatchObject({ count: 0, first: -1 });
    const built = tourPlan((name) => isWidgetName(name) || name === 'future-widget', [...TOUR_STEPS, later], sections);
    expect(built.steps.at(-1).id).toBe('next-idea');
    expect(built.sections.find((s) => s.key === 'next')).toMatchObject({ count: 1, first: TOUR_STEPS.length });
  });
});

describe('series styles', () => {
  it('tell the first 35 series apart by colour or line pattern', () => {
    const keys = Array.from({ length: SERIES_COLORS.length * SERIES_DASHES.length }, (_, i) =>
      JSON.stringify(seriesStyle(i)),
    );
    expect(new Set(keys).size).toBe(35);
  });
});
