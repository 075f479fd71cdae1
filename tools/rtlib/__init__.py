"""What the Python tools share, one copy each:

  rtlib.pfm         PFM images: read, write and encode (either byte order, the bottom row
                    first on disk)
  rtlib.provenance  where a measurement was made: the machine, the compiler of a build, and the
                    commit a build or the tree is at (and whether its sources differ from it)
  rtlib.report_html the HTML report: its page from the Markdown report, its image comparisons
                    and the maps of where two images differ
  rtlib.browser     a headless Chromium driven through its DevTools protocol (the HTML
                    report's test)
  rtlib.compiler_cache  ccache's settings for the trees tools/bug-zoo and tools/exercise
                    build (one cache with the release stage's)

A tool finds this package beside itself, from any working directory, and writes no bytecode
into the tree:

    sys.dont_write_bytecode = True
    sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
    from rtlib import pfm, provenance
"""
