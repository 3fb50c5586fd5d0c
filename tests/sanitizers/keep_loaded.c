/* Preloaded into the sanitizer job's tests (CMakePresets.json "asan"):
 * dlclose() does nothing, so Mesa's driver stays mapped until the process
 * ends. LeakSanitizer runs at exit; once EGL has unloaded the driver, its
 * globals are no longer scanned and everything they still point to shows
 * up as leaked, with stacks that end in "<unknown module>". Kept mapped, the
 * driver's memory is reachable and no report (nor suppression) is needed.
 * Built without sanitizers: it must not come before libasan's own hooks. */
#include <dlfcn.h>

int dlclose(void* handle) {
  (void)handle;
  return 0;
}
