// stitch -o OUT.png [--size WxH] PART...: region images (Raytracer --crop X,Y,W,H) joined
// into the full image. The PNG is written by the program's own writer (host/base/image_io.h),
// so regions of a render stitched give the file of the whole render, byte for byte.
#include "base/image_io.h"
#include "tool_arguments.h"

#include <cstdio>
#include <exception>
#include <optional>
#include <regex>
#include <string>
#include <vector>

namespace {

const char* const usage =
    "usage: stitch -o OUT.png [--size WxH] PART...\n"
    "Joins region images (Raytracer --crop X,Y,W,H -o ...) into one PNG. Each PART is\n"
    "FILE@X,Y, or a PNG whose name ends in -X-Y.png (part-X-Y.png, as tools/farm writes\n"
    "them): X,Y is the column and row of the full image where its top-left pixel goes.\n"
    "The output is W x H (default: just large enough for the parts). Every pixel must come\n"
    "from exactly one part. Exits 0 when written, 1 when the parts leave a gap or overlap\n"
    "(the first such pixel is named), 2 on a usage or file error.\n";

struct Part {
    std::string file;
    int x = 0, y = 0;
    Image8 image;
};

// "FILE@X,Y", or a FILE named ...-X-Y.png.
Part partFromArgument(const std::string& argument) {
    static const std::regex placed(R"((.+)@([0-9]+),([0-9]+))");
    static const std::regex named(R"((.*-([0-9]+)-([0-9]+)\.png))");
    std::smatch match;
    if (!std::regex_match(argument, match, placed) && !std::regex_match(argument, match, named))
        throw tool_arguments::UsageError("'" + argument +
                                         "' names no place: give FILE@X,Y or a file named "
                                         "...-X-Y.png");
    Part part;
    part.file = match[1];
    part.x = tool_arguments::parseNumber<int>("X", match[2].str());
    part.y = tool_arguments::parseNumber<int>("Y", match[3].str());
    return part;
}

int stitch(int argc, char** argv) {
    std::string output;
    std::optional<std::pair<int, int>> size;
    std::vector<Part> parts;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw tool_arguments::UsageError(arg + " expects a value");
            return argv[++i];
        };
        if (arg == "-h" || arg == "--help") {
            std::fputs(usage, stdout);
            return 0;
        } else if (arg == "-o") {
            output = value();
        } else if (arg == "--size") {
            static const std::regex wxh(R"(([0-9]+)x([0-9]+))");
            const std::string text = value();
            std::smatch match;
            if (!std::regex_match(text, match, wxh))
                throw tool_arguments::UsageError("--size expects WxH, got '" + text + "'");
            size = {tool_arguments::parseCount("--size", match[1].str(), 1),
                    tool_arguments::parseCount("--size", match[2].str(), 1)};
        } else if (arg.size() > 1 && arg[0] == '-') {
            throw tool_arguments::UsageError("unknown option '" + arg + "'");
        } else {
            parts.push_back(partFromArgument(arg));
        }
    }
    if (output.empty() || parts.empty())
        throw tool_arguments::UsageError("give -o OUT.png and at least one part");

    int width = 0, height = 0;
    for (Part& part : parts) {
        part.image = readPng(part.file);
        width = std::max(width, part.x + part.image.width);
        height = std::max(height, part.y + part.image.height);
    }
    if (size) {
        if (width > size->first || height > size->second)
            throw tool_arguments::UsageError("the parts reach " + std::to_string(width) + "x" +
                                             std::to_string(height) + ", beyond --size " +
                                             std::to_string(size->first) + "x" +
                                             std::to_string(size->second));
        width = size->first;
        height = size->second;
    }
    Image8 whole;
    whole.width = width;
    whole.height = height;
    whole.rgba.assign(std::size_t(width) * height * 4, 0);
    std::vector<const Part*> source(std::size_t(width) * height, nullptr);
    for (const Part& part : parts)
        for (int row = 0; row < part.image.height; ++row)
            for (int column = 0; column < part.image.width; ++column) {
                const std::size_t at = std::size_t(part.y + row) * width + part.x + column;
                if (source[at]) {
                    std::fprintf(stderr, "stitch: pixel %d,%d is in both %s and %s\n",
                                 part.x + column, part.y + row, source[at]->file.c_str(),
                                 part.file.c_str());
                    return 1;
                }
                source[at] = &part;
                for (int c = 0; c < 4; ++c)
                    whole.rgba[at * 4 + c] =
                        part.image.rgba[(std::size_t(row) * part.image.width + column) * 4 + c];
            }
    for (std::size_t at = 0; at < source.size(); ++at)
        if (!source[at]) {
            std::fprintf(stderr, "stitch: pixel %zu,%zu of the %dx%d image is in no part\n",
                         at % std::size_t(width), at / std::size_t(width), width, height);
            return 1;
        }
    writePng(output, whole);
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    try {
        return stitch(argc, argv);
    } catch (const tool_arguments::UsageError& error) {
        std::fprintf(stderr, "stitch: %s\n%s", error.what(), usage);
        return 2;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "stitch: %s\n", error.what());
        return 2;
    }
}
