// imsmanifest.xml of a SCORM 1.2 package with one SCO (IMS Content Packaging 1.1.2 with ADL's adlcp
// extension, as the SCORM 1.2 Content Aggregation Model describes): one organization, one item pointing at the
// one resource, and every file of the package listed under it.
const escapeXml = (text) =>
  String(text).replace(
    /[<>&"']/g,
    (c) => ({ '<': '&lt;', '>': '&gt;', '&': '&amp;', '"': '&quot;', "'": '&apos;' })[c],
  );

const SCHEMAS =
  'http://www.imsproject.org/xsd/imscp_rootv1p1p2 imscp_rootv1p1p2.xsd ' +
  'http://www.imsglobal.org/xsd/imsmd_rootv1p2p1 imsmd_rootv1p2p1.xsd ' +
  'http://www.adlnet.org/xsd/adlcp_rootv1p2 adlcp_rootv1p2.xsd';

/**
 * identifier: the package's id (letters, digits, '-', '_', '.'); title; launch: the SCO's start file; files: every
 * path in the package (forward slashes); mastery: the pass mark in percent, or null.
 */
export function scormManifest({ identifier, title, launch, files, mastery = null }) {
  const mark = mastery === null ? '' : `\n        <adlcp:masteryscore>${mastery}</adlcp:masteryscore>`;
  const list = files.map((f) => `      <file href="${escapeXml(encodeURI(f))}"/>`).join('\n');
  return `<?xml version="1.0" encoding="UTF-8"?>
<manifest identifier="${escapeXml(identifier)}" version="1.0"
  xmlns="http://www.imsproject.org/xsd/imscp_rootv1p1p2"
  xmlns:adlcp="http://www.adlnet.org/xsd/adlcp_rootv1p2"
  xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
  xsi:schemaLocation="${SCHEMAS}">
  <metadata>
    <schema>ADL SCORM</schema>
    <schemaversion>1.2</schemaversion>
  </metadata>
  <organizations default="organization">
    <organization identifier="organization">
      <title>${escapeXml(title)}</title>
      <item identifier="item" identifierref="sco" isvisible="true">
        <title>${escapeXml(title)}</title>${mark}
      </item>
    </organization>
  </organizations>
  <resources>
    <resource identifier="sco" type="webcontent" adlcp:scormtype="sco" href="${escapeXml(encodeURI(launch))}">
${list}
    </resource>
  </resources>
</manifest>
`;
}

/**
 * The launch page: it opens the set in exercises.html in package mode (no script: the app's CSP allows none). Its
 * icon is the package's own: without one the browser asks the server's root for /favicon.ico, outside the package.
 */
export function launchPage({ title, set }) {
  const url = `exercises.html?scorm=1&src=${encodeURIComponent(set)}`;
  return `<!doctype html>
<html lang="en">
  <head>
    <meta charset="utf-8" />
    <meta http-equiv="Content-Security-Policy" content="default-src 'self'" />
    <meta http-equiv="refresh" content="0; url=${escapeXml(url)}" />
    <link rel="icon" href="favicon.svg" type="image/svg+xml" />
    <title>${escapeXml(title)}</title>
  </head>
  <body>
    <p><a href="${escapeXml(url)}">Open the exercises: ${escapeXml(title)}</a></p>
  </body>
</html>
`;
}
