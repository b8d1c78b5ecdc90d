// The bytes of a scene file, as cheaply as the file allows.
#pragma once

#include <string>
#include <string_view>
#include <sys/types.h>

// A scene file's bytes. A large regular file is mapped rather than copied: reading a
// 400 MB scene into a string costs most of a second, mapping it a few milliseconds.
// (If another program truncates the file while it is mapped, reading the lost pages
// raises SIGBUS; scene files are written whole and then read, so this is accepted.)
class MappedFile {
  public:
    // Throws SceneError ("cannot open file: ...", "cannot read file: ...", or for a device
    // such as /dev/zero, which would never end).
    explicit MappedFile(const std::string& name);
    ~MappedFile();
    MappedFile(const MappedFile&) = delete;
    MappedFile& operator=(const MappedFile&) = delete;

    std::string_view text() const { return mapped_.empty() ? std::string_view(read_) : mapped_; }

  private:
    static constexpr off_t kMapMinimum = 1 << 20;
    int descriptor_ = -1;
    std::string_view mapped_;
    std::string read_;
};
