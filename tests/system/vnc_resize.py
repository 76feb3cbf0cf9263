#!/usr/bin/env python3
# Asks QEMU's VNC server to resize the guest's display, as a VNC viewer whose window was
# resized does (RFB SetDesktopSize): with a virtio-gpu, the guest then sees its connector
# come back with the new size as its preferred mode, through a real hotplug uevent.
#   vnc_resize.py SOCKET WIDTH HEIGHT
import socket
import struct
import sys


def main():
    path, width, height = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    s = socket.socket(socket.AF_UNIX)
    s.settimeout(30)
    s.connect(path)

    def read(n):
        data = b""
        while len(data) < n:
            chunk = s.recv(n - len(data))
            if not chunk:
                sys.exit("vnc_resize: the server closed the connection")
            data += chunk
        return data

    s.sendall(read(12))  # the server's protocol version, 3.8, taken as it is
    types = read(read(1)[0])
    if 1 not in types:
        sys.exit("vnc_resize: the server wants authentication")
    s.sendall(b"\x01")  # security: none
    if struct.unpack(">I", read(4))[0] != 0:
        sys.exit("vnc_resize: security handshake failed")
    s.sendall(b"\x01")  # shared
    old_w, old_h = struct.unpack(">HH", read(4))
    read(16)  # pixel format
    read(struct.unpack(">I", read(4))[0])  # name
    # SetEncodings: ExtendedDesktopSize (-308), which SetDesktopSize needs, and raw
    s.sendall(struct.pack(">BBHii", 2, 0, 2, -308, 0))
    # SetDesktopSize: one screen, id 0, at 0,0
    s.sendall(struct.pack(">BBHHBB", 251, 0, width, height, 1, 0) +
              struct.pack(">IHHHHI", 0, 0, 0, width, height, 0))
    # the server answers with a framebuffer update announcing the result
    msg = read(1)[0]
    s.close()
    print(f"vnc_resize: {old_w}x{old_h} -> {width}x{height} asked (reply type {msg})")


main()
