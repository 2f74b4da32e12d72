// The guided tour as plain data: one step per idea of the talk, in its order. A step names the widget that
// shows the idea and the state that sets it up (only the keys that matter: the rest take the widget's
// defaults, so a step looks the same however the reader arrived). Its id is its URL: tour.html#<id>. A step
// whose words are about a view further down its widget names it in `look` (a selector within the widget): the
// tour scrolls it into sight under the step's words.
//
// To extend the tour, append steps; nothing else changes. A step whose widget is not registered yet is left
// out, and a section without steps is shown as "coming".
import { CHAPTERS } from '../widgets/chapters.js';

/** The talk's sections the tour walks through, in order (the performance chapter is not part of the talk). */
export const TOUR_SECTIONS = CHAPTERS.filter((c) => c.key !== 'performance').map(({ key, title }) => ({ key, title }));

export const TOUR_STEPS = [
  // 1. Light in media
  {
    id: 'media-straight-line',
    section: 'media',
    widget: 'media',
    title: 'Light in a clear medium',
    state: { medium: 'water', distance: 0 },
    text:
      'Where a medium is the same everywhere, light travels in straight lines. The glass here, the square inside ' +
      'a border of bare wall, holds a metre of clean water: the chequered wall shows through it sharp and ' +
      'undistorted, only tinted a little blue-green, since a metre of water lets 73% of red light through, 96% of ' +
      'green and 97% of blue. Five centimetres would leave the glass invisible: 98% of red gets across.',
  },
  {
    id: 'media-water-depth',
    section: 'media',
    widget: 'media',
    title: 'Absorption depends on distance',
    state: { medium: 'water', distance: 1.5 },
    text:
      'Water does absorb a little red. Over centimetres that is invisible, but Beer–Lambert makes the loss ' +
      'exponential in depth: after about thirty metres almost no red is left and the light is blue-green. ' +
      'The plot below follows each channel from a millimetre to a hundred metres.',
  },
  {
    id: 'media-red-absorber',
    section: 'media',
    widget: 'media',
    title: 'Absorption changes colour',
    state: { medium: 'red', distance: -1.3 },
    text:
      'A stronger absorber that takes far more blue and green than red (an illustrative one, wine-like) tints ' +
      'light within a centimetre: 1 cm leaves 97% of red, 55% of green and 41% of blue; the 5 cm shown leave 86%, ' +
      '5% and 1%. Absorption changes how much light there is and what colour it has, never its direction.',
  },
  {
    id: 'media-scattering',
    section: 'media',
    widget: 'media',
    title: 'Scattering makes a medium cloudy',
    state: { medium: 'cloudy', distance: -1.3 },
    text:
      'Particles whose index of refraction differs from their surroundings turn light aside. A few of them ' +
      'blur the wall behind the glass; the light is not lost, it leaves in other directions.',
  },
  {
    id: 'media-grid',
    section: 'media',
    widget: 'media',
    title: 'Absorption and scattering together',
    state: { view: 'grid', samples: '64' },
    text:
      'The talk’s grid of glasses: absorption grows upwards, scattering to the right. Strong scattering with ' +
      'little absorption (bottom right) sends light back out in every direction: the medium looks white and ' +
      'opaque, like milk.',
  },

  // 2. Surfaces and microgeometry
  {
    id: 'surfaces-flat',
    section: 'surfaces',
    widget: 'surfaces',
    title: 'An optically flat surface',
    state: { material: 'glass-high', theta: 40, alpha: 0.02 },
    text:
      'A surface is a sudden change of refractive index. When its bumps are smaller than a wavelength it is ' +
      'optically flat and splits light into exactly two directions, reflected and refracted; the Fresnel ' +
      'equations give the split (here 8.7% and 91.3%, drawn at the top). The plot under that picture is set to ' +
      'the smoothest microsurface the widget has, α = 0.02, nearly flat: the reflected light leaves in one narrow ' +
      'spike at the mirror direction, −40°.',
  },
  {
    id: 'surfaces-metal',
    section: 'surfaces',
    widget: 'surfaces',
    title: 'Metals and non-metals',
    state: { material: 'copper', theta: 40 },
    text:
      'What happens to the refracted light depends on the material. A metal absorbs it within nanometres, so ' +
      'all we see is the reflection; a non-metal (switch the material back to glass) scatters it inside, and some ' +
      'comes back out elsewhere.',
  },
  {
    id: 'surfaces-rough',
    section: 'surfaces',
    widget: 'surfaces',
    title: 'Rougher means blurrier',
    state: { material: 'glass-high', theta: 30, alpha: 0.5 },
    text:
      'Most surfaces have microgeometry: facets too small to see but larger than a wavelength. Each one is a ' +
      'mirror, but they face different ways, so the reflection spreads into a cone, and the ray-traced histogram ' +
      'follows the microfacet prediction. The spheres below show the result: rougher, blurrier reflections.',
  },
  {
    id: 'subsurface-local',
    section: 'surfaces',
    widget: 'subsurface-scale',
    title: 'When diffuse is local',
    state: { pixel: 4 },
    text:
      'Light refracted into a non-metal wanders and re-emerges some distance from where it entered. If a pixel’s ' +
      'footprint on the surface is much wider than that distance, we may pretend it comes out where it went in: ' +
      'shading stays local, and this re-emerging light is the diffuse term.',
  },
  {
    id: 'subsurface-needed',
    section: 'surfaces',
    widget: 'subsurface-scale',
    title: 'When subsurface scattering is needed',
    state: { pixel: 0.3 },
    text:
      'Shrink the shading sample below the typical exit distance (a close-up of skin, say) and most of the ' +
      'light leaves outside it. The physics is the same as diffuse; only the scale has changed, and now ' +
      'subsurface scattering has to be rendered.',
  },

  // 3. The BRDF and the reflectance equation
  {
    id: 'brdf-radiance',
    section: 'brdf',
    widget: 'radiance',
    title: 'Light as a number: radiance',
    state: { distance: 4, lampRadius: 0.05, light: 'daylight', surface: 'grey' },
    text:
      'Shading measures light as radiance: power along a single ray, per area across it and per solid angle ' +
      'around it. Radiance does not fade with distance: the lamp, 4 m away here, is smaller than at 1 m but no ' +
      'dimmer. What fades is the irradiance a surface receives from the whole lamp, as $1/d^2$ (16 times less than ' +
      'at 1 m). Drag the distance and watch the two curves.',
  },
  {
    id: 'brdf-spectral',
    section: 'brdf',
    widget: 'radiance',
    title: 'Spectra become RGB',
    state: { distance: 1, light: 'sodium', surface: 'red' },
    text:
      'Light is a spectrum, but a renderer keeps three numbers and multiplies them channel by channel (the ⊗ ' +
      'of the reflectance equation). Under a sodium lamp, whose light sits almost all at 589 nm, that shortcut ' +
      'makes this red paint’s red channel 2.4 times too bright. Under the daylight-like white the two agree.',
  },
  {
    id: 'brdf-lobe',
    section: 'brdf',
    widget: 'brdf-lobe',
    title: 'The BRDF f(l, v)',
    state: { lightTheta: 30, viewTheta: 30, alpha: 0.2 },
    text:
      'With shading local, a surface point answers one question: of the light arriving from l, how much ' +
      'leaves towards v? That is the BRDF, defined only for l and v above the surface. Fix the light (here at ' +
      '30°, on a fairly smooth surface, α = 0.2) and sweep the view, and f traces a lobe around the mirror ' +
      'direction: 0.11 per steradian at its peak, at 31°, and 0.03 towards the horizon. Drag l or v on the ' +
      'polar plot.',
  },
  {
    id: 'brdf-intensity',
    section: 'brdf',
    widget: 'brdf-lobe',
    title: 'BRDF times the cosine',
    state: { lightTheta: 60, viewTheta: 60, cosine: true, alpha: 0.3 },
    text:
      'The BRDF is a density per steradian, and it can be large where little light goes. On this rougher ' +
      'surface (α = 0.3, light at 60°) f is largest at the horizon: 1.00 per steradian at θv = 89°, against 0.22 ' +
      'in the mirror direction (at α = 0.1 it would peak near the mirror direction). But seen from near the ' +
      'horizon the lit patch looks thin, so the light it sends per steradian towards v is f times the cosine of ' +
      'the view angle, n·v. That product is the lobe drawn here: it peaks near 70° and falls to nothing at the ' +
      'horizon. It is not the cosine of the reflectance equation, n·l, which weighs the light arriving from ' +
      'each direction l (the albedo plot adds that up).',
  },
  {
    id: 'brdf-factors',
    section: 'brdf',
    widget: 'brdf-lobe',
    title: 'Taking the BRDF apart',
    state: { lightTheta: 60, viewTheta: 60, useDenominator: false },
    text:
      'A microfacet BRDF is $\\frac{F\\,G\\,D}{4 \\nl\\nv}$. Here the denominator is switched off: the lobe stops ' +
      'growing at grazing angles. Turn factors off one at a time to see what each contributes.',
  },
  {
    id: 'brdf-compare',
    section: 'brdf',
    widget: 'brdf-lobe',
    title: 'Two BRDFs side by side',
    state: { compare: true, lightTheta: 30, viewTheta: 30 },
    text:
      'Overlay a second BRDF (dashed) at the same width: GGX against Beckmann. The images over the half and ' +
      'difference angles (θh, θd) show the same functions in the coordinates they really depend on.',
  },

  // 4. Microfacet theory
  {
    id: 'microfacets-half-vector',
    section: 'microfacets',
    widget: 'microfacets',
    title: 'The half vector',
    state: { lightTheta: 35, viewTheta: -15, alpha: 0.5, bounces: false },
    text:
      'Each microfacet is a perfect mirror, so it reflects l into v only if its normal m lies halfway between ' +
      'them: $\\mathbf{m} = \\mathbf{h}$. The marked facets are the only ones that send this light to the eye; ' +
      '$D(\\mathbf{h})$ counts how many there are.',
  },
  {
    id: 'microfacets-shadowing',
    section: 'microfacets',
    widget: 'microfacets',
    title: 'Shadowing and masking',
    state: { lightTheta: 75, viewTheta: -60, alpha: 0.6, bounces: false },
    text:
      'Not every facet facing along h contributes: some are hidden from the light (shadowed, solid black) ' +
      'and some from the eye (masked, hollow blue). Towards grazing angles more are lost; the plot compares the ' +
      'ray-traced share with Smith’s G1.',
  },
  {
    id: 'microfacets-bounces',
    section: 'microfacets',
    widget: 'microfacets',
    title: 'Light that bounces twice',
    state: { kind: 'ggx', alpha: 1, lightTheta: 60, viewTheta: -40, bounces: true },
    text:
      'Blocked light does not vanish: it bounces again (red) and some of it still reaches the eye. The ' +
      'microfacet BRDF drops it, so it assumes all blocked light is lost.',
  },
  {
    id: 'microfacets-furnace',
    section: 'microfacets',
    widget: 'energy',
    title: 'The energy that is lost',
    state: {},
    look: '.sphere-grid',
    text:
      'How much does dropping the second bounces cost? In a uniform white environment a surface that loses ' +
      'nothing would vanish. In the row of spheres below the plots the smoothest nearly does; rougher ones stay ' +
      'grey, and at α = 1 most of the light arriving head-on is lost (the table has the figures).',
  },
  {
    id: 'microfacets-furnace-fixed',
    section: 'microfacets',
    widget: 'energy',
    title: 'The lost energy, found',
    state: { compensation: 'kullaConty', metal: 'gold', metalAlpha: 0.8 },
    look: '.sphere-grid',
    text:
      'With an energy compensation switched on (here Kulla–Conty) the dropped light is put back, and the row of ' +
      'spheres below the plots looks empty: each sphere, at every roughness, is now as bright as the white around ' +
      'it (point at one: the probe’s compensated albedo reads 1.0000). It matters most on a metal (the plot and ' +
      'table under the spheres): rough gold (α = 0.8) seen head-on reflects 43% of red, 30% of green and 12% of ' +
      'blue light in one bounce; followed through every bounce (the random walk) it reflects 100%, 56% and 16%, ' +
      'brighter and more saturated (a channel that reflects more gets more of its lost light back). Kulla–Conty ' +
      'comes within 0.02 of the walk; Turquin overshoots green by 0.03.',
  },
  {
    id: 'microfacets-multiple-lobe',
    section: 'microfacets',
    widget: 'brdf-lobe',
    title: 'Putting the lost light back',
    state: { multiple: true, alpha: 1, F: 'one', lightTheta: 30, viewTheta: 20 },
    text:
      'The talk stops at the loss; renderers since Kulla & Conty (2017) add it back as a second, nearly diffuse ' +
      'lobe (dotted), built so that the white furnace closes. The dots are the truth it approximates: light walked ' +
      'from facet to facet until it escapes (Heitz et al. 2016). At α = 1 with F = 1 the returned lobe is larger ' +
      'than the single-scattering one here: 0.24 against 0.09 per steradian at these angles.',
  },

  // 5. Fresnel reflectance
  {
    id: 'fresnel-curves',
    section: 'fresnel',
    widget: 'fresnel-curves',
    title: 'Fresnel reflectance against angle',
    state: { materials: ['copper', 'aluminum', 'glass-low', 'diamond'], schlick: false, zones: true },
    text:
      'The share of light reflected by an optically flat surface depends on the material and on the angle. ' +
      'Up to about 45° it barely changes, to 75° it changes somewhat, and at grazing angles it rises quickly to ' +
      '100% for every material. Metals get one curve per colour channel.',
  },
  {
    id: 'fresnel-nv-glass',
    section: 'fresnel',
    widget: 'fresnel-zones',
    title: 'Fresnel of n·v on a shape',
    state: { mode: 'fresnel-nv', material: 'glass-low', shape: 'sphere' },
    text:
      'Under even, directionless light the angle that matters is the one between the view and the normal. ' +
      'Glass on a sphere: about 3% reflected where it faces us, brightening to white at the silhouette.',
  },
  {
    id: 'fresnel-zones-nv',
    section: 'fresnel',
    widget: 'fresnel-zones',
    title: 'Zones of n·v',
    state: { mode: 'zones-nv', shape: 'sphere' },
    text:
      'Colour the same angles by zone. Most of the picture lies where reflectance barely changes: for an ' +
      'orthographic sphere exactly $\\sin^2 45^\\circ = 50\\%$, then 43.3% where it changes somewhat, and only ' +
      '6.7% in the rapidly rising zone at the rim. The widget measures the shares on the GPU beside the analytic ' +
      'values.',
  },
  {
    id: 'fresnel-zones-lh',
    section: 'fresnel',
    widget: 'fresnel-zones',
    title: 'Zones of l·h',
    state: { mode: 'zones-lh', shape: 'torusknot', lightTheta: 140 },
    text:
      'In a microfacet BRDF the facets that reflect are those facing along h, so Fresnel takes the angle ' +
      'between l and h. With the light behind the object the whole shape turns yellow or red. Move the light ' +
      'around (drag, or the arrow keys on the picture).',
  },
  {
    id: 'fresnel-zones-lh-weighted',
    section: 'fresnel',
    widget: 'fresnel-zones',
    title: 'Weighted by the rest of the BRDF',
    state: { mode: 'zones-lh-weighted', shape: 'torusknot', lightTheta: 140, alpha: 0.3 },
    text:
      'Now weight each pixel by the light the rest of the BRDF actually sends to the eye. From behind, ' +
      'little light reaches the eye: only thin grazing edges stay bright. Averaged over light directions all ' +
      'around the object, at this roughness (GGX α = 0.3) about two thirds of the reflected light is green and ' +
      'under 1% red (see the legend); a smoother surface (α = 0.1) sends about 2% red.',
  },
  {
    id: 'fresnel-f0-tables',
    section: 'fresnel',
    widget: 'f0-tables',
    title: 'F(0°) is the specular colour',
    state: { selected: 'gold' },
    text:
      'Since reflectance hardly moves over most angles, its value at normal incidence, F(0°), serves as the ' +
      'surface’s specular colour. Metals are bright and often coloured; non-metals are dark and grey, a few ' +
      'percent. Mind linear against sRGB values.',
  },
  {
    id: 'fresnel-gold',
    section: 'fresnel',
    widget: 'fresnel-zones',
    title: 'A metal’s colour is its reflection',
    state: { mode: 'fresnel-nv', material: 'gold', shape: 'teapot', camera: 'perspective' },
    text:
      'A metal has no diffuse term: everything refracted is absorbed, so its Fresnel reflectance is all the ' +
      'colour it has. Gold keeps its yellow over most of the teapot and whitens only at grazing angles.',
  },
  {
    id: 'fresnel-schlick',
    section: 'fresnel',
    widget: 'fresnel-curves',
    title: 'Schlick’s approximation',
    state: { materials: ['gold', 'copper', 'glass-low', 'diamond'], schlick: true, zones: true },
    text:
      'Schlick’s approximation needs only $F(0^\\circ)$: $F(0^\\circ) + (1 - F(0^\\circ))(1 - \\cos \\theta)^5$. ' +
      'The dashed curves follow the exact ones closely; the error plot shows it is largest towards grazing angles, ' +
      'where little of the picture lies.',
  },

  // 6. Normal distribution functions
  {
    id: 'ndf-matched',
    section: 'ndf',
    widget: 'ndf-explorer',
    title: 'Five NDFs at one width',
    state: { hwhm: 8 },
    text:
      'The normal distribution function D(h) is the density of facets facing along h: it sets the size and ' +
      'shape of the highlight. Given the same half width, the five distributions of the talk share a core and ' +
      'differ in shape.',
  },
  {
    id: 'ndf-tails',
    section: 'ndf',
    widget: 'ndf-explorer',
    title: 'Long tails, soft halos',
    state: { hwhm: 8, exposure: 8 },
    text:
      'On the log plot the tails part ways: GGX, ABC and the shifted gamma keep many more facets far from the ' +
      'peak than Beckmann or Blinn-Phong. Raised exposure shows what that does: a glow around the highlight.',
  },
  {
    id: 'ndf-rough',
    section: 'ndf',
    widget: 'ndf-explorer',
    title: 'Roughness is width',
    state: { hwhm: 25 },
    text:
      'Widen the distribution and the highlight grows and dims. D is normalised, so the projected area of ' +
      'the facets always integrates to one, as the table measures.',
  },

  // 7. Geometry and visibility terms
  {
    id: 'visibility-terms',
    section: 'visibility',
    widget: 'visibility-explorer',
    title: 'The visibility term',
    state: { config: 'view-fixed', viewTheta: 60, alpha: 0.5 },
    text:
      'G gives the share of facets along h that are neither shadowed nor masked; the talk folds it with the ' +
      'denominator into $V = \\frac{G}{\\nl\\nv}$. The plots show G for every term against the light angle, and ' +
      'how far each is from height-correlated Smith.',
  },
  {
    id: 'visibility-implicit',
    section: 'visibility',
    widget: 'visibility-explorer',
    title: 'The implicit term ignores roughness',
    state: { config: 'view-fixed', viewTheta: 60, alpha: 0.1 },
    text:
      'The implicit term, $G = \\nl\\nv$, costs nothing but is the same at every roughness. At $\\alpha = 0.1$ the ' +
      'Smith terms stay near 1 until grazing angles, while the implicit one is at most $\\nv = 0.5$ here and falls ' +
      'with the light’s cosine.',
  },
  {
    id: 'visibility-mirror',
    section: 'visibility',
    widget: 'visibility-explorer',
    title: 'Cook-Torrance and Kelemen',
    state: { config: 'mirror', alpha: 0.5 },
    text:
      'With l and v mirrored about the normal, $\\mathbf{h} = \\mathbf{n}$: Cook-Torrance and Kelemen both give $G ' +
      '= 1$ whatever the angle, while the Smith terms darken towards grazing.',
  },
  {
    id: 'visibility-smith',
    section: 'visibility',
    widget: 'visibility-explorer',
    title: 'The Smith family',
    state: { alpha: 0.8, terms: ['smithGGXSeparable', 'smithGGXCorrelated', 'smithGGXCorrelatedFast', 'schlickGGX'] },
    text:
      'Smith’s terms are derived from the NDF itself. The height-correlated form is the more accurate; the ' +
      'separable form shadows a little too much. The error plot shows how closely the cheaper approximations ' +
      'follow it, and where they part.',
  },
  // 8. Diffuse
  {
    id: 'diffuse-lambert',
    section: 'diffuse',
    widget: 'diffuse-explorer',
    title: 'Lambert: the same from every direction',
    state: { models: ['lambert'], lightTheta: 50, lightPhi: 30 },
    text:
      'Light that enters a non-metal, scatters inside and comes out again close to where it went in is seen from ' +
      'afar as diffuse reflection. Lambert’s model makes it a constant, ' +
      '$\\frac{\\mathbf{c}_{\\text{diff}}}{\\pi}$: the sphere’s brightness follows $\\nl$ alone and does not ' +
      'depend on where you look from.',
  },
  {
    id: 'diffuse-tradeoff',
    section: 'diffuse',
    widget: 'diffuse-explorer',
    title: 'The diffuse–specular trade-off',
    state: { models: ['lambert', 'fresnelWeighted', 'ashikhminShirley'], lightTheta: 70, lightPhi: 0 },
    text:
      'Light reflected at the surface never enters it, so it cannot come back out as diffuse. Where Fresnel ' +
      'reflects more, at grazing angles, there must be less diffuse. Plain Lambert ignores this; the ' +
      'Fresnel-weighted and Ashikhmin–Shirley terms dim towards the rim to keep the budget at most 1.',
  },
  {
    id: 'diffuse-full-moon',
    section: 'diffuse',
    widget: 'diffuse-explorer',
    title: 'Rough diffuse: the full moon',
    state: { models: ['lambert', 'orenNayar', 'orenNayarQualitative'], sigma: 40, lightTheta: 0, lightPhi: 0 },
    text:
      'When the surface is rough on a scale larger than the distance light travels inside it, the bumps ' +
      'themselves shade each other. Lit from behind the viewer, a rough sphere looks flatter, towards the look ' +
      'of the full moon: near the rim, 95% of the radius out, Oren–Nayar at σ = 40° is still 0.71 as bright as ' +
      'the centre (its qualitative form 0.80), where Lambert, following n·l, has fallen to 0.31.',
  },
  // 9. From math to rendering
  {
    id: 'rendering-punctual',
    section: 'rendering',
    widget: 'material-lab',
    title: 'Punctual lights and c_light',
    state: {
      env: false,
      punctual: true,
      lightTheta: 0,
      cLight: 1,
      layers: 'diffuse',
      diffuse: '#ffffff',
      refSamples: '128',
    },
    text:
      'A punctual light is a direction and a colour. Its colour $\\mathbf{c}_{\\text{light}}$ is defined as the ' +
      'radiance of a white Lambertian surface that faces it: the centre of this white sphere shows exactly ' +
      '$\\mathbf{c}_{\\text{light}}$. The integral collapses to $L_o = \\pi f(\\mathbf{l}_c, \\mathbf{v}) \\otimes ' +
      '\\mathbf{c}_{\\text{light}} (\\mathbf{n} \\cdot \\mathbf{l}_c)$; the $\\pi$ is what turns a BRDF into that ' +
      'definition.',
  },
  {
    id: 'rendering-area',
    section: 'rendering',
    widget: 'material-lab',
    title: 'Area lights have a size',
    state: {
      env: false,
      punctual: false,
      area: true,
      areaRadius: 15,
      material: 'silver',
      alpha: 0.1,
      refSamples: '128',
      errorScale: 0.2,
    },
    text:
      'A real lamp has a size, and on a smooth surface its reflection shows it. The representative-point ' +
      'approximation bends the light direction towards the reflected ray to draw a highlight of the right shape; ' +
      'the reference integrates over the sphere light, and the error image shows what the shortcut misses.',
  },
  {
    id: 'rendering-mirror',
    section: 'rendering',
    widget: 'material-lab',
    title: 'Image-based lighting: a mirror',
    state: {
      material: 'silver',
      alpha: 0.01,
      punctual: false,
      envMethod: 'mirror',
      environment: 'studio',
      refSamples: '128',
    },
    text:
      'For an optically flat surface, image-based lighting is easy: the environment seen in the mirror ' +
      'direction, times Fresnel at the angle between view and normal. On this near-mirror the error is small.',
  },
  {
    id: 'rendering-split-sum',
    section: 'rendering',
    widget: 'material-lab',
    title: 'Glossy reflections by prefiltering',
    state: {
      material: 'gold',
      alpha: 0.3,
      punctual: false,
      envMethod: 'split-sum',
      environment: 'studio',
      refSamples: '128',
    },
    text:
      'A glossy surface needs the environment averaged over its lobe. Prefiltering does that once per ' +
      'roughness and splits off the rest of the BRDF into a small table (the split sum): cheap, and close to the ' +
      'reference except at grazing angles, where its assumption that the view looks straight at the surface fails.',
  },
  {
    id: 'rendering-importance',
    section: 'rendering',
    widget: 'material-lab',
    title: 'Glossy reflections by importance sampling',
    state: {
      material: 'gold',
      alpha: 0.3,
      punctual: false,
      envMethod: 'importance',
      samples: 16,
      environment: 'studio',
      refSamples: '128',
    },
    text:
      'Importance sampling takes a few directions where the BRDF is large and averages the environment ' +
      'there. With 16 samples the same pattern repeats on every pixel; more samples converge on the reference ' +
      'at a proportional cost. Raise N and watch the RMS error fall.',
  },
  {
    id: 'rendering-models',
    section: 'rendering',
    widget: 'lighting-models',
    title: 'From general lighting to ambient',
    state: { refSamples: '128' },
    text:
      'The illumination models side by side on one sky with an enlarged sun (2°; the real one is 0.27°): ' +
      'general lighting (the reference), ' +
      'image-based, area, punctual and ambient light. Each step down is cheaper and assumes more about where ' +
      'light comes from; the table says how much each costs and how far it falls from the reference.',
  },
];

/**
 * The tour as shown: the steps whose widget `isAvailable(name)`, and every section with the index of its
 * first step and its number of steps (0: "coming").
 */
export function tourPlan(isAvailable, steps = TOUR_STEPS, sections = TOUR_SECTIONS) {
  const live = steps.filter((s) => isAvailable(s.widget));
  return {
    steps: live,
    sections: sections.map((sec) => {
      const first = live.findIndex((s) => s.section === sec.key);
      return { ...sec, first, count: live.filter((s) => s.section === sec.key).length };
    }),
  };
}
