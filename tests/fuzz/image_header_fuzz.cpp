// libFuzzer target for the readers of handed-in images written by hand (compare's input,
// docs/compare.md): the PPM reader (host/base/ppm_image.h) and the JPEG marker walk that
// tells a whole file from a cut one and reads its quality (host/compare/jpeg_file.h); and
// stb's decoder as a model's textures are read with it (decodeTextures,
// model/texture_decoder.h: PNG, JPEG, BMP, TGA, the size its header claims checked first, in
// a child process, since stb itself is not hardened: a crash there must come back as the
// texture's problem). Any
// input must either be read or be rejected with a std::runtime_error naming the file;
// anything else (another exception, a crash, a sanitizer report, a leak, a hang,
// unbounded memory from a size a header claims) is a bug. Also compiled into
// image_fuzz_replay (tests/fuzz/fuzz_replay.cpp).
#include "base/ppm_image.h"
#include "compare/jpeg_file.h"
#include "model/texture_decoder.h"

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
    // A smaller side than textures' 16384, so that one input cannot ask for a gigabyte.
    const std::vector<DecodedTexture> decoded =
        decodeTextures({{"fuzz.image", std::vector<std::uint8_t>(data, data + size)}}, 1024);
    if (decoded.size() != 1 || decoded[0].image.has_value() == !decoded[0].problem.empty())
        __builtin_trap(); // one answer: an image or a problem
    try {
        (void)readJpegFacts("fuzz.jpg", std::vector<std::uint8_t>(data, data + size)).quality;
    } catch (const std::runtime_error&) {
    }
    return 0;
}
