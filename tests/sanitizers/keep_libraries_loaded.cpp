// Linked into every program that links raytracer_core (Raytracer, and the tests that
// open a Vulkan device themselves), in the sanitizer build only (-DRAYTRACER_SANITIZE=ON). The
// Vulkan loader unloads the driver (Mesa's lavapipe) in vkDestroyInstance, before
// LeakSanitizer runs at exit; a leak inside the driver would then be reported with
// "<unknown module>" frames, impossible to attribute or to suppress by library. This
// dlclose, which the executable exports and so the loader calls instead of glibc's,
// keeps every library loaded, so reports name the library and function.
extern "C" int dlclose(void*) {
    return 0;
}
