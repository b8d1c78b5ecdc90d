#include "test_support.h"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

std::string readWholeFile(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

namespace {

ProcessResult
runProgramIn(const std::filesystem::path& program, const std::vector<std::string>& args,
             int timeoutSeconds, const std::filesystem::path& workingDirectory,
             const std::function<void(pid_t, const std::filesystem::path&)>& duringRun);

} // namespace

ProcessResult runRaytracer(const std::vector<std::string>& args, int timeoutSeconds,
                           const std::filesystem::path& workingDirectory) {
    return runProgramIn(RAYTRACER_BINARY, args, timeoutSeconds, workingDirectory, {});
}

ProcessResult
runRaytracerWhile(const std::vector<std::string>& args,
                  const std::function<void(pid_t, const std::filesystem::path&)>& duringRun,
                  int timeoutSeconds) {
    return runProgramIn(RAYTRACER_BINARY, args, timeoutSeconds, {}, duringRun);
}

ProcessResult runProgram(const std::filesystem::path& program, const std::vector<std::string>& args,
                         int timeoutSeconds) {
    return runProgramIn(program, args, timeoutSeconds, {}, {});
}

namespace {

ProcessResult
runProgramIn(const std::filesystem::path& program, const std::vector<std::string>& args,
             int timeoutSeconds, const std::filesystem::path& workingDirectory,
             const std::function<void(pid_t, const std::filesystem::path&)>& duringRun) {
    static int runCount = 0;
    std::filesystem::path captureDir =
        freshOutputDir("process-" + std::to_string(getpid()) + "-" + std::to_string(runCount++));
    std::filesystem::path outPath = captureDir / "stdout.txt", errPath = captureDir / "stderr.txt";

    std::vector<std::string> argv = {program.string()};
    argv.insert(argv.end(), args.begin(), args.end());
    std::vector<char*> argvPointers;
    for (std::string& arg : argv)
        argvPointers.push_back(arg.data());
    argvPointers.push_back(nullptr);

    pid_t child = fork();
    if (child < 0) throw std::runtime_error("fork failed");
    if (child == 0) {
        int out = open(outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        int err = open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        int in = open("/dev/null", O_RDONLY);
        dup2(in, 0);
        dup2(out, 1);
        dup2(err, 2);
        if (!workingDirectory.empty() && chdir(workingDirectory.c_str()) != 0) _exit(126);
        execv(argvPointers[0], argvPointers.data());
        _exit(127);
    }

    ProcessResult result;
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeoutSeconds);
    if (duringRun) duringRun(child, errPath);
    int status = 0;
    while (waitpid(child, &status, WNOHANG) == 0) {
        if (std::chrono::steady_clock::now() > deadline) {
            kill(child, SIGKILL);
            waitpid(child, &status, 0);
            result.timedOut = true;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    if (!result.timedOut && WIFEXITED(status)) result.exitCode = WEXITSTATUS(status);
    result.out = readWholeFile(outPath);
    result.err = readWholeFile(errPath);
    return result;
}

} // namespace

std::string benchJson(const ProcessResult& run) {
    return run.out.substr(run.out.rfind('{'));
}

void waitForText(const std::filesystem::path& file, const std::string& text,
                 std::chrono::seconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (readWholeFile(file).find(text) == std::string::npos &&
           std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
}

std::filesystem::path freshOutputDir(const std::string& name) {
    std::filesystem::path dir = std::filesystem::path(TEST_OUTPUT_DIR) / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

std::vector<std::filesystem::path> sceneFilesIn(const std::filesystem::path& folder) {
    std::vector<std::filesystem::path> scenes;
    if (!std::filesystem::is_directory(folder)) return scenes;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        if (entry.is_regular_file() && entry.path().extension() == ".scene")
            scenes.push_back(entry.path());
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

void writeTextFile(const std::filesystem::path& path, const std::string& text) {
    std::ofstream file(path, std::ios::binary);
    file << text;
    if (!file) throw std::runtime_error("cannot write " + path.string());
}

bool hasValidationMessage(const ProcessResult& result) {
    // The program's messenger prefixes every message it relays (host/gpu/context.cpp).
    return result.err.find("validation error: ") != std::string::npos ||
           result.err.find("validation warning: ") != std::string::npos;
}
