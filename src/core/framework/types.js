// @ts-check
// The widget contract, in one place: what a widget module exports, what its `create` is given and what it
// returns, and the kinds of field its state schema is made of. Types only (JSDoc, checked by `npm run
// typecheck`); the shell (widget-shell.js), the host (widget-host.js) and state.js refer to them.

/**
 * @typedef {object} NumberField  a slider; the URL carries a plain decimal, clamped to min…max
 * @property {'number'} type
 * @property {number} min
 * @property {number} max
 * @property {number} [step]
 * @property {number} default
 */

/**
 * @typedef {object} EnumField  one of a list; the URL carries the option's key
 * @property {'enum'} type
 * @property {Record<string, string>} options  key → label
 * @property {Record<string, string>} [aliases]  old spelling → key: read as the key, silently (old links work)
 * @property {string} default
 */

/**
 * @typedef {object} SetField  any number of a list; the URL carries a comma list of keys
 * @property {'set'} type
 * @property {Record<string, string>} options  key → label
 * @property {Record<string, string>} [aliases]  old spelling → key
 * @property {string[]} default
 */

/**
 * @typedef {object} BoolField  a checkbox; the URL carries 1 or 0
 * @property {'bool'} type
 * @property {boolean} default
 */

/**
 * @typedef {object} ColorField  an sRGB colour '#rrggbb' (the URL may drop the '#')
 * @property {'color'} type
 * @property {string} default
 */

/**
 * @typedef {object} SamplesField  data handed over by another widget (no control): `length` plain decimals in
 *   min…max, or none (a list of any other length or with any bad item is refused whole)
 * @property {'samples'} type
 * @property {number} length
 * @property {number} min
 * @property {number} max
 * @property {number[]} default
 */

/**
 * @typedef {object} TextField  a name to show (no control): letters, digits, spaces and . _ - ( ) + , only
 * @property {'text'} type
 * @property {number} maxLength
 * @property {string} default
 */

/**
 * @typedef {object} FieldCommon  what every kind of field may carry
 * @property {string} [label]  the control's name and the name in notices (else the key)
 * @property {string} [group]  the control goes in a folder of this name
 * @property {boolean} [closed]  on a group's first field: its folder starts closed (a long panel stays short)
 * @property {string} [hint]  the control's tooltip
 * @property {string} [unit]  shown after the label (a number's unit)
 * @property {string[]} [formerly]  the field's old names: read as this field (old links work), never written
 */

/** @typedef {NumberField | EnumField | SetField | BoolField | ColorField | SamplesField | TextField} FieldKind */

/** @typedef {FieldKind & FieldCommon} Field  one key of the state */

/** @typedef {Record<string, Field>} Schema  a widget's whole state, key by key */

/** @typedef {string | number | boolean | (string | number)[]} StateValue  a set's keys or a samples list */

/** @typedef {Record<string, StateValue>} State  a plain object, one value per schema key */

/**
 * @typedef {object} WidgetOptions  the third argument of `create`
 * @property {string[]} [locked]  keys shown but not editable (an exercise fixes them): their controls are
 *   disabled and update() leaves them alone; the widget hands them to createWidgetShell
 * @property {(state: State) => void} [onStateChange]  called after every change that took, from the GUI, the
 *   URL or update(); the host uses it to write the URL and to tell an embedding page
 * @property {(materialKey: string, target: string) => boolean} [onPick]  f0-tables only: a material picked for
 *   widget `target`; true when the page loaded it in place (the link is then not followed)
 */

/**
 * @typedef {object} Progress  how far a progressive view has come (it refines over frames or worker results)
 * @property {number} frame  frames (or results) done
 * @property {number} target  frames (or results) at which it is finished
 */

/**
 * @typedef {object} Widget  what `create` returns; tests may call further getters a widget adds
 * @property {(partial: Partial<Record<string, unknown>>) => void} update  validates `partial` (as the URL does)
 *   and applies what changed
 * @property {() => State} getState
 * @property {() => void} dispose  frees its canvases, GPU resources, GUI and listeners, and removes its element
 * @property {() => Progress} [getProgress]  only for views that converge: the tests wait for frame ≥ target
 */

/**
 * @callback CreateWidget
 * @param {HTMLElement} container  where the widget appends its root element
 * @param {Partial<Record<string, unknown>>} [initialState]  as a URL or a caller gives it: coerced, never thrown
 * @param {WidgetOptions} [options]
 * @returns {Widget}
 */

/**
 * @typedef {object} WidgetContract  what a widget module exports as `widget`
 * @property {string} name  its name in URLs (embed.html?w=NAME)
 * @property {Schema} schema  pure data: loads in Node without three.js
 * @property {CreateWidget} create
 * @property {string[]} [terms]  the math functions it uses, linked to the parity page
 */

/**
 * @typedef {object} WidgetEntry  one widget of the registry (src/widgets/registry.js)
 * @property {string} title
 * @property {string} summary
 * @property {() => Promise<{ widget: WidgetContract }>} load  the widget's module, loaded when first opened
 */

/** @typedef {Record<string, WidgetEntry>} WidgetRegistry */

export {};
