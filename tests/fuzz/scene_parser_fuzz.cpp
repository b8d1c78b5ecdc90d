// libFuzzer target for the scene parser (host/scene.h): any input must either parse
// or be rejected with a SceneError. Anything else (another exception, a crash, a
// sanitizer report, a leak, a hang, unbounded memory) is a bug. Also compiled into
// fuzz_replay (tests/fuzz/fuzz_replay.cpp), which replays the seeds and regressions
// in the ordinary test suite.
#include "scene.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        Scene scene = parseScene(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.scene");
        (void)scene;
    } catch (const SceneError&) {
        // The expected way to reject a file; other exceptions escape and abort.
    }
    return 0;
}
