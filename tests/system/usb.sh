#!/bin/bash
# System test of USB export: edaha installed by `meson install` onto the VM's root,
# systemd as PID 1 (vm.sh -i systemd) with edaha-usb.socket and edaha.service as the
# product runs them; FAT (and ext4) stick images built here and hot-plugged on an xHCI
# controller through QEMU's QMP (vm.sh -u -q, qmp.py) while the kiosk runs; export
# pressed on a gpio-sim button. In one boot:
#   1. a stick receives three exports: read back with mtools, the .glb passes the glTF
#      validator, the .edaha loads, the .obj names its .mtl, no temporaries; its gallery
#      edaha/index.html lists the three, newest first, every link and picture a file there;
#   2. a slow stick (QEMU write throttling) holding the first stick's edaha/ (three sets
#      and their gallery) is pulled (device_del) in the middle of an export: the kiosk
#      says so and runs on, the image holds no final name of the new set and its gallery
#      is whole, every link resolving; while it wrote, the stick was mounted in the host's
#      namespace nosuid, nodev, noexec, noatime, nosymfollow;
#   3. a new stick holding another kiosk's index.html then receives a complete export,
#      and our gallery replaces that index;
#   4. a read-only stick, an unformatted one, one with a file named edaha, a full one,
#      and an ext4 one whose edaha/ holds symlinks named like the files and like
#      index.html, and 2000 others: each said in the journal, the kiosk running on;
#      nothing of a failed set left, no broken gallery; on ext4 the set goes past every
#      name, no symlink followed or replaced but index.html's, replaced as a link;
#   5. an exFAT stick receives an export and its gallery (read back by the guest's kernel).
# At the end edaha.service was never restarted and the local copies are there.
# Prints the time each save to a stick took (TCG-emulated CPU, emulated USB).
# Environment from meson: EDAHA, GLTF_VALIDATE, VM, UINPUT_PEN, KMOD_DIR, BUILD_ROOT,
# EDAHA_GL_PRELOAD (ASan builds). Packages: mtools dosfstools exfatprogs e2fsprogs python3.
set -uo pipefail
: "${EDAHA:?}" "${GLTF_VALIDATE:?}" "${VM:?}" "${UINPUT_PEN:?}" "${KMOD_DIR:?}" "${BUILD_ROOT:?}"
HERE=$(cd "$(dirname "$0")" && pwd)
T=$(mktemp -d "${TMPDIR:-/tmp}/edaha-usb.XXXXXX")
vmpid=""
cleanup() {
	# a test that failed half way: QEMU quits (QMP), vm.sh then ends by itself
	if [ -n "$vmpid" ]; then
		python3 "$HERE/qmp.py" "$T/qmp.sock" quit 2>/dev/null
		wait "$vmpid" 2>/dev/null
	fi
	[ -n "${KEEP:-}" ] && echo "kept $T" || rm -rf "$T"
}
trap cleanup EXIT
fail() {
	echo "FAIL: $*" >&2
	[ -f "$T/vm/edaha.log" ] && grep -v '^MESA-LOADER\|^failed to load driver\|^pci id\|^kmsro' \
		"$T/vm/edaha.log" | tail -40 | sed 's/^/  | /' >&2
	exit 1
}
skip() { echo "SKIP: $*"; exit 77; }
for c in mkfs.vfat mcopy mdir mkfs.exfat mkfs.ext4 debugfs python3; do
	command -v $c >/dev/null || skip "no $c (apt-get install mtools dosfstools exfatprogs e2fsprogs python3)"
done
command -v /lib/systemd/systemd >/dev/null || skip "no systemd"
export MTOOLS_SKIP_CHECK=1
"$HERE/build_kmods.sh" "$KMOD_DIR"
rc=$?
[ $rc -eq 77 ] && exit 77
[ $rc -eq 0 ] || fail "cannot build the gpio-sim module"
. "$HERE/gl_env.sh"

# the product as installed, the test's configuration, the GL driver's environment
. "$HERE/installed_root.sh"
root=$T/root
installed_root "$root" "$HERE/usb.conf" || fail "meson install into $root failed"
find "$root" -name edaha-usb.socket | grep -q . || fail "meson installed no edaha-usb.socket"
# an ASan build's helper: LeakSanitizer's ptrace is outside the unit's system calls (the
# helper's leaks are checked by tests/platform's usb_helper instead)
if [ -n "${EDAHA_GL_PRELOAD:-}" ]; then
	mkdir -p "$root/etc/systemd/system/edaha-usb@.service.d"
	printf '[Service]\nEnvironment=ASAN_OPTIONS=detect_leaks=0\n' \
		> "$root/etc/systemd/system/edaha-usb@.service.d/test.conf"
