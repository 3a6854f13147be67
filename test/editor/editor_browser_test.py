# Copyright (c) 2026 The CGAL Surface Design authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""End-to-end test of the stripe editor in a real headless Chromium, driven through the DevTools
protocol over a pipe (--remote-debugging-pipe: no port, no extra package). The page's own script
(?selftest=1) clicks and drags with real pointer events on the canvas: it adds a +1/-1 pair by two
clicks, checks that the picture changed and that the reported singularities are the clicked faces,
drags the -1 across faces (saving a frame per step), annihilates the pair, checks that a refused
edit is explained and keeps the state. This script starts the server (and opens the page with the
server's token), waits for the page's verdict, then judges from outside the page: it asks the
server for its own state and checks that it holds exactly the pair the page clicked, has applied
exactly as many edits as the page saw accepted, and has the page's field and frequency. It also
checks the frames and saves a screenshot of the whole page.

usage: editor_browser_test.py EDITOR DATA_DIR OUTPUT_DIR
Exit 77 (CTest: skipped) when chromium is not installed."""

import base64
import fcntl
import json
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from editor_support import Server  # noqa: E402


class Chromium:
    """A headless Chromium whose DevTools protocol runs over fds 3 (commands) and 4 (answers)."""

    def __init__(self, binary, width, height):
        to_child, self.commands = os.pipe()
        self.answers, from_child = os.pipe()
        # move our ends above 10 so that the dup2 to 3 and 4 in the child cannot overwrite them
        to_child, from_child = fcntl.fcntl(to_child, fcntl.F_DUPFD, 10), fcntl.fcntl(from_child, fcntl.F_DUPFD, 10)

        def child_fds():
            os.dup2(to_child, 3)
            os.dup2(from_child, 4)

        self.process = subprocess.Popen(
            [binary, "--headless", "--no-sandbox", "--remote-debugging-pipe", "--use-angle=swiftshader",
             "--enable-unsafe-swiftshader", "--no-first-run", "--disable-extensions", "--hide-scrollbars",
             f"--window-size={width},{height}", "about:blank"],
            preexec_fn=child_fds, pass_fds=(3, 4), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(to_child)
        os.close(from_child)
        self.next_id = 0
        self.buffer = b""

    def send(self, method, params=None, session=None, timeout=60):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        os.write(self.commands, json.dumps(message).encode() + b"\0")
        deadline = time.time() + timeout
        while time.time() < deadline:
            while b"\0" not in self.buffer:
                chunk = os.read(self.answers, 1 << 20)
                if not chunk:
                    raise RuntimeError("chromium closed the DevTools pipe")
                self.buffer += chunk
            raw, self.buffer = self.buffer.split(b"\0", 1)
            answer = json.loads(raw)
            if answer.get("id") == self.next_id:
                if "error" in answer:
                    raise RuntimeError(f"{method}: {answer['error']}")
                return answer.get("result", {})
        raise RuntimeError(f"{method}: no answer in {timeout} s")

    def close(self):
        try:
            self.send("Browser.close", timeout=10)
        except (RuntimeError, OSError):
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        return 2
    editor, data, output = sys.argv[1:]
    binary = shutil.which("chromium") or shutil.which("chromium-browser")
    if binary is None:
        print("SKIPPED: chromium is not installed (Debian: apt-get install chromium); the browser test needs it")
        return 77
    os.makedirs(output, exist_ok=True)
    for name in os.listdir(output):
        if name.endswith(".png"):
            os.remove(os.path.join(output, name))
    server = Server(editor, os.path.join(data, "bunny_8k.off"), "--save-frames", output)
    browser = Chromium(binary, 1200, 760)
    try:
        target = browser.send("Target.createTarget", {"url": server.url + "?token=" + server.token + "&selftest=1"})["targetId"]
        session = browser.send("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        browser.send("Runtime.enable", session=session)
        deadline, title = time.time() + 180, ""
        while time.time() < deadline:
            title = browser.send("Runtime.evaluate", {"expression": "document.title", "returnByValue": True},
                                 session=session)["result"].get("value", "")
            if title.startswith("SELFTEST"):
                break
            time.sleep(0.5)
        report = browser.send("Runtime.evaluate", {
            "expression": "document.getElementById('selftest').textContent + '\\n' + "
                          "document.getElementById('error').textContent", "returnByValue": True},
            session=session)["result"].get("value", "")
        shot = browser.send("Page.captureScreenshot", {"format": "png"}, session=session)["data"]
        with open(os.path.join(output, "editor_page.png"), "wb") as f:
            f.write(base64.b64decode(shot))
        server_state = server.state()[0] if server.alive() else None
    finally:
        browser.close()
        server.stop()

    if not report.startswith("SELFTEST "):
        print(f"the page's test did not finish (title '{title}'); page says: {report}")
        print("the server printed:\n" + server.output())
        return 1
    result = json.loads(report[len("SELFTEST "):].split("\n")[0])
    failed = 0
    for c in result.get("checks", []):
        print(("ok      " if c["ok"] else "FAILED  ") + c["name"] + (f"  ({c['detail']})" if c["detail"] else ""))
        failed += not c["ok"]
    # judged from outside the page: after the clicks, the drag, the annihilation and the final
    # pair, the server itself must hold exactly the pair the page clicked, and have applied
    # exactly the edits the page saw accepted (every drag step one edit, the refused one none)
    did = result.get("did", {})
    server_checks = [
        ("the server holds the +1/-1 pair at the clicked faces",
         server_state is not None and sorted(map(tuple, server_state["singularities"])) ==
         sorted([(did.get("plus"), 1, 0), (did.get("minus"), -1, 0)]),
         (server_state and server_state["singularities"], did)),
        ("the server applied as many edits as the page saw accepted (version)",
         server_state is not None and did.get("edits", 0) >= 6 and server_state["version"] == did.get("edits"),
         (server_state and server_state["version"], did.get("edits"))),
        ("the server's field and frequency are the page's",
         server_state is not None and server_state["field"]["kind"] == "smoothest" == did.get("field") and
         server_state["stripes"] == did.get("stripes"), (server_state and server_state["field"], did)),
    ]
    for name, ok, detail in server_checks:
        print(("ok      " if ok else "FAILED  ") + name + ("" if ok else f"  ({detail})"))
        failed += not ok
    if "error" in result:
        print("the page's test threw:", result["error"])
        failed += 1
    # the frames the page sent: the drag must show a moving picture
    frames = sorted(n for n in os.listdir(output) if n.startswith("editor_drag_") and n[12:-4].isdigit())
    pictures = [open(os.path.join(output, n), "rb").read() for n in frames]
    distinct = len(set(pictures))
    print(f"{len(frames)} drag frames, {distinct} distinct; screenshot {os.path.join(output, 'editor_page.png')}")
    if not os.path.exists(os.path.join(output, "editor_drag_strip.png")):
        print("FAILED  no film strip of the drag")
        failed += 1
    if len(frames) < 6 or distinct < 3:
        print("FAILED  the drag frames do not show the singularity moving")
        failed += 1
    drags = [entry for entry in result.get("latency", []) if entry["label"] == "drag"]
    if drags:
        server_ms = sorted(entry["server_ms"] for entry in drags)
        frame_ms = sorted(entry["frame_ms"] for entry in drags)
        print(f"drag steps on {result['faces']} faces: server median {server_ms[len(server_ms) // 2]:.2f} ms, "
              f"event to picture median {frame_ms[len(frame_ms) // 2]:.1f} ms (software WebGL)")
    checks = len(result.get("checks", [])) + len(server_checks) + 1
    print(f"{checks - failed} passed, {failed} failed")
    return 0 if failed == 0 and result.get("pass") else 1


if __name__ == "__main__":
    sys.exit(main())
