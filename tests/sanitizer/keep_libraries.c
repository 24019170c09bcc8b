// LD_PRELOAD shim for the sanitizer test run (scripts/sanitize.sh): dlclose() keeps the library
// loaded. Mesa's EGL unloads its driver (libgallium, swrast_dri.so) at eglTerminate, so the
// driver's own leaks would reach LeakSanitizer from "<unknown module>", which no suppression can
// name; with the driver still mapped they carry its name and tests/lsan-mesa.supp matches them.
// Only the sanitizer run preloads this; it changes nothing else (no library is unloaded twice).

int dlclose(void* handle) {
  (void)handle;
  return 0;
}
