// Shader experiments without a window: --dump-shaders writes the embedded sources, a
// folder of them (--shader-dir) compiles to the same kernel and renders the same bytes,
// a compile error names the folder's file and line, and the file watch the window polls
// notices saves of a file and of a folder.
#include "base/file_watch.h"
#include "gpu/shader_compiler.h"
#include "render/kernel_sources.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>

namespace {

std::filesystem::path showcase() {
    return std::filesystem::path(PROJECT_SCENES_DIR) / "showcase.scene";
}

void appendText(const std::filesystem::path& path, const std::string& text) {
    std::ofstream file(path, std::ios::app);
    file << text;
}

TEST(ShaderDirectory, DumpedSourcesCompileToTheEmbeddedKernel) {
    const std::filesystem::path dir = freshOutputDir("shader-dir/compile");
    writeEmbeddedShaders(dir / "shaders");
    EXPECT_TRUE(std::filesystem::exists(dir / "shaders" / "trace.comp"));
    EXPECT_TRUE(std::filesystem::exists(dir / "shaders" / "shared.h"));
    EXPECT_EQ(compileComputeShader("trace.comp", directoryShaderLoader(dir / "shaders")),
              compileComputeShader("trace.comp", embeddedShaderLoader()));
    // Includes resolve inside the folder only.
    EXPECT_FALSE(directoryShaderLoader(dir / "shaders")("../shaders/trace.comp"));
}

TEST(ShaderDirectory, RendersTheSameBytesAsTheEmbeddedKernel) {
    const std::filesystem::path dir = freshOutputDir("shader-dir/render");
    ProcessResult dump = runRaytracer({"--dump-shaders", (dir / "shaders").string()});
    ASSERT_EQ(dump.exitCode, 0) << dump.err;
    const std::vector<std::string> size = {"--width", "64", "--height", "48", "--spp", "2"};
    std::vector<std::string> embedded = {showcase().string(), "-o",
                                         (dir / "embedded.png").string()};
    std::vector<std::string> folder = {showcase().string(),           "-o",
                                       (dir / "folder.png").string(), "--shader-dir",
                                       (dir / "shaders").string(),    "--validate"};
    embedded.insert(embedded.end(), size.begin(), size.end());
    folder.insert(folder.end(), size.begin(), size.end());
    ASSERT_EQ(runRaytracer(embedded).exitCode, 0);
    ProcessResult run = runRaytracer(folder);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_FALSE(hasValidationMessage(run)) << run.err;
    EXPECT_EQ(readPng(dir / "embedded.png").rgba, readPng(dir / "folder.png").rgba);
}

TEST(ShaderDirectory, CompileErrorNamesTheFolderFileAndLine) {
    const std::filesystem::path dir = freshOutputDir("shader-dir/error");
    writeEmbeddedShaders(dir / "shaders");
    appendText(dir / "shaders" / "shade.glsl", "\nnot glsl at all\n");
    ProcessResult run =
        runRaytracer({showcase().string(), "-o", (dir / "out.png").string(), "--width", "16",
                      "--height", "16", "--shader-dir", (dir / "shaders").string()});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.err.find("ERROR: " + (dir / "shaders" / "shade.glsl").string() + ":"),
              std::string::npos)
        << run.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

TEST(ShaderDirectory, MissingFolderIsAnError) {
    const std::filesystem::path dir = freshOutputDir("shader-dir/missing");
    ProcessResult run =
        runRaytracer({showcase().string(), "-o", (dir / "out.png").string(), "--width", "16",
                      "--height", "16", "--shader-dir", (dir / "nowhere").string()});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(
        run.err.find(
            "error: --shader-dir expects a folder holding trace.comp (see --dump-shaders), got '" +
            (dir / "nowhere").string() + "'"),
        std::string::npos)
        << run.err;
}

TEST(FileWatch, NoticesASavedFileOnce) {
    const std::filesystem::path dir = freshOutputDir("file-watch/file");
    writeTextFile(dir / "a.scene", "one");
    FileWatch watch = watchPath(dir / "a.scene");
    EXPECT_FALSE(pathChanged(watch));
    writeTextFile(dir / "a.scene", "three"); // another size, whatever the clock's resolution
    EXPECT_TRUE(pathChanged(watch));
    EXPECT_FALSE(pathChanged(watch));
    std::filesystem::remove(dir / "a.scene");
    EXPECT_TRUE(pathChanged(watch)); // gone: the reload reports the missing file
    EXPECT_EQ(pathSignature(dir / "a.scene"), 0u);
}

TEST(FileWatch, NoticesAnyFileOfAFolder) {
    const std::filesystem::path dir = freshOutputDir("file-watch/folder");
    writeTextFile(dir / "a.glsl", "a");
    writeTextFile(dir / "b.glsl", "b");
    FileWatch watch = watchPath(dir);
    EXPECT_FALSE(pathChanged(watch));
    appendText(dir / "b.glsl", "more");
    EXPECT_TRUE(pathChanged(watch));
    writeTextFile(dir / "c.glsl", "new file");
    EXPECT_TRUE(pathChanged(watch));
    std::filesystem::rename(dir / "c.glsl", dir / "d.glsl"); // same content, new name
    EXPECT_TRUE(pathChanged(watch));
    EXPECT_FALSE(pathChanged(watch));
}

TEST(FileWatch, SameSizeRewriteIsNoticedThroughTheModificationTime) {
    const std::filesystem::path dir = freshOutputDir("file-watch/mtime");
    writeTextFile(dir / "a.scene", "abc");
    const auto written = std::filesystem::last_write_time(dir / "a.scene");
    FileWatch watch = watchPath(dir / "a.scene");
    writeTextFile(dir / "a.scene", "xyz");
    // Two seconds on, past any file system's timestamp granularity, however fast the
    // rewrite was.
    std::filesystem::last_write_time(dir / "a.scene", written + std::chrono::seconds(2));
    EXPECT_TRUE(pathChanged(watch));
}

} // namespace
