// Draws the measured-BRDF widget's views from its state and the data they show ({ measured, fits, sourceWords }),
// one group at a time, so that a change redraws only what it touches.
import { FIT_MODELS } from '../../measured/fit.js';
import { lightDirFromAngles, DEG } from '../../math/angles.js';
import { RESIDUAL_TOP, fitBRDF, lobe3dSpec, residualImage } from './model.js';
import { describeLobe3d, describeMeasured, imageCaption, residualCaption } from './words.js';

const MODELS = Object.keys(FIT_MODELS);

/** `lobe()`, `ndf()`, `images()`, `spheres()`, `describe()`: each redraws its views. */
export function createPainter({ lobePlot, lobe3d, spheres, image, ndfPlot, residuals }, shell, data) {
  const s = () => shell.state;
  const images = () => {
    const { measured, fits } = data();
    const phiD = s().phiD;
    image.draw(
      measured ? (th, td) => measured.valueAt(th, td, phiD * DEG)[1] : () => 0,
      imageCaption(Boolean(measured), phiD),
    );
    MODELS.forEach((k, i) =>
      residuals[i].draw(
        measured && fits[k] ? residualImage(measured, fits[k], phiD) : () => 0,
        residualCaption(k, Boolean(fits[k]), phiD),
        { max: RESIDUAL_TOP },
      ),
    );
  };
  return {
    lobe() {
      const { measured, fits } = data();
      const fit = fits[s().overlay];
      lobePlot.show(measured, fit, s().lightTheta);
      if (!measured) return;
      const spec = lobe3dSpec(measured.lookup, fit ? fitBRDF(fit) : null, s().lightTheta, lobe3d.directions);
      lobe3d.update({ ...spec, description: describeLobe3d(fit, s().lightTheta, spec.max) });
    },
    ndf: () => ndfPlot.show(data().measured, data().fits, s().overlay),
    images,
    spheres: () => spheres.setLight(lightDirFromAngles(s().sphereLight, 135), s().exposure),
    describe: () => shell.describe(describeMeasured(data(), s()), spheres.canvas),
  };
}
