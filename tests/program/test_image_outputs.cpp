// Tests of image_outputs.h: an image written as a run's output is refused before anything is
// written when its path is bad, replaces the old file only when complete, and leaves the old file
// as it was when it cannot be written.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "rt/core/error.h"
#include "rt/files/image_outputs.h"
#include "rt/image/image_io.h"
#include "test_helpers.h"

namespace {
namespace fs = std::filesystem;
using rt_test::read_bytes, rt_test::same_bits, rt_test::temp_folder, rt_test::varied_image,
    rt_test::write_bytes;
}  // namespace

TEST_CASE("image_outputs: writing into a missing folder throws and creates nothing", "[program]") {
    temp_folder dir("image_outputs", "missing");
    for (const char* name : {"no/such/folder/a.pfm", "no/a.png"}) {
        INFO(name);
        CHECK_THROWS_AS(rt::write_image(dir.file(name), varied_image(2, 2)), rt::user_error);
        CHECK_THROWS_WITH(rt::write_image(dir.file(name), varied_image(2, 2)),
                          Catch::Contains("does not exist"));
    }
    CHECK(dir.entries().empty());
}

TEST_CASE("image_outputs: an unknown extension throws and creates nothing", "[program]") {
    temp_folder dir("image_outputs", "extension");
    for (const char* name : {"a.jpg", "a.tif", "a", "a.pfm.txt"}) {
        INFO(name);
        CHECK_THROWS_AS(rt::write_image(dir.file(name), varied_image(2, 2)), rt::user_error);
        CHECK_FALSE(rt::output_path_problem(dir.file(name)).empty());
    }
    CHECK(dir.entries().empty());
    CHECK(rt::output_path_problem(dir.file("a.pfm")).empty());
    CHECK(rt::output_path_problem(dir.file("a.png")).empty());
    CHECK(rt::output_path_problem(dir.file("a.exr")).empty());
}

TEST_CASE("image_outputs: an existing file is replaced on success and left intact on failure",
          "[program]") {
    temp_folder dir("image_outputs", "replace");
    for (const char* name : {"out.pfm", "out.png", "out.exr"}) {
        INFO(name);
        const std::string path = dir.file(name);

        // Success: the new image replaces the old file, and no temporary is left beside it.
        write_bytes(path, "old contents");
        rt::write_image(path, varied_image(3, 2));
        CHECK(read_bytes(path) != "old contents");
        if (std::string(name) != "out.png")
            CHECK(same_bits(rt::read_exact_image(path), varied_image(3, 2)));
        CHECK(dir.entries() == std::vector<std::string>{name});

        // Failure: the temporary file cannot be created (a folder, not empty, sits where
        // write_image puts it: path + ".tmp." + pid + ".0", see output_set.h). The write must
        // throw, name the file and the reason, and leave the old file as it was.
        write_bytes(path, "old contents");
        const std::string blocker = path + ".tmp." + std::to_string(::getpid()) + ".0";
        fs::create_directory(blocker);
        write_bytes(blocker + "/keep", "x");
        CHECK_THROWS_WITH(
            rt::write_image(path, varied_image(3, 2)),
            "cannot write '" + path + "': Is a directory (creating '" + blocker + "')");
        CHECK(read_bytes(path) == "old contents");
        CHECK(read_bytes(blocker + "/keep") == "x");
        fs::remove_all(blocker);
        fs::remove(path);
    }

    // A folder where the file should go is refused, and left alone with what it holds.
    fs::create_directory(dir.file("folder.pfm"));
    write_bytes(dir.file("folder.pfm/inside"), "kept");
    CHECK_THROWS_AS(rt::write_image(dir.file("folder.pfm"), varied_image(3, 2)), rt::user_error);
    CHECK(fs::is_directory(dir.file("folder.pfm")));
    CHECK(read_bytes(dir.file("folder.pfm/inside")) == "kept");
    CHECK(dir.entries() == std::vector<std::string>{"folder.pfm"});
}
