// libFuzzer target for the readers of handed-in images written by hand (compare's input,
// docs/compare.md): the PPM reader (host/base/ppm_image.h) and the JPEG marker walk that
// tells a whole file from a cut one and reads its quality (host/compare/jpeg_file.h). Any
// input must either be read or be rejected with a std::runtime_error naming the file;
// anything else (another exception, a crash, a sanitizer report, a leak, a hang,
// unbounded memory from a size a header claims) is a bug. Also compiled into
// image_fuzz_replay (tests/fuzz/fuzz_replay.cpp).
#include "base/ppm_image.h"
#include "compare/jpeg_file.h"

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        (void)decodePpm("fuzz.ppm", std::string(reinterpret_cast<const char*>(data), size))
            .rgb.size();
    } catch (const std::runtime_error&) {
        // the expected way to reject a file
    }
    try {
        (void)readJpegFacts("fuzz.jpg", std::vector<std::uint8_t>(data, data + size)).quality;
    } catch (const std::runtime_error&) {
    }
    return 0;
}