fi

# the sticks: superfloppy FAT images as mkfs.vfat makes them (the kiosk sees /dev/sdX)
img=$T/img
mkdir -p "$img"
for s in good1 good3 ro hostile; do mkfs.vfat -n EDAHA -C "$img/$s.img" 16384 >/dev/null; done
# room for the first stick's three sets and part of a fourth
mkfs.vfat -n EDAHA -C "$img/slow.img" 65536 >/dev/null
head -c 8M /dev/zero > "$img/blank.img"
truncate -s 16M "$img/exfat.img"
mkfs.exfat "$img/exfat.img" >/dev/null || fail "mkfs.exfat failed"
echo "not a directory" > "$T/edaha-file"
mcopy -i "$img/hostile.img" "$T/edaha-file" ::edaha
mmd -i "$img/ro.img" ::edaha

qmp=$T/qmp.sock
"$VM" -t 600 -s 640x400 -g bochs -i systemd -r "$root" -u -q "$qmp" -o "$T/vm" -- \
	"$HERE/usb_guest.sh" "$UINPUT_PEN" "$KMOD_DIR" > "$T/vm.log" 2>&1 &
vmpid=$!
v=$T/vm
log=$v/edaha.log

alive() { kill -0 "$vmpid" 2>/dev/null; }
wait_file() { # FILE SECONDS
	local i=0
	while [ ! -e "$1" ] && [ $i -lt $(($2 * 5)) ] && alive; do sleep 0.2; i=$((i + 1)); done
	[ -e "$1" ]
}
count() { grep -c -- "$1" "$log" 2>/dev/null || true; }
wait_log() { # PATTERN N SECONDS
	local i=0
	while [ "$(count "$1")" -lt "$2" ] && [ $i -lt $(($3 * 5)) ] && alive; do sleep 0.2; i=$((i + 1)); done
	[ "$(count "$1")" -ge "$2" ] || fail "no \"$1\" (#$2) in the kiosk's journal within $3 s"
}
ncmd=0
guest() { # COMMAND: the guest does it
	ncmd=$((ncmd + 1))
	echo "$1" > "$v/cmd.$ncmd"
	wait_file "$v/ack.$ncmd" 60 || fail "the guest did not do \"$1\""
}
plug() { python3 "$HERE/qmp.py" "$qmp" plug "$@" || fail "cannot plug $1"; }
pull() { python3 "$HERE/qmp.py" "$qmp" pull "$1" || fail "cannot pull $1"; }
ready=0 saved=0
plug_ready() { # ID IMAGE [qmp.py options]: plugged in, the kiosk looked at it and is ready
	plug "$@"
	ready=$((ready + 1))
	wait_log ') is ready' $ready 60
}
save() { # the export button; the kiosk says the stick is safe to pull
	guest export
	saved=$((saved + 1))
	wait_log 'safe to pull' $saved 90
	grep 'safe to pull' "$log" | tail -1 | sed 's/.* in \([0-9.]* s\).*/\1/' >> "$T/times"
}
# the files of set BASE on a FAT image, copied to DIR and checked by their consumers
check_set() { # IMAGE BASE DIR
	mkdir -p "$3"
	for s in glb obj mtl png edaha; do
		mcopy -n -i "$1" "::edaha/$2.$s" "$3/" 2>/dev/null || fail "$(basename "$1"): no edaha/$2.$s"
		[ -s "$3/$2.$s" ] || fail "$(basename "$1"): edaha/$2.$s is empty"
	done
	"$GLTF_VALIDATE" "$3/$2.glb" >/dev/null || fail "$(basename "$1"): $2.glb is not valid glTF"
	env "${host_env[@]}" "$EDAHA" --headless --load "$3/$2.edaha" --out "$3/loaded" \
		>"$3/load.log" 2>&1 || { cat "$3/load.log"; fail "$(basename "$1"): $2.edaha does not load"; }
	grep -q "\"origin\"" "$3/loaded/skeleton.json" || fail "$2.edaha holds no tree"
	grep -qx "mtllib $2.mtl" "$3/$2.obj" || fail "$2.obj does not name $2.mtl"
	[ "$(head -c 8 "$3/$2.png" | od -An -tx1 | tr -d ' ')" = 89504e470d0a1a0a ] ||
		fail "$2.png is no PNG"
}
names() { mdir -b -a -i "$1" ::edaha 2>/dev/null | sed 's|.*/||'; }
# a gallery as read from a stick (FILE), against the names beside it (NAMES, one a line):
# whole (its end there), no script, every link and picture one of those names, the links
# all tree-NNNN.html or .glb; with N and FIRST, N entries, the first (newest) FIRST's
check_gallery() { # FILE NAMES [N FIRST]
	python3 - "$@" <<'PY'
import html.parser, re, sys
path, names = sys.argv[1:3]
text = open(path, encoding="utf-8").read()
have = set(open(names, encoding="utf-8", errors="replace").read().split("\n"))
class Page(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.links, self.pictures, self.tags = [], [], set()
    def handle_starttag(self, tag, attrs):
        self.tags.add(tag)
        a = dict(attrs)
        if tag == "a":
            self.links.append(a.get("href"))
        if tag == "img":
            self.pictures.append(a.get("src"))
p = Page()
p.feed(text)
assert text.startswith("<!DOCTYPE html>") and text.endswith("</html>\n"), "not whole"
assert "script" not in p.tags, "a script"
for name in p.links:
    assert re.fullmatch(r"tree-\d{4,5}\.(html|glb)", name or ""), "a link to %r" % name
for name in p.links + p.pictures:
    assert name in have, "%s is not on the stick" % name
if len(sys.argv) > 3:
    n, first = int(sys.argv[3]), sys.argv[4]
    assert len(p.links) == n, "%d entries, not %d: %s" % (len(p.links), n, p.links)
    assert p.links[0].startswith(first + "."), "the newest is %s, not %s" % (p.links[0], first)
print("%d trees listed" % len(p.links))
PY
}
# a FAT stick's gallery (IMAGE [N FIRST]): as check_gallery; none at all is whole too
fat_gallery() {
	local g=$T/gallery.$$ n
	rm -f "$g"
	names "$1" > "$g.names"
	grep -qx index.html "$g.names" || { [ $# -eq 1 ] && return 0; fail "$(basename "$1"): no edaha/index.html"; }
	mcopy -n -i "$1" ::edaha/index.html "$g" || fail "$(basename "$1"): cannot read edaha/index.html"
	n=$(check_gallery "$g" "$g.names" "${@:2}") || fail "$(basename "$1"): edaha/index.html is broken"
	echo "  $(basename "$1"): edaha/index.html, $n"
}

# vm.sh waits its turn for the machine's one VM: the clock starts when QEMU does
while alive && ! grep -q SeaBIOS "$T/vm.log" 2>/dev/null; do sleep 1; done
t_boot=$(date +%s)
wait_file "$v/drawn" 300 || fail "the guest never drew its tree: $(tail -20 "$T/vm.log")"
t_drawn=$(date +%s)
grep -q "first frame on screen" "$log" || fail "the kiosk did not start"

# 1. a stick, three exports, and its gallery
plug_ready s1 "$img/good1.img"
save
save
save
pull s1
check_set "$img/good1.img" tree-0001 "$T/s1"
check_set "$img/good1.img" tree-0003 "$T/s1-3"
names "$img/good1.img" | grep -q '^\.tree-\|^\.index' && fail "good1: temporaries left: $(names "$img/good1.img")"
fat_gallery "$img/good1.img" 3 tree-0003
grep -q 'gallery: sd[a-z0-9]*/edaha/index.html lists 3 trees' "$log" ||
	fail "the journal does not say the gallery lists 3 trees"
bytes=$(cat "$T"/s1/tree-0001.* | wc -c)
echo "  an export: $bytes bytes"

# 2. a slow stick holding the first one's sets and gallery, pulled in the middle of the
# export (six seconds' worth of writes)
mkdir -p "$T/good1"
mcopy -s -n -i "$img/good1.img" ::edaha "$T/good1/" || fail "cannot copy good1's edaha/"
mcopy -s -i "$img/slow.img" "$T/good1/edaha" :: || fail "cannot copy edaha/ onto slow.img"
bps=$((bytes / 6))
[ $bps -lt 20000 ] && bps=20000
plug_ready s2 "$img/slow.img" --bps-write $bps
guest export
wait_log 'edaha: usb: writing to' 2 60
sleep 1.5
guest mounts
pull s2
# the failed write (the stick gone from sysfs) or udev's remove event, whichever the
# kiosk hears first, tells the visitor
wait_log 'failed (pulled)' 1 90
names "$img/slow.img" | grep -q '^tree-0004' && fail "the pulled stick holds final names: $(names "$img/slow.img")"
echo "  pulled mid-write; left on it: $(names "$img/slow.img" | tr '\n' ' ')"
# its gallery: the one from before (the set did not go in), whole, every link resolving
fat_gallery "$img/slow.img" 3 tree-0003
grep -q ' /run/edaha/media/sd[a-z]* ' "$v/mounts.txt" ||
	fail "the stick was not mounted in the host's namespace while written: $(cat "$v/mounts.txt")"
for o in nosuid nodev noexec noatime nosymfollow; do
	grep -q "[ ,]$o[ ,]" "$v/mounts.txt" || fail "mounted without $o: $(cat "$v/mounts.txt")"
done

# 3. a new stick, with another kiosk's index.html: a complete export, and ours replaces it
mmd -i "$img/good3.img" ::edaha
printf '<html><body>another kiosk<script>alert(1)</script></body></html>' > "$T/foreign.html"
mcopy -i "$img/good3.img" "$T/foreign.html" ::edaha/index.html
plug_ready s3 "$img/good3.img"
save
pull s3
check_set "$img/good3.img" tree-0001 "$T/s3"
fat_gallery "$img/good3.img" 1 tree-0001

# 4. sticks that will not do
plug s4 "$img/ro.img" --read-only
wait_log 'cannot be used: read-only' 1 60
guest export
wait_log 'cannot be used: read-only' 2 60
pull s4
plug s5 "$img/blank.img"
wait_log 'cannot be used: unformatted' 1 60
pull s5
plug s6 "$img/hostile.img"
wait_log 'cannot be used: edaha-not-a-directory' 1 60
guest export
wait_log 'cannot be used: edaha-not-a-directory' 2 60
pull s6
[ "$(mtype -i "$img/hostile.img" ::edaha)" = "not a directory" ] || fail "the file named edaha changed"
# full: room for half an export
mkfs.vfat -C "$img/full.img" 2048 >/dev/null
# mdir says "2 076 672 bytes free"; the filler is sparse, so a wrong sum fills no disk
free=$(mdir -i "$img/full.img" :: | sed -n 's/ bytes free//p' | tr -d ' ')
case $free in '' | *[!0-9]*) fail "cannot read the free space of full.img: \"$free\"" ;; esac
fill=$((free - bytes / 2))
[ $fill -gt 0 ] && [ $fill -lt $((2 << 20)) ] || fail "bad filler size $fill for $free bytes free"
truncate -s $fill "$T/filler"
mcopy -i "$img/full.img" "$T/filler" ::filler || fail "cannot fill full.img"
plug_ready s7 "$img/full.img"
guest export
wait_log 'failed (full)' 1 90
pull s7
names "$img/full.img" | grep -q 'tree-' && fail "the full stick holds part of a set: $(names "$img/full.img")"
fat_gallery "$img/full.img"
# ext4, hostile: symlinks at the first set's names and at the next one's temporary,
# 2000 files; edaha/ writable by anyone, so the kiosk's user may write there
mkdir -p "$T/ext4/edaha"
chmod 0777 "$T/ext4/edaha"
ln -s /etc/passwd "$T/ext4/edaha/tree-0001.glb"
ln -s /var/lib/edaha "$T/ext4/edaha/tree-0001.obj"
ln -s /etc/passwd "$T/ext4/edaha/.tree-2002.glb.tmp"
ln -s /etc/passwd "$T/ext4/edaha/index.html"
(cd "$T/ext4/edaha" && for i in $(seq 2 2001); do : > "$(printf 'tree-%04d.png' "$i")"; done)
mkfs.ext4 -q -F -d "$T/ext4" "$img/ext4.img" 16M >/dev/null || fail "mkfs.ext4 -d failed"
plug_ready s8 "$img/ext4.img"
save
pull s8
e4() { debugfs -R "$1" "$img/ext4.img" 2>/dev/null; }
mkdir -p "$T/s8"
for s in glb obj mtl png edaha; do
	e4 "dump /edaha/tree-2003.$s $T/s8/tree-2003.$s"
	[ -s "$T/s8/tree-2003.$s" ] || fail "ext4: no tree-2003.$s (past the symlinks, files and stale temporary)"
done
"$GLTF_VALIDATE" "$T/s8/tree-2003.glb" >/dev/null || fail "ext4: tree-2003.glb is not valid glTF"
[ "$(e4 'stat /edaha/tree-0001.glb' | grep -c 'Type: symlink')" = 1 ] || fail "ext4: the symlink tree-0001.glb was replaced"
e4 'ls -l /edaha' | grep -q '\.tree-2002' && fail "ext4: the stale temporary symlink is still there"
[ "$(e4 'ls /edaha' | tr -s ' \t' '\n' | grep -c '^tree-.*\.png$')" -ge 2001 ] || fail "ext4: files went missing"
# the gallery: the symlink named index.html replaced by the file itself; one tree listed
# (the 2000 pictures have no page nor model, tree-0001's model is a symlink)
[ "$(e4 'stat /edaha/index.html' | grep -c 'Type: regular')" = 1 ] || fail "ext4: index.html is not our file"
e4 "dump /edaha/index.html $T/s8/index.html"
e4 'ls /edaha' | tr -s ' \t' '\n' > "$T/s8/names"
n=$(check_gallery "$T/s8/index.html" "$T/s8/names" 1 tree-2003) || fail "ext4: edaha/index.html is broken"
echo "  ext4: edaha/index.html, $n"

# exFAT: read back by the guest's kernel (mtools knows no exFAT)
plug_ready s9 "$img/exfat.img"
save
guest readback-exfat
pull s9
for s in glb obj mtl png edaha; do
	[ -s "$v/exfat/tree-0001.$s" ] || fail "exfat: no tree-0001.$s: $(cat "$v/exfat.ls")"
done
"$GLTF_VALIDATE" "$v/exfat/tree-0001.glb" >/dev/null || fail "exfat: tree-0001.glb is not valid glTF"
ls "$v/exfat" > "$T/exfat.names"
[ -s "$v/exfat/index.html" ] || fail "exfat: no index.html: $(cat "$v/exfat.ls")"
n=$(check_gallery "$v/exfat/index.html" "$T/exfat.names" 1 tree-0001) || fail "exfat: index.html is broken"
echo "  exfat: edaha/index.html, $n"

t_sticks=$(date +%s)
guest stop
wait "$vmpid"
rc=$?
vmpid=""
[ $rc -eq 0 ] || { tail -30 "$T/vm.log"; fail "the guest exited $rc"; }

# the kiosk ran through it all
grep -q 'ActiveState=active' "$v/status.txt" && grep -q 'NRestarts=0' "$v/status.txt" ||
	fail "edaha.service did not run through: $(cat "$v/status.txt")"
grep -q 'User=edaha' "$v/status.txt" || fail "the kiosk did not run as edaha: $(cat "$v/status.txt")"
grep -q 'srw-rw---- .* root edaha .*/run/edaha/usb.sock' "$v/status.txt" ||
	fail "the helper's socket is not root:edaha 0660: $(grep usb.sock "$v/status.txt")"
grep -q 'edaha-usb-helper: mount sd[a-z]* for uid [1-9]' "$log" ||
	fail "the helper was not asked by the edaha user through the socket"
[ -s "$v/local/tree-0001.glb" ] || fail "no local copy in kiosk.export_dir"
echo "  local copies: $(ls "$v/local" | grep -c '\.glb$') sets"
# and their gallery: every set, the newest first
ls "$v/local" > "$T/local.names"
newest=$(grep '^tree-[0-9]*\.glb$' "$T/local.names" | sort | tail -1 | sed 's/\.glb$//')
n=$(check_gallery "$v/local/index.html" "$T/local.names" "$(grep -c '^tree-[0-9]*\.glb$' "$T/local.names")" \
	"$newest") || fail "kiosk.export_dir's index.html is broken"
echo "  kiosk.export_dir/index.html, $n"
echo "  saves to a stick took: $(tr '\n' ' ' < "$T/times")(TCG guest, emulated xHCI)"
echo "  boot, kiosk up and tree drawn: $((t_drawn - t_boot)) s; the nine sticks: $((t_sticks - t_drawn)) s"
echo "system-usb: OK"
