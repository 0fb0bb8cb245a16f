#!/usr/bin/env python3
"""make_stub.py LIB WANTED OUTDIR: a stand-in for the shared library LIB that has its soname and
exports, with their symbol versions, those of its dynamic symbols listed in WANTED (one name a
line: what the other carried libraries import). Functions return a pointer to zeros; data are
zeros. It is for libraries that a carried program must load but never runs: OpenImageIO's
plugins for formats the globe does not read (video, DICOM, OpenVDB...) and Mesa's LLVM when the
X server's GLX runs softpipe. Utilities/device/bundle.sh checks the result by running the
benchmark with it before anything is sent."""
import os
import subprocess
import sys

lib, wanted_path, out = sys.argv[1:4]
wanted = set(open(wanted_path).read().split())
dynamic = subprocess.run(["readelf", "-d", lib], capture_output=True, text=True, check=True).stdout
soname = next(l.split("[")[1].rstrip("]") for l in dynamic.splitlines() if "(SONAME)" in l)
symbols = subprocess.run(["nm", "-D", "--defined-only", "-S", lib], capture_output=True, text=True,
                         check=True).stdout
asm, versions, seen = [], {}, set()
for line in symbols.splitlines():
    fields = line.split()
    if len(fields) == 4:
        size, kind, name = int(fields[1], 16), fields[2], fields[3]
    elif len(fields) == 3:
        size, kind, name = 0, fields[1], fields[2]
    else:
        continue
    name, _, version = name.partition("@")
    version = version.lstrip("@")
    if name not in wanted or name in seen:
        continue
    seen.add(name)
    if version:
        versions.setdefault(version, []).append(name)
    if kind in "TtWiI":
        asm.append(f'.text\n.globl "{name}"\n.type "{name}",@function\n"{name}":\n'
                   f' lea stub_zeros(%rip),%rax\n ret\n')
    else:
        size = max(size, 8)
        asm.append(f'.bss\n.globl "{name}"\n.type "{name}",@object\n.size "{name}",{size}\n'
                   f'"{name}":\n .zero {size}\n')
asm.append(".bss\n.balign 64\nstub_zeros:\n .zero 4096\n")
base = os.path.join(out, soname)
open(base + ".s", "w").write("".join(asm))
command = ["gcc", "-shared", "-nostdlib", "-Wl,-soname," + soname, "-o", base, base + ".s"]
if versions:
    open(base + ".map", "w").write(
        "".join(f"{v} {{ global: {' '.join(chr(34) + n + chr(34) + ';' for n in names)} }};\n"
                for v, names in versions.items()))
    command.insert(3, "-Wl,--version-script=" + base + ".map")
subprocess.run(command, check=True)
subprocess.run(["strip", base], check=True)
for suffix in (".s", ".map"):
    if os.path.exists(base + suffix):
        os.remove(base + suffix)
print(soname, len(seen), "symbols")
