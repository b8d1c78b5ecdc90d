// Linked into every program that links raytracer_base, in the sanitizer build only
// (-DRAYTRACER_SANITIZE=ON), and into the fuzz target of the models read through assimp:
// LeakSanitizer's built-in suppressions, which it reads from this hook whatever
// LSAN_OPTIONS says. Leaks inside the Debian libraries below, on their error paths:
//
// Debian's tinyexr 1.0.1: when LoadEXRImageFromMemory fails on damaged pixel data it frees
// its array of channel pointers but not the channel planes they point to (found by
// image_diff_test and float_image_test, which read truncated EXR files). The header, which
// its LoadEXRFromMemory also leaks on that path, host/base/exr_image.cpp releases itself.
//
// Debian's assimp 5.2: its ASCII STL reader, failing on a damaged file, leaks the mesh it
// was building (found by tools/fuzz.sh's model target within seconds). What is leaked is
// the damaged file's, once per file read.
extern "C" const char* __lsan_default_suppressions() {
    return "leak:libtinyexr\nleak:libassimp\n";
}

// And no list of the suppressions used on stderr, whose messages the tests read (as
// LSAN_OPTIONS asks in tests/CMakeLists.txt; this is the default when it is not passed).
extern "C" const char* __lsan_default_options() {
    return "print_suppressions=0";
}
