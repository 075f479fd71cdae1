#include "rt/files/output_set.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>
#include <utility>

#include "rt/core/error.h"

namespace rt {

namespace {

// The system's text for an errno ("No such file or directory"), as strerror gives it but
// thread-safe.
std::string reason(int error_number) {
    return std::error_code(error_number, std::generic_category()).message();
}

// What commit() did with a target's old file before the renames.
struct old_file {
    enum { absent, kept, not_kept } how = absent;
    std::string second_name;  // the hard link holding it, when kept
    int error = 0;            // why it could not be kept
};

}  // namespace

void temporary_file::append(const void* data, std::size_t size) {
    const char* bytes = static_cast<const char*>(data);
    while (error == 0 && size > 0) {
        const ssize_t written = ::write(fd, bytes, size);
        if (written < 0 && errno == EINTR) continue;
        if (written <= 0) {
            error = written < 0 ? errno : EIO;  // 0 bytes for a regular file: nothing will go
            return;
        }
        bytes += written;
        size -= std::size_t(written);
    }
}

output_set::~output_set() {
    for (const entry& e : entries) ::unlink(e.temporary.c_str());
}

void output_set::add(const std::string& path, const std::function<void(temporary_file&)>& write) {
    if (entries.size() >= std::size_t(max_files))
        throw user_error("cannot write '" + path + "': a run writes at most " +
                         std::to_string(max_files) + " files");
    entries.reserve(max_files);  // so that adding the entry below cannot fail once it is written
    std::string target = path;
    std::string temporary =
        path + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(entries.size());
    // Guarded before it exists, so that no moment of its life can leave it behind.
    removed_on_interrupt guard(temporary);
    // O_NOFOLLOW: a symbolic link planted at the temporary name is refused, never written through.
    const int fd =
        ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0666);
    if (fd < 0)
        throw user_error("cannot write '" + path + "': " + reason(errno) + " (creating '" +
                         temporary + "')");
    temporary_file file(fd);
    try {
        write(file);
    } catch (...) {
        ::close(fd);
        ::unlink(temporary.c_str());
        throw;
    }
    // close() can be where a network file system reports a failed write.
    if (::close(fd) != 0 && file.error == 0) file.error = errno;
    if (file.error != 0) {
        ::unlink(temporary.c_str());
        throw user_error("cannot write '" + path + "': " + reason(file.error));
    }
    entries.push_back(entry{std::move(target), std::move(temporary), std::move(guard)});
}

void output_set::commit() {
    interrupts_held hold;  // a signal now waits until the renames are all made or all undone
    const std::string pid = std::to_string(::getpid());
    const std::size_t n   = entries.size();

    // Every old target gets a second name first, so that a rename can be undone.
    std::vector<old_file> old(n);
    for (std::size_t i = 0; i < n; ++i) {
        old[i].second_name = entries[i].target + ".old." + pid + "." + std::to_string(i);
        if (::link(entries[i].target.c_str(), old[i].second_name.c_str()) == 0) {
            old[i].how = old_file::kept;
        } else if (errno != ENOENT) {
            old[i].how   = old_file::not_kept;
            old[i].error = errno;
        }
    }

    std::size_t done   = 0;
    int rename_error   = 0;
    bool a_signal_came = false;
    for (; done < n; ++done) {
        if (hold.arrived()) {
            a_signal_came = true;
            break;
        }
        if (::rename(entries[done].temporary.c_str(), entries[done].target.c_str()) != 0) {
            rename_error = errno;
            break;
        }
    }

    if (done == n) {
        for (const old_file& o : old)
            if (o.how == old_file::kept) ::unlink(o.second_name.c_str());
        entries.clear();  // nothing left to remove on an interrupt
        hold.end();       // a signal that came during the last rename ends the process now
        return;
    }

    // Undo, last first (a path given twice then ends with its oldest content).
    std::string not_undone;
    for (std::size_t j = done; j-- > 0;) {
        const std::string& target = entries[j].target;
        if (old[j].how == old_file::kept) {
            if (::rename(old[j].second_name.c_str(), target.c_str()) == 0)
                old[j].how = old_file::absent;  // its second name is its name again
            else
                not_undone += "; could not put back '" + target + "' (its old file is '" +
                              old[j].second_name + "'): " + reason(errno);
        } else if (old[j].how == old_file::absent) {
            if (::unlink(target.c_str()) != 0 && errno != ENOENT)
                not_undone += "; could not remove '" + target + "' again: " + reason(errno);
        } else {
            not_undone += "; '" + target + "' was replaced (its old file could not be kept: " +
                          reason(old[j].error) + ")";
        }
    }
    for (std::size_t i = done; i < n; ++i) {
        ::unlink(entries[i].temporary.c_str());
        if (old[i].how == old_file::kept) ::unlink(old[i].second_name.c_str());
    }
    if (a_signal_came) hold.end();  // the process dies of it here, every old file back in place

    const entry& failed = entries[done];
    std::string message = "cannot write '" + failed.target + "': " + reason(rename_error) +
                          " (renaming '" + failed.temporary + "' onto it)";
    if (done > 0)
        message += not_undone.empty() ? "; the outputs renamed before it were put back as they were"
                                      : not_undone;
    entries.clear();
    throw user_error(message);
}

std::vector<std::string> output_set::temporary_paths() const {
    std::vector<std::string> paths;
    for (const entry& e : entries) paths.push_back(e.temporary);
    return paths;
}

}  // namespace rt
