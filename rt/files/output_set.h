// The files one run writes, all or none.
// Each output is written in full to a temporary file beside its target ("<target>.tmp.<pid>.<n>":
// the same folder, so the same file system, where a rename replaces the target in one step).
// Only when every output is written does commit() rename them onto their targets, in the order
// they were added. So a failure or an interrupt before commit() leaves every old file exactly as
// it was and no temporary file (an interrupt removes them: interrupt.h); and a reader who sees
// the last file added (a run adds its --stats-out record last) sees every other one complete.
//
// commit() is the one window left: n renames, each atomic, not all together. What covers it:
//  - Before the first rename, each existing target gets a second name, a hard link
//    "<target>.old.<pid>.<n>", so its old bytes stay reachable (and the target is never missing).
//  - When a rename fails, the renames made are undone (each old file renamed back from its
//    second name, a target that did not exist removed again), the temporary files removed, and
//    the error names the file, the reason, and any file it could not put back.
//  - An interrupting signal during commit() waits (interrupts_held). One arriving before the last
//    rename is treated as a failure: the renames made are undone, then the process dies of it.
//    One arriving later (during the last rename, or the removal of the second names) ends the
//    process once the commit is complete: the outputs are all new, the exit code still 128 + N.
//  - Not covered: the process killed outright (SIGKILL, power lost) between two renames leaves
//    some targets new, some old, and second names beside them; on a file system without hard
//    links (FAT) an old file cannot be kept, so a failed rename there cannot undo the renames
//    before it (the error names them). Both windows last a few system calls.
// While a set lives, the old and the new outputs are on disk together: room is needed for both.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "rt/files/interrupt.h"

namespace rt {

// The bytes of one output, into its temporary file (a POSIX descriptor: the reason of a failed
// write is its errno). A failed append is remembered, not thrown: stb_image_write, a C library,
// calls append() through a callback, and no exception may cross it. output_set reports it.
class temporary_file {
  public:
    void append(const void* data, std::size_t size);

  private:
    friend class output_set;
    explicit temporary_file(int descriptor) : fd(descriptor) {}
    int fd;
    int error = 0;  // errno of the first failure, 0 if none
};

class output_set {
  public:
    // The most files one set writes: one guard each in the interrupt handler's table.
    static constexpr int max_files = max_removed_on_interrupt;

    output_set() = default;
    // Removes every temporary file not renamed onto its target: a set dropped without commit()
    // (an exception, a refusal) changes nothing.
    ~output_set();
    output_set(const output_set&)            = delete;
    output_set& operator=(const output_set&) = delete;

    // Writes one output: `write` fills the temporary file beside `path`; it may throw. Throws
    // user_error naming `path` and the reason ("cannot write 'a.png': File too large") when the
    // file cannot be created or written, or when the set holds max_files already; the set then
    // holds what it held before. The same path may come twice: the later one wins.
    void add(const std::string& path, const std::function<void(temporary_file&)>& write);

    // Renames every temporary file onto its target, in the order added: all or none (above).
    // Throws user_error naming the file and the reason when a rename fails.
    void commit();

    // The temporary files written so far, in the order added (for tests).
    std::vector<std::string> temporary_paths() const;

  private:
    struct entry {
        std::string target, temporary;
        removed_on_interrupt guard;  // removes `temporary` on an interrupt while it lives
    };
    std::vector<entry> entries;
};

}  // namespace rt
