// Tests for output_set.h (chapter 01): a run's files are written all or none. Nothing reaches a
// target before commit(); a failure (a file that cannot be created or written, a rename that
// fails) or an interrupt leaves every old file as it was and no temporary file; commit() renames
// them all. tests/cli/write_failure.sh and tests/cli/interrupt.sh check the same of whole runs.
#include <sys/resource.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <csignal>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "child_process.h"
#include "rt/core/error.h"
#include "rt/files/output_set.h"
#include "test_helpers.h"

namespace {

namespace fs = std::filesystem;
using rt_test::child_ends, rt_test::read_bytes, rt_test::temp_folder, rt_test::write_bytes;

// A writer of these bytes, for output_set::add.
std::function<void(rt::temporary_file&)> bytes(const std::string& text) {
    return [text](rt::temporary_file& file) { file.append(text.data(), text.size()); };
}

}  // namespace

TEST_CASE("output_set: nothing reaches a target before commit(), which renames every file",
          "[program]") {
    temp_folder dir("output_set", "commit");
    const std::string a = dir.file("a.png"), b = dir.file("b.pfm"), c = dir.file("c.json");
    write_bytes(a, "old a");
    write_bytes(c, "old c");
    rt::output_set set;
    set.add(a, bytes("new a"));
    set.add(b, bytes("new b"));
    set.add(c, bytes("new c"));

    // Written in full, each beside its target, under a name of this process.
    const std::vector<std::string> temporaries = set.temporary_paths();
    REQUIRE(temporaries.size() == 3);
    CHECK(read_bytes(temporaries[0]) == "new a");
    CHECK(read_bytes(temporaries[1]) == "new b");
    CHECK(read_bytes(temporaries[2]) == "new c");
    for (const auto& t : temporaries) {
        CHECK(fs::path(t).parent_path() == dir.path());
        CHECK(t.find(".tmp." + std::to_string(::getpid()) + ".") != std::string::npos);
    }
    CHECK(read_bytes(a) == "old a");
    CHECK_FALSE(fs::exists(b));
    CHECK(read_bytes(c) == "old c");

    set.commit();
    CHECK(read_bytes(a) == "new a");
    CHECK(read_bytes(b) == "new b");
    CHECK(read_bytes(c) == "new c");
    // No temporary file, and no second name of an old file, is left.
    CHECK(dir.entries() == std::vector<std::string>{"a.png", "b.pfm", "c.json"});
}

TEST_CASE("output_set: a set dropped without commit() changes nothing and leaves nothing",
          "[program]") {
    temp_folder dir("output_set", "dropped");
    write_bytes(dir.file("a.png"), "old a");
    {
        rt::output_set set;
        set.add(dir.file("a.png"), bytes("new a"));
        set.add(dir.file("b.png"), bytes("new b"));
        CHECK(dir.entries().size() == 3);  // a.png and two temporary files
    }
    CHECK(read_bytes(dir.file("a.png")) == "old a");
    CHECK(dir.entries() == std::vector<std::string>{"a.png"});
}

TEST_CASE(
    "output_set: a file that cannot be created is refused by name and reason, and the "
    "files written before it never reach their targets",
    "[program]") {
    temp_folder dir("output_set", "cannot_create");
    const std::string a = dir.file("a.png"), b = dir.file("missing/b.png");
    write_bytes(a, "old a");
    {
        rt::output_set set;
        set.add(a, bytes("new a"));
        const std::string temporary = b + ".tmp." + std::to_string(::getpid()) + ".1";
        CHECK_THROWS_WITH(
            set.add(b, bytes("new b")),
            "cannot write '" + b + "': No such file or directory (creating '" + temporary + "')");
        CHECK(set.temporary_paths().size() == 1);  // the set holds what it held before
    }
    CHECK(read_bytes(a) == "old a");
    CHECK(dir.entries() == std::vector<std::string>{"a.png"});
}

TEST_CASE("output_set: a writer that throws leaves no temporary file", "[program]") {
    temp_folder dir("output_set", "writer_throws");
    rt::output_set set;
    set.add(dir.file("a.png"), bytes("new a"));
    auto failing = [](rt::temporary_file& file) {
        file.append("half", 4);
        throw rt::user_error("the encoder failed");
    };
    CHECK_THROWS_WITH(set.add(dir.file("b.png"), failing), "the encoder failed");
    CHECK(set.temporary_paths().size() == 1);
    CHECK(dir.entries().size() == 1);  // a.png's temporary file alone
}

