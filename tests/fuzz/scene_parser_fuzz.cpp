// libFuzzer target for the scene parser (host/scene/scene.h): any input must either parse
// or be rejected with a SceneError. Anything else (another exception, a crash, a
// sanitizer report, a leak, a hang, unbounded memory) is a bug. Also compiled into
// fuzz_replay (tests/fuzz/fuzz_replay.cpp), which replays the seeds and regressions
// in the ordinary test suite.
//
// It is also a differential test of the parallel reader: fuzz inputs are far below the
// size at which parseScene splits a text, so an input is parsed again split into shares
// as small as one byte among a few threads, and the two outcomes must be the same in
// every respect: success or failure, the error's text, file, line and message, the
// warnings, and every value bit for bit. A difference prints both outcomes and aborts.
#include "scene/scene_loader.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace {

// Every struct of a Scene is doubles and a 64-bit line only, without padding, so comparing
// their bytes compares the values bit for bit (0.0 and -0.0 differ, as they should) and
// the lines of objects read by different chunks.
static_assert(sizeof(Sphere) == 12 * sizeof(double) + sizeof(std::int64_t));
static_assert(sizeof(Triangle) == 3 * 14 * sizeof(double) + sizeof(std::int64_t));
static_assert(sizeof(Light) == 6 * sizeof(double) + sizeof(std::int64_t));

struct Outcome {
    std::optional<Scene> scene;      // set on success
    std::optional<SceneError> error; // set on failure
};

Outcome parse(std::string_view text, const std::optional<SceneParseOptions>& options) {
    Outcome outcome;
    try {
        outcome.scene =
            options ? parseScene(text, "fuzz.scene", *options) : parseScene(text, "fuzz.scene");
    } catch (const SceneError& error) {
        // The expected way to reject a file; other exceptions escape and abort.
        outcome.error = error;
    }
    return outcome;
}

template <typename T> bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

bool same(const Outcome& a, const Outcome& b) {
    if (a.error || b.error)
        return a.error && b.error && std::string_view(a.error->what()) == b.error->what() &&
               a.error->file == b.error->file && a.error->line == b.error->line &&
               a.error->message == b.error->message;
    const Scene &x = *a.scene, &y = *b.scene;
    return std::memcmp(&x.ambient, &y.ambient, sizeof x.ambient) == 0 &&
           sameBits(x.spheres, y.spheres) && sameBits(x.triangles, y.triangles) &&
           sameBits(x.lights, y.lights) && x.warnings == y.warnings;
}

// An outcome in words, every value in hex so that no bit is lost.
std::string describe(const Outcome& outcome) {
    if (outcome.error)
        return std::string(outcome.error->what()) + " [file " + outcome.error->file + ", line " +
               std::to_string(outcome.error->line) + ", message " + outcome.error->message + "]";
    std::ostringstream out;
    out << std::hexfloat;
    const auto vec = [&](const glm::dvec3& v) { out << ' ' << v.x << ' ' << v.y << ' ' << v.z; };
    const auto material = [&](const Material& m) {
        vec(m.diffuse);
        vec(m.specular);
        out << ' ' << m.shininess;
    };
    const Scene& scene = *outcome.scene;
    out << "ambient";
    vec(scene.ambient);
    for (const Sphere& s : scene.spheres) {
        out << "\nsphere";
        vec(s.center);
        out << ' ' << s.radius;
        material(s.material);
    }
    for (const Triangle& t : scene.triangles) {
        out << "\ntriangle";
        for (const Vertex& v : t.vertices) {
            vec(v.position);
            vec(v.normal);
            material(v.material);
        }
    }
    for (const Light& l : scene.lights) {
        out << "\nlight";
        vec(l.position);
        vec(l.color);
    }
    for (const std::string& warning : scene.warnings)
        out << '\n' << warning;
    return out.str();
}

// Starting threads dominates the cost of a split parse (about 120 us for two or three
// threads under the sanitizers on an idle 2-core machine, against 28 us for a whole
// input), so under libFuzzer only an input of even length is split, with 2 to 4 threads
// by its length: libFuzzer's mutations change lengths all the time, so every kind of
// input is split in time, and a given input always splits the same way, so a reported
// mismatch replays. fuzz_replay splits every input with 2 to 5 threads.
bool splitEveryInput = true;

void expectSameSplit(std::string_view text, const Outcome& whole, unsigned threads) {
    // Shares of one byte: each thread starts at the first object keyword after its
    // share, so the splits fall at many places even in a short text.
    const Outcome parts = parse(text, SceneParseOptions{threads, 1});
    if (same(whole, parts)) return;
    std::fprintf(stderr,
                 "scene_parser_fuzz: the text parsed in %u shares differs from one pass\n"
                 "--- one pass:\n%s\n--- in shares:\n%s\n",
                 threads, describe(whole).c_str(), describe(parts).c_str());
    std::abort();
}

} // namespace

// Called by libFuzzer only (not by fuzz_replay), before the first input.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
    splitEveryInput = false;
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const Outcome whole = parse(text, std::nullopt); // small inputs: one reader, in one pass
    if (splitEveryInput) {
        for (unsigned threads = 2; threads <= 5; ++threads)
            expectSameSplit(text, whole, threads);
    } else if (size % 2 == 0) {
        expectSameSplit(text, whole, 2 + unsigned(size / 2 % 3));
    }
    return 0;
}
