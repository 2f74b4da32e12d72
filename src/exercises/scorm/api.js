// Finding a SCORM 1.2 LMS's API object, as the SCORM 1.2 Run-Time Environment (ADL, 2001, section 3.3)
// says: `API` on this window or on up to 7 parents, then the same from the opener (a package the LMS
// opened in a new window). A parent from another origin cannot be read: the search stops there.
const MAX_PARENTS = 7;
const LMS_CALLS = ['LMSInitialize', 'LMSFinish', 'LMSGetValue', 'LMSSetValue', 'LMSCommit', 'LMSGetLastError'];

const apiOn = (win) => {
  try {
    const api = win.API;
    return api && LMS_CALLS.every((name) => typeof api[name] === 'function') ? api : null;
  } catch {
    return null; // another origin
  }
};

function searchUp(win) {
  for (let tries = 0; win && tries <= MAX_PARENTS; tries++) {
    const api = apiOn(win);
    if (api) return api;
    let parent;
    try {
      parent = win.parent;
    } catch {
      return null;
    }
    if (!parent || parent === win) return null;
    win = parent;
  }
  return null;
}

/** The API object, or null when the page was opened without an LMS. */
export function findLmsApi(win) {
  const here = searchUp(win);
  if (here) return here;
  try {
    return (win.opener && searchUp(win.opener)) || (win.top?.opener && searchUp(win.top.opener)) || null;
  } catch {
    return null;
  }
}
