"""A headless Chromium driven through its DevTools protocol over a pair of pipes: enough of the
protocol to load a page, read values from it, take screenshots and move the mouse, for the tests
of the HTML report.

With --remote-debugging-pipe Chromium reads commands from its fd 3 and writes replies and events
to its fd 4, each message one JSON object ended by a NUL byte; so no websocket and no port, and
nothing but the standard library here.

    with browser.Browser() as b:
        b.open_page(1280, 900)
        b.navigate("file:///path/to/page.html")
        title = b.evaluate("document.title")
        png = b.screenshot(0, 0, 200, 100)   # document coordinates, CSS pixels

Every wait has a timeout; trouble of any kind (no browser, a start that fails, a command the
browser refuses, a wait that times out) raises BrowserError with one line saying what.
"""
import base64
import fcntl
import json
import os
import select
import shutil
import signal
import subprocess
import tempfile
import time

EXECUTABLES = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable")
START_TIMEOUT = 30.0    # seconds for the browser to answer its first command
COMMAND_TIMEOUT = 30.0  # seconds for any other reply
EXIT_TIMEOUT = 5.0      # seconds for the browser to exit after Browser.close, before it is killed


class BrowserError(Exception):
    """Anything that went wrong with the browser; the message is one line."""


def find_executable():
    """The path of the first Chromium on PATH, or None."""
    for name in EXECUTABLES:
        path = shutil.which(name)
        if path:
            return path
    return None


