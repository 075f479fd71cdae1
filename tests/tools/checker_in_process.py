"""tools/check-render run in the test's own process. The checker's tests run it a few hundred
times, and as a process of its own it spends most of its time on a small image starting: the
Python interpreter and NumPy, then OpenImageIO's library and all it links (0.45 s of 0.8 s).
Its command line stays tested as a process by the bad-input entries."""
import contextlib
import functools
import importlib.machinery
import importlib.util
import io
import os

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.realpath(__file__))))
CHECK = os.path.join(ROOT, "tools", "check-render")


@functools.cache
def module():
    """tools/check-render as a module (loaded once): its Scene, renders, verdict and main."""
    loader = importlib.machinery.SourceFileLoader("check_render", CHECK)
    spec = importlib.util.spec_from_loader("check_render", loader)
    checker = importlib.util.module_from_spec(spec)
    loader.exec_module(checker)
    return checker


def run(args):
    """(exit code, standard output, standard error) of tools/check-render ARGS."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = module().main([str(a) for a in args])
        except SystemExit as stop:  # argparse's refusals and --help
            code = stop.code if isinstance(stop.code, int) else 2
    return code, out.getvalue(), err.getvalue()
