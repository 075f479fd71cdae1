"""ccache's settings for the trees the tools build (tools/bug-zoo's copy of the project,
tools/exercise's workspaces), one copy for both: they share one cache with the release stage of
tools/run-tests (RT_CCACHE_DIR), whose own settings must stay these for objects to be shared.

- Paths are hashed relative to the tree (CCACHE_BASEDIR), and the options that only change
  warnings are left out of the hash (CCACHE_IGNOREOPTIONS), so that the same code built in
  another folder, with or without warnings as errors, finds the same objects.
- A header's hash is kept by its inode, size and times (CCACHE_INODECACHE): read once, not once
  per file that includes it (tools/exercise verify ch07 with every object cached: 35 s of
  processor time without, 28 s with). A rewritten file has new times, so a mistake or a stub
  written into a header is hashed afresh.
"""
import os

SLOPPINESS = "pch_defines,time_macros,include_file_mtime,include_file_ctime"


def environment(tree, ignored_options="-Werror"):
    """The variables to add to a build's environment of the tree at `tree`."""
    return dict(CCACHE_BASEDIR=os.path.abspath(tree), CCACHE_IGNOREOPTIONS=ignored_options,
                CCACHE_SLOPPINESS=SLOPPINESS, CCACHE_INODECACHE="true")