class Browser:
    """One headless Chromium with a fresh profile, and at most one page (a target attached in
    flat mode, so the page's messages carry its sessionId)."""

    def __init__(self, executable=None, extra_args=()):
        executable = executable or find_executable()
        if not executable:
            raise BrowserError(f"no browser found: none of {', '.join(EXECUTABLES)} is on PATH")
        self.profile = tempfile.mkdtemp(prefix="rt-browser-")
        self.log = open(os.path.join(self.profile, "stderr.txt"), "w+b")
        args = [executable, "--headless", "--disable-gpu", f"--user-data-dir={self.profile}",
                "--no-first-run", "--no-default-browser-check", "--remote-debugging-pipe",
                # Screenshots hold the image files' own values, whatever the machine's display.
                "--force-color-profile=srgb",
                *extra_args]
        if os.geteuid() == 0:
            args.append("--no-sandbox")  # Chromium refuses to start its sandbox as root
        args.append("about:blank")
        commands_read, self.commands = os.pipe()
        self.replies, replies_write = os.pipe()

        def to_fds_3_and_4():
            # Both ends move above 4 first, so that neither dup2 overwrites the other.
            high_read = fcntl.fcntl(commands_read, fcntl.F_DUPFD_CLOEXEC, 5)
            high_write = fcntl.fcntl(replies_write, fcntl.F_DUPFD_CLOEXEC, 5)
            os.dup2(high_read, 3)
            os.dup2(high_write, 4)

        try:
            self.process = subprocess.Popen(
                args, stdin=subprocess.DEVNULL, stdout=self.log, stderr=self.log,
                preexec_fn=to_fds_3_and_4, close_fds=False, start_new_session=True)
        except OSError as e:
            self.log.close()
            self._remove_profile()
            raise BrowserError(f"could not run {executable}: {e.strerror}") from None
        finally:
            os.close(commands_read)
            os.close(replies_write)
        self.buffer = b""
        self.next_id = 1
        self.events = []       # (method, params, sessionId) not yet taken by wait_event
        self.session = None
        try:
            self.version = self.send("Browser.getVersion", timeout=START_TIMEOUT)["product"]
        except BrowserError as e:
            self.close()
            raise BrowserError(f"{executable} did not start: {e}") from None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    # The protocol: one message out, messages in until the reply to it.

    def send(self, method, params=None, session=False, timeout=COMMAND_TIMEOUT):
        """The result of a command; session=True sends it to the page rather than the
        browser. Events that arrive meanwhile are kept for wait_event."""
        message = {"id": self.next_id, "method": method, "params": params or {}}
        self.next_id += 1
        if session:
            message["sessionId"] = self.session
        data = json.dumps(message).encode() + b"\0"
        try:
            while data:
                data = data[os.write(self.commands, data):]
        except BrokenPipeError:
            raise BrowserError(f"{method}: the browser has exited{self._last_words()}") from None
        deadline = time.monotonic() + timeout
        while True:
            reply = self._receive(deadline, method)
            if reply.get("id") == message["id"]:
                if "error" in reply:
                    raise BrowserError(f"{method}: {reply['error'].get('message')}")
                return reply.get("result", {})
            if "method" in reply:
                self.events.append((reply["method"], reply.get("params", {}),
                                    reply.get("sessionId")))

    def wait_event(self, method, timeout=COMMAND_TIMEOUT, predicate=lambda params: True):
        """The parameters of the first event of that name (of any session) that satisfies
        predicate, kept or yet to come; it is taken from the kept events."""
        deadline = time.monotonic() + timeout
        scanned = 0
        while True:
            for i in range(scanned, len(self.events)):
                name, params, _ = self.events[i]
                if name == method and predicate(params):
                    del self.events[i]
                    return params
            scanned = len(self.events)
            message = self._receive(deadline, f"waiting for {method}")
            if "method" in message:
                self.events.append((message["method"], message.get("params", {}),
                                    message.get("sessionId")))

    def pump(self, seconds):
        """Keeps the events that arrive within the next seconds."""
        deadline = time.monotonic() + seconds
        while True:
            try:
                message = self._receive(deadline, "")
            except TimeoutError:
                return
            if "method" in message:
                self.events.append((message["method"], message.get("params", {}),
                                    message.get("sessionId")))

    def take_events(self, methods):
        """The kept events whose names are in methods, as (name, params), in order of arrival;
        they are no longer kept."""
        taken = [(name, params) for name, params, _ in self.events if name in methods]
        self.events = [event for event in self.events if event[0] not in methods]
        return taken

    def _receive(self, deadline, what):
        while b"\0" not in self.buffer:
            left = deadline - time.monotonic()
            if left <= 0:
                if not what:
                    raise TimeoutError
                raise BrowserError(f"{what}: no answer within the time allowed")
            ready, _, _ = select.select([self.replies], [], [], left)
            if ready:
                chunk = os.read(self.replies, 1 << 20)
                if not chunk:
                    raise BrowserError(f"{what or 'reading'}: the browser has exited"
                                       f"{self._last_words()}")
                self.buffer += chunk
        message, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(message)

    def _last_words(self):
        """The last line the browser wrote, to say why it stopped."""
        self.log.flush()
        self.log.seek(0)
        lines = [line for line in self.log.read().decode(errors="replace").splitlines()
                 if line.strip()]
        return f" (its last line: {lines[-1].strip()})" if lines else ""

    # The page.

    def open_page(self, width, height):
        """A new page of width x height CSS pixels (one device pixel each), attached, with the
        Page, Runtime, Log and Network domains reporting their events."""
        target = self.send("Target.createTarget", {"url": "about:blank"})["targetId"]
        self.session = self.send("Target.attachToTarget",
                                 {"targetId": target, "flatten": True})["sessionId"]
        for domain in ("Page", "Runtime", "Log", "Network"):
            self.send(f"{domain}.enable", session=True)
        self.resize(width, height)

    def resize(self, width, height):
        """The viewport's size in CSS pixels, one device pixel each."""
        self.send("Emulation.setDeviceMetricsOverride",
                  {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False},
                  session=True)

    def navigate(self, url, timeout=COMMAND_TIMEOUT):
        """Loads url and waits for its load event and then document.readyState "complete"."""
        self.take_events({"Page.loadEventFired"})
        result = self.send("Page.navigate", {"url": url}, session=True)
        if result.get("errorText"):
            raise BrowserError(f"could not load {url}: {result['errorText']}")
        deadline = time.monotonic() + timeout
        self.wait_event("Page.loadEventFired", timeout=timeout)
        while self.evaluate("document.readyState") != "complete":
            if time.monotonic() > deadline:
                raise BrowserError(f"{url}: document.readyState never became complete")
            self.pump(0.05)

    def evaluate(self, expression, timeout=COMMAND_TIMEOUT):
        """The value of a JavaScript expression in the page (JSON-like values; a promise is
        awaited). An exception thrown by the expression raises BrowserError."""
        result = self.send("Runtime.evaluate",
                           {"expression": expression, "returnByValue": True,
                            "awaitPromise": True, "timeout": timeout * 1000},
                           session=True, timeout=timeout + 5)
        if "exceptionDetails" in result:
            details = result["exceptionDetails"]
            text = details.get("exception", {}).get("description") or details.get("text")
            raise BrowserError(f"JavaScript failed: {text.splitlines()[0]}")
        return result["result"].get("value")

    def screenshot(self, x=None, y=None, width=None, height=None, beyond_viewport=False):
        """PNG bytes of the rectangle at (x, y) of width x height, in document coordinates
        (CSS pixels from the page's top left, not the viewport's), or of the viewport when no
        rectangle is given. beyond_viewport lets the rectangle reach outside the viewport."""
        params = {"format": "png", "captureBeyondViewport": beyond_viewport}
        if x is not None:
            params["clip"] = {"x": x, "y": y, "width": width, "height": height, "scale": 1}
        return base64.b64decode(self.send("Page.captureScreenshot", params, session=True)["data"])

    # The mouse: viewport coordinates, CSS pixels, the left button.

    def mouse_press(self, x, y):
        self._mouse("mousePressed", x, y, buttons=1)

    def mouse_move(self, x, y, pressed=False):
        self._mouse("mouseMoved", x, y, buttons=1 if pressed else 0)

    def mouse_release(self, x, y):
        self._mouse("mouseReleased", x, y, buttons=0)

    def click(self, x, y):
        self.mouse_move(x, y)
        self.mouse_press(x, y)
        self.mouse_release(x, y)

    def _mouse(self, kind, x, y, buttons):
        params = {"type": kind, "x": x, "y": y, "buttons": buttons,
                  "button": "left" if kind != "mouseMoved" or buttons else "none"}
        if kind != "mouseMoved":
            params["clickCount"] = 1
        self.send("Input.dispatchMouseEvent", params, session=True)

    # The end.

    def close(self):
        """Asks the browser to exit, kills it (and what it started) if it does not, and
        removes its profile. Safe to call twice."""
        if self.process.poll() is None:
            try:
                self.send("Browser.close", timeout=EXIT_TIMEOUT)
            except BrowserError:
                pass
            try:
                self.process.wait(EXIT_TIMEOUT)
            except subprocess.TimeoutExpired:
                os.killpg(self.process.pid, signal.SIGKILL)  # its own group: start_new_session
                self.process.wait()
        for fd in (self.commands, self.replies):
            try:
                os.close(fd)
            except OSError:
                pass
        self.commands = self.replies = -1
        self.log.close()
        self._remove_profile()

    def _remove_profile(self):
        shutil.rmtree(self.profile, ignore_errors=True)
