# Copyright (c) 2026 The CGAL Surface Design authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Shared by the editor's tests: start surface_design_editor on a free loopback port, talk to it,
and decode its binary state (4-byte little-endian length, JSON, float32 per-corner data)."""

import json
import struct
import subprocess
import threading
import time
import urllib.error
import urllib.request


class Server:
    def __init__(self, program, mesh, *options):
        self.process = subprocess.Popen([program, mesh, "--port", "0", *options], stdout=subprocess.PIPE,
                                        stderr=subprocess.STDOUT, text=True)
        self.log = []
        deadline = time.time() + 120
        self.url = None
        while time.time() < deadline:
            line = self.process.stdout.readline()
            if not line:
                break
            self.log.append(line)
            if line.startswith("open http://"):
                address = line.split()[1]
                self.url, _, query = address.partition("?")
                self.token = query[len("token="):] if query.startswith("token=") else ""
                break
        if self.url is None:
            self.stop()
            raise RuntimeError("the editor did not start:\n" + "".join(self.log))
        if not self.url.startswith("http://127.0.0.1:"):
            raise RuntimeError("the editor must listen on the loopback address by default, not " + self.url)
        if len(self.token) != 32:
            raise RuntimeError("the printed address must carry a 128-bit token: " + address)
        self.host = self.url[len("http://"):].rstrip("/")
        # keep reading what the server prints (a sanitizer's report, say) so that its pipe never fills
        self.reader = threading.Thread(target=lambda: self.log.extend(iter(self.process.stdout.readline, "")),
                                       daemon=True)
        self.reader.start()

    def request(self, method, path, body=None, content_type="application/json", headers=None, token=True):
        """(status, content type, body bytes) of one request, with the server's token unless `token`
        is False; `headers` adds or replaces headers (Host, Origin, ...). HTTP errors are returned,
        not raised."""
        data = body if body is None or isinstance(body, bytes) else body.encode()
        all_headers = {"Content-Type": content_type} if data is not None else {}
        if token:
            all_headers["X-Editor-Token"] = self.token
        all_headers.update(headers or {})
        req = urllib.request.Request(self.url + path, data=data, method=method, headers=all_headers)
        try:
            with urllib.request.urlopen(req, timeout=120) as response:
                return response.status, response.headers.get("Content-Type", ""), response.read()
        except urllib.error.HTTPError as error:
            return error.code, error.headers.get("Content-Type", ""), error.read()

    def json(self, path):
        status, _, body = self.request("GET", path)
        assert status == 200, (path, status, body[:300])
        return json.loads(body)

    def edit(self, request):
        """(status, state or error message, corner data or None) of POST /api/edit."""
        body = request if isinstance(request, (str, bytes)) else json.dumps(request)
        status, _, content = self.request("POST", "api/edit", body)
        if status != 200:
            return status, json.loads(content)["error"], None
        state, corners = decode_state(content)
        return status, state, corners

    def state(self):
        status, _, content = self.request("GET", "api/state")
        assert status == 200
        return decode_state(content)

    def alive(self):
        return self.process.poll() is None

    def output(self):
        """Everything the server printed so far."""
        return "".join(self.log)

    def stop(self):
        if self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self.process.kill()


def decode_state(content):
    (length,) = struct.unpack_from("<I", content, 0)
    state = json.loads(content[4:4 + length])
    assert (4 + length) % 4 == 0, "the corner data must be 4-byte aligned"
    count = (len(content) - 4 - length) // 4
    corners = struct.unpack_from("<%df" % count, content, 4 + length)
    return state, corners
