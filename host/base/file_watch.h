// Noticing that a file or the files of a folder were saved: the window polls a cheap
// signature (modification times and sizes) every few frames. Polling, rather than
// inotify, also sees an editor's save-by-rename and a file that is deleted and recreated.
#pragma once

#include <cstdint>
#include <filesystem>

struct FileWatch {
    std::filesystem::path path; // a file, or a folder whose regular files are watched
    std::uint64_t signature = 0;
};

// Starts watching path as it is now.
FileWatch watchPath(const std::filesystem::path& path);

// True (once) when the signature differs from the last call's or watchPath's.
bool pathChanged(FileWatch& watch);

// The signature of path now: a hash of name, modification time and size of the file or of
// every regular file in the folder; 0 when path does not exist.
std::uint64_t pathSignature(const std::filesystem::path& path);
