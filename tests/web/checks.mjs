// The web tests' checks: check(ok, what) prints a failed check (every check with `everyOne`)
// and counts the failures; failed() says how many.
export function checks({ everyOne = false } = {}) {
  let failures = 0;
  const check = (ok, what) => {
    if (everyOne || !ok) console.log(`${ok ? "ok  " : "FAIL"} ${what}`);
    if (!ok) failures++;
  };
  return { check, failed: () => failures };
}
