"""Where a measurement was made, for the records the tools write beside their numbers: the
machine, the compiler of a build, and the commit a build or the tree is at, with the sources
that differ from it.

  machine()                the processor, cores, system and host
  compiler(build)          the C++ compiler, build type, flags and scalar of a CMake build folder
  source_of(build)         the source folder a build was configured from
  tree_state(source)       its commit, and which of BUILD_SOURCES differ from that commit

Also a command line, for the shell tools:

  provenance.py commit [--source DIR] [--abbrev N] [--mark TEXT]   the commit, TEXT appended
                                                                   when the sources differ
  provenance.py cpu                                                the processor's name
"""
import argparse
import os
import platform
import subprocess
import sys
from typing import NamedTuple

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.realpath(__file__))))
# What the measured programs are compiled from: a change here changes what a tool measures.
# (tests/ is compiled too, but no tool measures a test.)
BUILD_SOURCES = ("CMakeLists.txt", "CMakePresets.json", "cmake", "rt", "chapters",
                 "tools/merge_parts", "bench")


def cpu():
    """The processor's model name, as /proc/cpuinfo gives it."""
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


def machine():
    """cpu, cores (logical CPUs), system ("Linux 6.1.0-..."), platform (Python's longer
    platform.platform()) and host."""
    return {"cpu": cpu(), "cores": os.cpu_count(),
            "system": f"{platform.system()} {platform.release()}",
            "platform": platform.platform(), "host": platform.node()}


def cmake_cache(build):
    """The variables of build/CMakeCache.txt, by name without their type ({} without one)."""
    cache = {}
    try:
        with open(os.path.join(build, "CMakeCache.txt")) as f:
            for line in f:
                if "=" in line and not line.startswith(("#", "//")):
                    key, value = line.rstrip("\r\n").split("=", 1)
                    cache[key.split(":", 1)[0]] = value
    except OSError:
        pass
    return cache


def compiler(build):
    """compiler (the first line of its --version, or its path), path, build_type, flags (the
    general and the build type's CMAKE_CXX_FLAGS) and scalar (RT_SCALAR; None when the build
    folder does not say)."""
    cache = cmake_cache(build)
    path = cache.get("CMAKE_CXX_COMPILER")
    name = "unknown compiler"
    if path:
        try:
            version = subprocess.run([path, "--version"], capture_output=True,
                                     text=True).stdout.splitlines()
            name = version[0] if version else path
        except OSError:
            name = path
    build_type = cache.get("CMAKE_BUILD_TYPE", "")
    flags = " ".join(f for f in (cache.get("CMAKE_CXX_FLAGS", ""),
                                 cache.get(f"CMAKE_CXX_FLAGS_{build_type.upper()}", "")) if f)
    return {"compiler": name, "path": path, "build_type": build_type, "flags": flags,
            "scalar": cache.get("RT_SCALAR")}


def source_of(build):
    """The source folder the build folder was configured from, or None."""
    return cmake_cache(build).get("CMAKE_HOME_DIRECTORY")


class TreeState(NamedTuple):
    commit: str  # "unknown" when neither git nor a .commit file says
    changed: list  # the BUILD_SOURCES paths with uncommitted changes (tracked files only)

    def label(self, mark):
        """The commit, with mark appended when sources differ from it."""
        return self.commit + (mark if self.changed else "")


def tree_state(source=ROOT, abbrev=None):
    """The commit the source folder is at (abbreviated to at least abbrev hex digits, or in
    full), and its uncommitted changes to BUILD_SOURCES."""
    def git(*words):
        try:
            done = subprocess.run(["git", "-C", source, *words], capture_output=True, text=True)
        except OSError:
            return None
        return done.stdout if done.returncode == 0 else None

    top = git("rev-parse", "--show-toplevel")
    # Only the source's own checkout counts: a copy unpacked under build/ sits inside another.
    if top and os.path.realpath(top.strip()) == os.path.realpath(source):
        head = git("rev-parse", f"--short={abbrev}" if abbrev else "--verify", "HEAD")
        if head:
            status = git("status", "--porcelain", "--untracked-files=no", "--",
                         *BUILD_SOURCES) or ""
            return TreeState(head.strip(), [line[3:] for line in status.splitlines()
                                            if line.strip()])
    # A copy made with `git archive COMMIT | tar -x` has no .git; its maker may leave the
    # commit in a file .commit at its root.
    try:
        with open(os.path.join(source, ".commit")) as f:
            commit = f.read().strip()
            return TreeState(commit[:abbrev] if abbrev else commit, [])
    except OSError:
        return TreeState("unknown", [])


def main(argv):
    parser = argparse.ArgumentParser(prog="provenance.py", description=__doc__.split("\n\n")[0])
    sub = parser.add_subparsers(dest="what", required=True)
    commit = sub.add_parser("commit", help="the commit the tree is at")
    commit.add_argument("--source", default=ROOT, help="the source folder (this repository)")
    commit.add_argument("--abbrev", type=int, help="at least this many hex digits (all)")
    commit.add_argument("--mark", default="", help="appended when BUILD_SOURCES differ")
    sub.add_parser("cpu", help="the processor's name")
    args = parser.parse_args(argv)
    if args.what == "commit":
        print(tree_state(args.source, args.abbrev).label(args.mark))
    else:
        print(cpu())
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
