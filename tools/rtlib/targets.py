"""A chapter's targets (its CTest entries) run one at a time, as a student meets them: which
entries a chapter has, which programs they need built, how to run one under a time limit, and
the line of its output a student reads first. tools/bug-zoo and tools/exercise share them.

A test is a tuple (name, labels, command, working folder, environment), as chapter_tests
lists it from CTest.
"""
import concurrent.futures
import json
import os
import re
import signal
import subprocess
import threading
import time


def chapter_tests(tree, chapter):
    """The CTest entries of the build tree labelled chapter (chNN), in CTest's order."""
    listed = subprocess.run(["ctest", "--test-dir", tree, "--show-only=json-v1",
                             "-L", f"^{chapter}$"], capture_output=True, text=True,
                            check=True).stdout
    found = []
    for test in json.loads(listed).get("tests", []):
        props = {p["name"]: p["value"] for p in test.get("properties", [])}
        found.append((test["name"], props.get("LABELS", []), test.get("command", []),
                      props.get("WORKING_DIRECTORY", tree), props.get("ENVIRONMENT", [])))
    return found


def chapter_targets(src, tree, chapter, program):
    """What a chapter's targets run: its program, its test executable, and every program of the
    build tree their commands name (the build targets to make before running them)."""
    names = {program, "noise_compare"}
    if os.path.isdir(os.path.join(src, "tests", chapter)):
        names.add(f"tests_{chapter}")
    for _, _, command, _, _ in chapter_tests(tree, chapter):
        for word in command:
            # (a folder of the tree, which a script takes as its argument, is no target)
            if (word.startswith(tree + os.sep) and "CMakeFiles" not in word
                    and not os.path.isdir(word)):
                base = os.path.basename(word)
                if re.fullmatch(r"[A-Za-z0-9_]+", base):
                    names.add(base)
    return sorted(names)


def rank(test):
    """Unit tests of the chapter's test executable first (the most telling messages), then its
    other unit targets (command lines, scripts), its hard cases, and the golden image last."""
    name, labels = test[0], test[1]
    if "golden" in labels:
        return 3
    if "hardcase" in labels:
        return 2
    return 0 if re.match(r"ch\d\d:", name) else 1


def order(tests):
    return sorted(tests, key=rank)


def first_message(output):
    """The line a student reads first in a failing target's output."""
    lines = [l.rstrip() for l in output.splitlines()]
    for i, line in enumerate(lines):
        if re.search(r": FAILED:$", line):
            # Catch2: the assertion, its expansion and the messages attached to it.
            where = os.path.basename(line.split(": FAILED:")[0])
            rest = []
            for follow in lines[i + 1:i + 12]:
                if not follow.strip() or follow.startswith("----") or follow.startswith("===="):
                    if rest:
                        break
                    continue
                if follow.strip() in ("with expansion:", "with messages:", "with message:"):
                    continue
                rest.append(follow.strip())
            return shorten(f"{where}: " + " / ".join(rest))
        if re.search(r": FAILED:|due to unexpected exception", line):
            return shorten(" ".join(l.strip() for l in lines[i:i + 3]))
    for line in lines:
        if re.match(r"(FAIL|error|.*: error:)", line.strip(), re.I):
            return shorten(line.strip())
    text = [l.strip() for l in lines if l.strip()]
    return shorten(text[-1]) if text else "(no output)"


def shorten(text, limit=200):
    text = re.sub(r"\s+", " ", text)
    return text if len(text) <= limit else text[:limit - 3] + "..."


def default_signals():
    """In a target's process, before it starts: the interrupt signals back to their default
    action, as CTest gives them. A run started in the background (`&`, nohup) ignores SIGINT or
    SIGHUP, the target would inherit that, and the tests of what an interrupt does would see a
    program that ignores it."""
    for number in (signal.SIGINT, signal.SIGHUP, signal.SIGTERM, signal.SIGQUIT):
        signal.signal(number, signal.SIG_DFL)


def run_test(test, timeout, env):
    """(passed, seconds, message, output). A golden image is judged by the noise statistic alone
    (RT_GOLDEN_NOISE_ONLY): the judgement a correct render of other code passes."""
    name, _, command, cwd, extra = test
    test_env = dict(env)
    test_env["RT_GOLDEN_NOISE_ONLY"] = "1"
    for item in extra:
        key, _, value = item.partition("=")
        test_env[key] = value
    start = time.monotonic()
    process = subprocess.Popen(command, cwd=cwd, env=test_env, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, start_new_session=True,
                               preexec_fn=default_signals)
    try:
        output, _ = process.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        process.communicate()
        return (False, timeout, f"did not finish within the time limit of {timeout} s (a hang)",
                "")
    seconds = time.monotonic() - start
    text = output.decode(errors="replace")
    if process.returncode == 0:
        return True, seconds, "", text
    if process.returncode < 0:
        return False, seconds, shorten(f"crashed (signal {-process.returncode}): "
                                       f"{first_message(text)}"), text
    return False, seconds, first_message(text), text


def failures(tests, timeout, jobs, env, stop_early):
    """[(name, message)] of the targets that fail, in order. Runs `jobs` at a time; with
    stop_early, starts nothing after a failure is known, and without it nothing after a hang."""
    stop, hung = threading.Event(), threading.Event()

    def one(test):
        # After a hang nothing more starts either way: each further hang would cost the limit.
        if (stop_early and stop.is_set()) or hung.is_set():
            return None
        result = run_test(test, timeout, env)
        if not result[0]:
            stop.set()
            if result[1] >= timeout:
                hung.set()
        return result

    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        results = list(pool.map(one, tests))
    return [(test[0], result[2]) for test, result in zip(tests, results)
            if result is not None and not result[0]]
