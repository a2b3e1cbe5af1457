"""cdp.py — headless Chromium driven over its DevTools protocol on a pipe (standard library only).

Chromium started with --remote-debugging-pipe reads the protocol's JSON messages, each ended by
a NUL byte, on its file descriptor 3 and writes its own on 4; no port, no WebSocket library.
  b = Browser(chromium, workdir, width, height)   # one page, attached
  b.call("Page.navigate", url=...)                 # a command of the page; its result
  b.eval("js expression")                          # Runtime.evaluate, promises awaited, by value
  b.wait("js condition", timeout)                  # polls until true; seconds it took
  b.screenshot(path)                               # PNG of the page as shown
  b.console                                        # the page's console errors and uncaught exceptions
  b.close()
Used by tests/viewer_test.py.
"""
import base64
import json
import os
import queue
import subprocess
import threading
import time


class Browser:
    def __init__(self, chromium, workdir, width=1400, height=900):
        r_in, w_in = os.pipe()        # ours -> Chromium's fd 3
        r_out, w_out = os.pipe()      # Chromium's fd 4 -> ours
        args = [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                "--hide-scrollbars", "--no-first-run", "--no-default-browser-check", "--mute-audio",
                "--force-device-scale-factor=1", "--remote-debugging-pipe",
                "--user-data-dir=" + os.path.join(workdir, "profile"), "--window-size=%d,%d" % (width, height),
                "about:blank"]
        cmd = 'exec "$@" 3<&%d 4>&%d' % (r_in, w_out)
        self.proc = subprocess.Popen(["bash", "-c", cmd, "chromium"] + args, pass_fds=(r_in, w_out),
                                     stdout=subprocess.DEVNULL,
                                     stderr=open(os.path.join(workdir, "chromium.log"), "wb"))
        os.close(r_in)
        os.close(w_out)
        self.out = os.fdopen(w_in, "wb", buffering=0)
        self.inp = os.fdopen(r_out, "rb", buffering=0)
        self.next_id, self.replies, self.console, self.session = 0, {}, [], None
        self.events = queue.Queue()
        self.lock = threading.Condition()
        threading.Thread(target=self._read, daemon=True).start()
        targets = self._send("Target.getTargets")["targetInfos"]
        page = [t for t in targets if t["type"] == "page"][0]
        self.session = self._send("Target.attachToTarget", targetId=page["targetId"], flatten=True)["sessionId"]
        for domain in ("Page", "Runtime", "DOM"):
            self.call(domain + ".enable")
        self.call("Emulation.setDeviceMetricsOverride", width=width, height=height, deviceScaleFactor=1, mobile=False)

    def _read(self):
        buf = b""
        while True:
            chunk = self.inp.read(65536)
            if not chunk:
                return
            buf += chunk
            while b"\0" in buf:
                raw, buf = buf.split(b"\0", 1)
                msg = json.loads(raw.decode("utf-8"))
                if "id" in msg:
                    with self.lock:
                        self.replies[msg["id"]] = msg
                        self.lock.notify_all()
                elif msg.get("method") == "Runtime.exceptionThrown":
                    d = msg["params"]["exceptionDetails"]
                    self.console.append("uncaught: " + d.get("exception", {}).get("description", d.get("text", "")))
                elif msg.get("method") == "Runtime.consoleAPICalled" and msg["params"]["type"] == "error":
                    self.console.append("console.error: " + " ".join(str(a.get("value", a.get("description", "")))
                                                                     for a in msg["params"]["args"]))

    def _send(self, method, session=None, timeout=120, **params):
        with self.lock:
            self.next_id += 1
            mid = self.next_id
        msg = {"id": mid, "method": method, "params": params}
        if session:
            msg["sessionId"] = session
        self.out.write(json.dumps(msg).encode("utf-8") + b"\0")
        end = time.time() + timeout
        with self.lock:
            while mid not in self.replies:
                if not self.lock.wait(timeout=max(0.0, end - time.time())) and time.time() > end:
                    raise TimeoutError("%s: no answer in %d s" % (method, timeout))
            reply = self.replies.pop(mid)
        if "error" in reply:
            raise RuntimeError("%s: %s" % (method, reply["error"]))
        return reply.get("result", {})

    def call(self, method, timeout=120, **params):
        return self._send(method, session=self.session, timeout=timeout, **params)

    def eval(self, expr, timeout=120):
        r = self.call("Runtime.evaluate", timeout=timeout, expression=expr, awaitPromise=True, returnByValue=True)
        if "exceptionDetails" in r:
            d = r["exceptionDetails"]
            raise RuntimeError("page: %s" % d.get("exception", {}).get("description", d.get("text")))
        return r["result"].get("value")

    def wait(self, cond, timeout=60, every=0.02):
        t0 = time.time()
        while time.time() - t0 < timeout:
            if self.eval("!!(%s)" % cond):
                return time.time() - t0
            time.sleep(every)
        raise TimeoutError("page: %s not true after %d s" % (cond, timeout))

    def screenshot(self, path):
        data = self.call("Page.captureScreenshot", format="png")["data"]
        with open(path, "wb") as f:
            f.write(base64.b64decode(data))
        return path

    def close(self):
        try:
            self._send("Browser.close", timeout=10)
        except Exception:
            pass
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
