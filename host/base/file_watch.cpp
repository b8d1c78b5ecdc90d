#include "base/file_watch.h"

#include "base/hash.h"

#include <algorithm>
#include <string>
#include <vector>

namespace {

std::uint64_t mixFile(const std::filesystem::path& file, std::uint64_t key) {
    std::error_code error;
    const auto size = std::filesystem::file_size(file, error);
    if (error) return key;
    const auto modified = std::filesystem::last_write_time(file, error);
    if (error) return key;
    const std::string name = file.filename().string();
    const std::int64_t ticks = modified.time_since_epoch().count();
    const std::uint64_t bytes = size;
    key = hashBytes(name.data(), name.size() + 1, key);
    key = hashBytes(&ticks, sizeof(ticks), key);
    return hashBytes(&bytes, sizeof(bytes), key);
}

} // namespace

std::uint64_t pathSignature(const std::filesystem::path& path) {
    std::error_code error;
    if (!std::filesystem::is_directory(path, error)) {
        if (!std::filesystem::exists(path, error)) return 0;
        return mixFile(path, 1);
    }
    std::vector<std::filesystem::path> files;
    for (std::filesystem::directory_iterator it(path, error), end; !error && it != end;
         it.increment(error))
        if (it->is_regular_file(error)) files.push_back(it->path());
    std::sort(files.begin(), files.end()); // the same signature whatever the listing order
    std::uint64_t key = 1;
    for (const std::filesystem::path& file : files)
        key = mixFile(file, key);
    return key;
}

FileWatch watchPath(const std::filesystem::path& path) {
    return {path, pathSignature(path)};
}

bool pathChanged(FileWatch& watch) {
    const std::uint64_t now = pathSignature(watch.path);
    if (now == watch.signature) return false;
    watch.signature = now;
    return true;
}
