#include "model/contained_reader.h"

#include "model/model_bytes.h"
#include "scene/scene_error.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <exception>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

// The child's answer: 'M' and the bytes produced, 'E' and a SceneError (line, file,
// message), or 'X' and another exception's text.
void writeAll(int fd, const std::string& bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return;
        done += std::size_t(n);
    }
}

std::string readAll(int fd) {
    std::string bytes;
    char buffer[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        bytes.append(buffer, std::size_t(n));
    }
    return bytes;
}

std::string withLength(const std::string& text) {
    const std::uint64_t size = text.size();
    return std::string(reinterpret_cast<const char*>(&size), sizeof size) + text;
}

// The text after a withLength at `at`, moving at past it; empty when cut short.
std::string lengthPrefixed(const std::string& bytes, std::size_t& at) {
    std::uint64_t size = 0;
    if (bytes.size() - at < sizeof size) return {};
    std::memcpy(&size, bytes.data() + at, sizeof size);
    at += sizeof size;
    if (size > bytes.size() - at) return {};
    std::string text = bytes.substr(at, size);
    at += size;
    return text;
}

[[noreturn]] void answerAndExit(int fd, const std::function<std::string()>& produce) {
    std::string answer;
    try {
        answer = "M" + produce();
    } catch (const SceneError& error) {
        const std::int64_t line = error.line;
        answer = "E" + std::string(reinterpret_cast<const char*>(&line), sizeof line) +
                 withLength(error.file) + withLength(error.message);
    } catch (const std::exception& error) {
        answer = "X" + withLength(error.what());
    }
    writeAll(fd, answer);
    ::_exit(0); // no destructors, no exit handlers: the parent's state is the parent's
}

} // namespace

std::string runContained(const std::string& fileName, const std::string& reader,
                         const std::function<std::string()>& produce) {
    int fds[2];
    if (::pipe(fds) != 0)
        throw SceneError(fileName, 0, "cannot start " + reader + ": " + std::strerror(errno));
    ::fcntl(fds[0], F_SETPIPE_SZ, 1 << 20); // fewer turns between the two for a large model
    const pid_t child = ::fork();
    if (child < 0) {
        const int error = errno;
        ::close(fds[0]);
        ::close(fds[1]);
        throw SceneError(fileName, 0, "cannot start " + reader + ": " + std::strerror(error));
    }
    if (child == 0) {
        ::close(fds[0]);
        answerAndExit(fds[1], produce);
    }
    ::close(fds[1]);
    // The kind of answer, then its bytes: read apart, so that a large answer is not copied
    // again to drop its first byte.
    char kind = 0;
    while (::read(fds[0], &kind, 1) < 0 && errno == EINTR) {
    }
    std::string answer = readAll(fds[0]);
    ::close(fds[0]);
    int status = 0;
    while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    if (WIFSIGNALED(status))
        throw SceneError(fileName, 0,
                         reader + " crashed on this file (" + ::strsignal(WTERMSIG(status)) +
                             "): it is damaged, or holds what the reader cannot read");
    if (kind == 'M' && WIFEXITED(status) && WEXITSTATUS(status) == 0) return answer;
    if (kind == 'E' && answer.size() >= sizeof(std::int64_t)) {
        std::int64_t line = 0;
        std::memcpy(&line, answer.data(), sizeof line);
        std::size_t at = sizeof line;
        std::string file = lengthPrefixed(answer, at);
        std::string message = lengthPrefixed(answer, at);
        throw SceneError(std::move(file), static_cast<int>(line), std::move(message));
    }
    if (kind == 'X') {
        std::size_t at = 0;
        throw SceneError(fileName, 0, reader + " failed: " + lengthPrefixed(answer, at));
    }
    throw SceneError(fileName, 0,
                     reader + " ended without an answer (exit status " +
                         std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")");
}

SourceModel readContained(const std::string& fileName, const std::function<SourceModel()>& read) {
    const std::string answer =
        runContained(fileName, "the model reader", [&] { return modelBytes(read()); });
    try {
        return modelFromBytes(answer);
    } catch (const std::exception& error) {
        throw SceneError(fileName, 0,
                         std::string("the model reader's answer is broken: ") + error.what());
    }
}