TEST_CASE("output_set: a write cut short (a full disk) is refused with its reason", "[program]") {
    temp_folder dir("output_set", "cut_short");
    const std::string a = dir.file("a.png"), b = dir.file("b.pfm");
    write_bytes(a, "old a");
    write_bytes(b, "old b");
    // In a child: a file size limit of 1 KiB (with SIGXFSZ ignored, write() fails with EFBIG, as
    // it fails with ENOSPC on a full disk). Exit 10: refused with the reason; 11: another message.
    const std::string ends = child_ends([&] {
        std::signal(SIGXFSZ, SIG_IGN);
        rlimit limit{1024, 1024};
        if (setrlimit(RLIMIT_FSIZE, &limit) != 0) _exit(12);
        int code = 0;
        try {
            rt::output_set set;  // gone, with its temporary files, before the catch
            set.add(a, bytes("new a"));
            set.add(b, bytes(std::string(4096, 'b')));
        } catch (const rt::user_error& e) {
            code = std::string(e.what()) == "cannot write '" + b + "': File too large" ? 10 : 11;
        }
        _exit(code);
    });
    CHECK(ends == "exit 10");
    CHECK(read_bytes(a) == "old a");
    CHECK(read_bytes(b) == "old b");
    CHECK(dir.entries() == std::vector<std::string>{"a.png", "b.pfm"});
}

TEST_CASE("output_set: a rename that fails in commit() undoes the renames before it", "[program]") {
    temp_folder dir("output_set", "rename_fails");
    const std::string a = dir.file("a.png"), b = dir.file("b.pfm"), c = dir.file("c.json");
    write_bytes(a, "old a");  // b does not exist
    rt::output_set set;
    set.add(a, bytes("new a"));
    set.add(b, bytes("new b"));
    set.add(c, bytes("new c"));
    // Between the writes and the renames, a folder (not empty) takes c's place: no file can be
    // renamed onto it.
    fs::create_directory(c);
    write_bytes(c + "/inside", "kept");
    const std::string c_temporary = set.temporary_paths()[2];
    CHECK_THROWS_WITH(set.commit(), "cannot write '" + c + "': Is a directory (renaming '" +
                                        c_temporary +
                                        "' onto it); the outputs renamed before it were put back "
                                        "as they were");
    CHECK(read_bytes(a) == "old a");
    CHECK_FALSE(fs::exists(b));
    CHECK(read_bytes(c + "/inside") == "kept");
    CHECK(dir.entries() == std::vector<std::string>{"a.png", "c.json"});
}

TEST_CASE("output_set: the same path given twice ends with the later file", "[program]") {
    temp_folder dir("output_set", "twice");
    const std::string a = dir.file("a.pfm");
    write_bytes(a, "old");
    rt::output_set set;
    set.add(a, bytes("first"));
    set.add(dir.file("./a.pfm"), bytes("second"));
    set.commit();
    CHECK(read_bytes(a) == "second");
    CHECK(dir.entries() == std::vector<std::string>{"a.pfm"});
}

TEST_CASE("output_set: at most max_files files, one more is refused", "[program]") {
    temp_folder dir("output_set", "too_many");
    {
        rt::output_set set;
        for (int i = 0; i < rt::output_set::max_files; ++i)
            set.add(dir.file(std::to_string(i) + ".png"), bytes("x"));
        CHECK_THROWS_WITH(set.add(dir.file("one_more.png"), bytes("x")),
                          Catch::Contains("a run writes at most " +
                                          std::to_string(rt::output_set::max_files) + " files"));
    }
    CHECK(dir.entries().empty());
}

TEST_CASE(
    "output_set: an interrupt while the second file is written keeps both old files and "
    "leaves no temporary file",
    "[program]") {
    for (int s : {SIGINT, SIGTERM, SIGHUP}) {
        INFO("signal " << s);
        temp_folder dir("output_set", "interrupt_" + std::to_string(s));
        const std::string a = dir.file("a.png"), b = dir.file("b.pfm");
        write_bytes(a, "old a");
        write_bytes(b, "old b");
        const std::string ends = child_ends([&] {
            rt::output_set set;
            set.add(a, bytes("new a"));
            set.add(b, [s](rt::temporary_file& file) {
                file.append("half of b", 9);
                std::raise(s);
            });
            _exit(3);  // only if the signal did not end the child
        });
        CHECK(ends == rt_test::killed_by(s));
        CHECK(read_bytes(a) == "old a");
        CHECK(read_bytes(b) == "old b");
        CHECK(dir.entries() == std::vector<std::string>{"a.png", "b.pfm"});
    }
}

TEST_CASE("output_set: after commit() an interrupt removes nothing", "[program]") {
    temp_folder dir("output_set", "interrupt_after");
    const std::string a = dir.file("a.png"), b = dir.file("b.pfm");
    const std::string ends = child_ends([&] {
        rt::output_set set;
        set.add(a, bytes("new a"));
        set.add(b, bytes("new b"));
        set.commit();
        std::raise(SIGTERM);
        _exit(3);
    });
    CHECK(ends == rt_test::killed_by(SIGTERM));
    CHECK(read_bytes(a) == "new a");
    CHECK(read_bytes(b) == "new b");
    CHECK(dir.entries() == std::vector<std::string>{"a.png", "b.pfm"});
}
