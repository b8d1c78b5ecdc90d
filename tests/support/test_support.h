// What the tests that run the program need: starting it as a user would, finding
// scenes, and comparing its images with the CPU reference.
#pragma once

#include "base/image_io.h"
#include "compare/image_compare.h"
#include "reference/reference_renderer.h"

#include <chrono>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <sys/types.h>

struct ProcessResult {
    int exitCode = -1; // -1 when killed by a signal or the time limit
    bool timedOut = false;
    std::string out;
    std::string err;
};

// Runs the Raytracer binary with args (no shell), in workingDirectory when given,
// capturing both streams. Killed after timeoutSeconds.
ProcessResult runRaytracer(const std::vector<std::string>& args, int timeoutSeconds = 300,
                           const std::filesystem::path& workingDirectory = {});

// The same for another program (a tool such as image_diff or reference_render; their paths
// are IMAGE_DIFF_BINARY and REFERENCE_RENDER_BINARY).
ProcessResult runProgram(const std::filesystem::path& program, const std::vector<std::string>& args,
                         int timeoutSeconds = 300);

// Like runRaytracer, and calls duringRun(pid, stderr file) once in this thread while the
// process runs (to send it a signal, for example); the process is then waited for.
ProcessResult
runRaytracerWhile(const std::vector<std::string>& args,
                  const std::function<void(pid_t, const std::filesystem::path&)>& duringRun,
                  int timeoutSeconds = 300);

// The JSON object that --bench prints last on stdout (from its last '{'); throws when
// there is none.
std::string benchJson(const ProcessResult& run);

// Waits until a file holds text, or timeout passes: a running program's stderr, to act
// once it has reached a stage that it reports.
void waitForText(const std::filesystem::path& file, const std::string& text,
                 std::chrono::seconds timeout = std::chrono::seconds(120));

// A fresh, empty folder under the build tree for one test's files.
std::filesystem::path freshOutputDir(const std::string& name);

// The *.scene files of a folder, sorted; empty when the folder is absent.
std::vector<std::filesystem::path> sceneFilesIn(const std::filesystem::path& folder);

// The bytes of a file; empty when it cannot be read.
std::string readWholeFile(const std::filesystem::path& path);

// Writes text to a file (for scene files made by a test).
void writeTextFile(const std::filesystem::path& path, const std::string& text);

// True when stderr holds a message relayed from the validation layer.
bool hasValidationMessage(const ProcessResult& result);
