#include "compare/jpeg_codec.h"

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <stdexcept>
#include <string>

#include <jpeglib.h>

namespace {

// libjpeg reports errors through a callback that must not return: it jumps back to the
// setjmp of the call that started the work, with the message kept here. No object with a
// destructor lives in a frame between setjmp and the jump.
struct ErrorManager {
    jpeg_error_mgr base;
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX];
    bool warned = false; // a warning (data cut short or corrupt) is an error here
};

void onError(j_common_ptr info) {
    auto* manager = reinterpret_cast<ErrorManager*>(info->err);
    (*info->err->format_message)(info, manager->message);
    std::longjmp(manager->jump, 1);
}

void onMessage(j_common_ptr info, int level) {
    auto* manager = reinterpret_cast<ErrorManager*>(info->err);
    if (level == -1 && !manager->warned) { // the first warning: keep its text
        manager->warned = true;
        (*info->err->format_message)(info, manager->message);
    }
}

ErrorManager* errorsOf(jpeg_common_struct* info, ErrorManager& manager) {
    info->err = jpeg_std_error(&manager.base);
    manager.base.error_exit = onError;
    manager.base.emit_message = onMessage;
    manager.message[0] = '\0';
    return &manager;
}

// Decodes into pixels (RGB bytes); false with manager.message set when libjpeg failed or
// warned. Plain C data only, because of the jump.
bool decodeInto(const std::vector<std::uint8_t>& bytes, int maxSide,
                std::vector<unsigned char>& pixels, int& width, int& height,
                ErrorManager& manager) {
    jpeg_decompress_struct info;
    errorsOf(reinterpret_cast<jpeg_common_struct*>(&info), manager);
    if (setjmp(manager.jump)) {
        jpeg_destroy_decompress(&info);
        return false;
    }
    jpeg_create_decompress(&info);
    jpeg_mem_src(&info, bytes.data(), static_cast<unsigned long>(bytes.size()));
    jpeg_read_header(&info, TRUE);
    width = int(info.image_width);
    height = int(info.image_height);
    if (width > maxSide || height > maxSide) {
        std::snprintf(manager.message, sizeof manager.message,
                      "the image is %dx%d, over %d pixels a side", width, height, maxSide);
        jpeg_destroy_decompress(&info);
        return false;
    }
    info.out_color_space = JCS_RGB;
    jpeg_start_decompress(&info);
    pixels.resize(std::size_t(width) * std::size_t(height) * 3);
    while (info.output_scanline < info.output_height) {
        JSAMPROW row = &pixels[std::size_t(info.output_scanline) * std::size_t(width) * 3];
        jpeg_read_scanlines(&info, &row, 1);
    }
    jpeg_finish_decompress(&info);
    jpeg_destroy_decompress(&info);
    return !manager.warned;
}

ImageF levelsOf(const std::vector<unsigned char>& pixels, int width, int height) {
    ImageF image;
    image.width = width;
    image.height = height;
    image.rgb.assign(pixels.begin(), pixels.end());
    return image;
}

std::vector<unsigned char> bytesOf(const ImageF& levels) {
    std::vector<unsigned char> bytes(levels.rgb.size());
    for (std::size_t k = 0; k < bytes.size(); ++k)
        bytes[k] =
            static_cast<unsigned char>(std::clamp(std::floor(levels.rgb[k] + 0.5f), 0.0f, 255.0f));
    return bytes;
}

// Encodes pixels; original (a JPEG file) gives the tables and sampling, else quality does.
bool encode(const std::vector<unsigned char>& pixels, int width, int height,
            const std::vector<std::uint8_t>* original, int quality, unsigned char*& out,
            unsigned long& outSize, ErrorManager& manager) {
    jpeg_compress_struct info;
    jpeg_decompress_struct source; // the original's header, read with the same errors
    errorsOf(reinterpret_cast<jpeg_common_struct*>(&info), manager);
    source.err = info.err;
    volatile bool sourceOpen = false; // read after a jump, so kept in memory
    if (setjmp(manager.jump)) {
        if (sourceOpen) jpeg_destroy_decompress(&source);
        jpeg_destroy_compress(&info);
        return false;
    }
    jpeg_create_compress(&info);
    jpeg_mem_dest(&info, &out, &outSize);
    info.image_width = JDIMENSION(width);
    info.image_height = JDIMENSION(height);
    info.input_components = 3;
    info.in_color_space = JCS_RGB;
    if (original) {
        jpeg_create_decompress(&source);
        sourceOpen = true;
        jpeg_mem_src(&source, original->data(), static_cast<unsigned long>(original->size()));
        jpeg_read_header(&source, TRUE);
        // The image's own size, colour space and component count; the original's tables
        // and sampling factors.
        jpeg_copy_critical_parameters(&source, &info);
        info.image_width = JDIMENSION(width);
        info.image_height = JDIMENSION(height);
        info.in_color_space = JCS_RGB;
        info.input_components = 3;
        if (source.jpeg_color_space == JCS_GRAYSCALE) jpeg_set_colorspace(&info, JCS_GRAYSCALE);
    } else {
        jpeg_set_defaults(&info);
        jpeg_set_quality(&info, quality, TRUE);
    }
    jpeg_start_compress(&info, TRUE);
    while (info.next_scanline < info.image_height) {
        JSAMPROW row =
            const_cast<JSAMPROW>(&pixels[std::size_t(info.next_scanline) * std::size_t(width) * 3]);
        jpeg_write_scanlines(&info, &row, 1);
    }
    jpeg_finish_compress(&info);
    jpeg_destroy_compress(&info);
    if (sourceOpen) jpeg_destroy_decompress(&source);
    return true;
}

std::vector<std::uint8_t> encodeOrThrow(const ImageF& levels,
                                        const std::vector<std::uint8_t>* original, int quality) {
    const std::vector<unsigned char> pixels = bytesOf(levels);
    unsigned char* out = nullptr;
    unsigned long outSize = 0;
    ErrorManager manager;
    const bool encoded =
        encode(pixels, levels.width, levels.height, original, quality, out, outSize, manager);
    std::vector<std::uint8_t> bytes;
    if (out) bytes.assign(out, out + outSize);
    std::free(out);
    if (!encoded) throw std::runtime_error(std::string("cannot encode a JPEG: ") + manager.message);
    return bytes;
}

} // namespace

ImageF decodeJpeg(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes,
                  int maxSide) {
    std::vector<unsigned char> pixels;
    int width = 0, height = 0;
    ErrorManager manager;
    if (!decodeInto(bytes, maxSide, pixels, width, height, manager))
        throw std::runtime_error(path.string() + ": not a readable JPEG: " + manager.message);
    return levelsOf(pixels, width, height);
}

ImageF throughJpegLike(const ImageF& levels, const std::vector<std::uint8_t>& original) {
    const std::vector<std::uint8_t> encoded = encodeOrThrow(levels, &original, 0);
    return decodeJpeg("the reference as JPEG", encoded, 1 << 16);
}

std::vector<std::uint8_t> encodeJpegWithLibjpeg(const ImageF& levels, int quality) {
    return encodeOrThrow(levels, nullptr, std::clamp(quality, 1, 100));
}
