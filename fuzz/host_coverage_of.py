#!/usr/bin/env python3
"""host_coverage_of.py RECORD HOST_CMD -- CMD... — the counters a host built
with SanitizerCoverage and vgc's runtime reaches while CMD runs against it,
written as a coverage record (fuzz/targets/coverage_record.h) that
fuzz/impl_coverage_by_file.py and fuzz/impl_coverage_union.py read beside a
campaign's records.

Spec: docs/fuzzing.md "Against the r6 host, guided by its own coverage"
(the ceiling: what any input vgc sends reaches, `vgc certify` over the wire
among them); runtime/vgc_coverage_shm.h (the region's layout, version 2).

`vgc fuzz` creates the region itself; `vgc certify` and `vgc replay` do not
(a host they start with --host-cmd runs without it). So this creates a
region as coverage_region.cpp does, starts HOST_CMD with /bin/sh -c and
VGC_COVERAGE_SHM naming it, waits a second, runs CMD, then stops the host
(SIGTERM to its process group) and writes RECORD: every counter that is not
zero (the host's whole life: start-up, every login, every command). Exit:
CMD's exit status, or 2 when the host never mapped its counters.
"""
import ctypes
import mmap
import os
import signal
import struct
import subprocess
import sys
import time

MAGIC = b"vgccov1\0"
HEADER_BYTES = 4096
MAX_MODULES = 30
NO_PC = 0xFFFFFFFF
MAX_COUNTERS = 1 << 20
HDR = struct.Struct("<8sIIIIQQQQiIIIQII")  # up to generation; the module table follows at 88
MOD = struct.Struct("<QIIII104s")


def round_up(v, to):
    return (v + to - 1) // to * to


def main():
    if len(sys.argv) < 5 or "--" not in sys.argv:
        print(__doc__, file=sys.stderr)
        return 2
    k = sys.argv.index("--")
    record, host_cmd, cmd = sys.argv[1], sys.argv[2], sys.argv[k + 1:]
    page = os.sysconf("SC_PAGESIZE")
    header = round_up(HEADER_BYTES, page)
    flags = round_up(MAX_COUNTERS, page)
    pcs = round_up(MAX_COUNTERS * 4, page)
    blocks = round_up(MAX_COUNTERS, page) + 2 * page * MAX_MODULES
    size = header + flags + pcs + blocks
    name = "/vgc-hostcov-%d" % os.getpid()
    librt = ctypes.CDLL("librt.so.1", use_errno=True)
    fd = librt.shm_open(name.encode(), os.O_RDWR | os.O_CREAT | os.O_EXCL, 0o600)
    if fd < 0:
        print("host_coverage_of: cannot create %s" % name, file=sys.stderr)
        return 2
    try:
        os.ftruncate(fd, size)
        mem = mmap.mmap(fd, size, mmap.MAP_SHARED, mmap.PROT_READ | mmap.PROT_WRITE)
        mem[0:HDR.size] = HDR.pack(b"\0" * 8, 2, page, MAX_COUNTERS, MAX_MODULES, header, header + flags,
                                    header + flags + pcs, size, 0, 0, 0, 0, 0, 0, 0)
        mem[0:8] = MAGIC  # last: the runtime checks it first
        env = dict(os.environ, VGC_COVERAGE_SHM=name)
        host = subprocess.Popen(["/bin/sh", "-c", host_cmd], env=env, stdin=subprocess.DEVNULL,
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
        time.sleep(1)
        rc = subprocess.call(cmd)
        try:
            os.killpg(host.pid, signal.SIGTERM)
        except ProcessLookupError:
            pass
        host.wait()
        h = HDR.unpack(mem[0:HDR.size])
        (_, _, _, _, _, flags_off, pcs_off, blocks_off, _, owner, modules, counters, dropped, _, entries, _) = h
        if not owner or not counters:
            print("host_coverage_of: the host did not map its counters (built without vgc's runtime?)",
                  file=sys.stderr)
            return 2
        reached = bytearray(counters)
        mods = []
        for m in range(min(modules, MAX_MODULES)):
            bo, co, n, first, _ = MOD.unpack(mem[88 + m * MOD.size:88 + (m + 1) * MOD.size])[:5]
            path = MOD.unpack(mem[88 + m * MOD.size:88 + (m + 1) * MOD.size])[5].split(b"\0")[0].decode()
            mods.append((path, n, first))
            at = blocks_off + bo + co
            for i, v in enumerate(mem[at:at + n]):
                if v:
                    reached[first + i] = 1
        fl = mem[flags_off:flags_off + counters]
        pc = mem[pcs_off:pcs_off + 4 * counters]

        def hexmap(bits):
            out = []
            for i in range(0, len(bits), 4):
                v = 0
                for b in range(4):
                    if i + b < len(bits) and bits[i + b]:
                        v |= 1 << b
                out.append("%x" % v)
            return "".join(out)

        def module_of(i):
            for m, (_, n, first) in enumerate(mods):
                if first <= i < first + n:
                    return m
            return 0

        lines = ["vgc-implementation-coverage 1", "mode observe", "seen 1", "counters %d" % counters,
                 "dropped %d" % dropped, "function_entries %d" % entries]
        lines += ["module %s (%d counters, PC table)" % (p, n) for (p, n, _) in mods]
        lines.append("timeline %d %d" % (int(time.time()), sum(reached)))
        lines.append("reached " + hexmap(reached))
        lines.append("entries " + hexmap(fl))
        for i in range(counters):
            if fl[i]:
                off = struct.unpack_from("<I", pc, 4 * i)[0]
                if off != NO_PC:
                    lines.append("function %d %d %x" % (i, module_of(i), off))
        with open(record, "w") as f:
            f.write("\n".join(lines) + "\n")
        print("host_coverage_of: %d of %d counters reached, %s" % (sum(reached), counters, record), file=sys.stderr)
        mem.close()
        return rc
    finally:
        librt.shm_unlink(name.encode())
        os.close(fd)


if __name__ == "__main__":
    sys.exit(main())
