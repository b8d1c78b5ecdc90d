#include "scene/mapped_file.h"

#include "scene/scene_error.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

MappedFile::MappedFile(const std::string& name) {
    descriptor_ = ::open(name.c_str(), O_RDONLY | O_CLOEXEC);
    if (descriptor_ < 0)
        throw SceneError(name, 0, std::string("cannot open file: ") + std::strerror(errno));
    struct stat info {};
    if (::fstat(descriptor_, &info) == 0 && (S_ISCHR(info.st_mode) || S_ISBLK(info.st_mode))) {
        ::close(descriptor_);
        descriptor_ = -1;
        throw SceneError(name, 0, "a device, not a file: it would be read without end");
    }
    if (S_ISREG(info.st_mode) && info.st_size >= kMapMinimum) {
        void* mapped = ::mmap(nullptr, std::size_t(info.st_size), PROT_READ,
                              MAP_PRIVATE | MAP_POPULATE, descriptor_, 0);
        if (mapped != MAP_FAILED) {
            mapped_ = {static_cast<const char*>(mapped), std::size_t(info.st_size)};
            return;
        }
    }
    // Not mappable (a pipe, a file in /proc that claims size 0): read to the end,
    // growing with what arrives; the size is a hint only.
    if (S_ISREG(info.st_mode) && info.st_size > 0) read_.reserve(std::size_t(info.st_size));
    char buffer[1 << 16];
    for (;;) {
        const ssize_t n = ::read(descriptor_, buffer, sizeof buffer);
        if (n == 0) break;
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            const int error = errno;
            ::close(descriptor_);
            throw SceneError(name, 0, std::string("cannot read file: ") + std::strerror(error));
        }
        read_.append(buffer, std::size_t(n));
    }
}

MappedFile::~MappedFile() {
    if (!mapped_.empty()) ::munmap(const_cast<char*>(mapped_.data()), mapped_.size());
    if (descriptor_ >= 0) ::close(descriptor_);
}
