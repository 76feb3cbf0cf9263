#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""USB sticks for a VM started with vm.sh -u -q SOCKET, through QEMU's QMP.

  qmp.py SOCKET plug ID IMAGE [--read-only] [--bps-write N]
      a raw IMAGE as a usb-storage device on the xHCI bus (node ID, device ID-dev); with
      --bps-write its writes are throttled to N bytes/s (a slow stick)
  qmp.py SOCKET pull ID
      the device is pulled out (device_del), then its block nodes are let go
  qmp.py SOCKET quit
      QEMU stops (a test that ends early)

Each call is one QMP session. Exit status 1 with QEMU's error on stderr.
"""
import json
import socket
import sys
import time


class Qmp:
    def __init__(self, path):
        self.sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        self.sock.settimeout(30)
        self.sock.connect(path)
        self.buf = b""
        self.events = []
        self.read()  # the greeting
        self.call("qmp_capabilities")

    def read(self):
        while b"\n" not in self.buf:
            data = self.sock.recv(65536)
            if not data:
                raise RuntimeError("QMP closed")
            self.buf += data
        line, self.buf = self.buf.split(b"\n", 1)
        return json.loads(line)

    def call(self, cmd, **args):
        self.sock.sendall(json.dumps({"execute": cmd, "arguments": args}).encode() + b"\n")
        while True:
            msg = self.read()
            if "event" in msg:
                self.events.append(msg)
                continue
            if "error" in msg:
                raise RuntimeError(f"{cmd}: {msg['error'].get('desc')}")
            return msg.get("return")

    def wait_event(self, name, timeout=20):
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            for e in self.events:
                if e["event"] == name:
                    return e
            self.events.append(self.read())
        raise RuntimeError(f"no {name} event")


def plug(q, node, image, read_only, bps):
    q.call("blockdev-add", **{"driver": "raw", "node-name": node + "-raw", "read-only": read_only,
                              "file": {"driver": "file", "filename": image,
                                       "read-only": read_only}})
    top = node + "-raw"
    if bps:
        q.call("object-add", **{"qom-type": "throttle-group", "id": node + "-tg",
                                "limits": {"bps-write": bps}})
        q.call("blockdev-add", **{"driver": "throttle", "node-name": node,
                                  "throttle-group": node + "-tg", "file": top})
        top = node
    q.call("device_add", driver="usb-storage", bus="xhci.0", drive=top, id=node + "-dev",
           removable=True)


def pull(q, node):
    q.call("device_del", id=node + "-dev")
    q.wait_event("DEVICE_DELETED")
    nodes = [n["node-name"] for n in q.call("query-named-block-nodes")]
    if node in nodes:
        q.call("blockdev-del", **{"node-name": node})
        q.call("object-del", id=node + "-tg")
    q.call("blockdev-del", **{"node-name": node + "-raw"})


def main(argv):
    if len(argv) < 3 or argv[2] not in ("plug", "pull", "quit") or (argv[2] != "quit" and len(argv) < 4):
        sys.exit(__doc__)
    try:
        q = Qmp(argv[1])
        if argv[2] == "quit":
            q.call("quit")
        elif argv[2] == "plug":
            read_only = "--read-only" in argv
            bps = int(argv[argv.index("--bps-write") + 1]) if "--bps-write" in argv else 0
            plug(q, argv[3], argv[4], read_only, bps)
        else:
            pull(q, argv[3])
    except (RuntimeError, OSError) as e:
        print(f"qmp.py: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
