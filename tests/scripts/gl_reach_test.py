#!/usr/bin/env python3
"""The GL stays behind the renderer: no non-test file outside the GL layers reaches a GL header.

Only render/ and the GL back-ends (platform/egl/, platform/openxr/, platform/output/) may include <GLES*/...> or
<EGL/...>, directly or through the headers they include; everything else talks to the renderer in its own types
(docs/design.md, "Layout"). This walks the project's include graph from the sources themselves: a quoted or
angled include that names a file of the project (from the root, or beside the including file) is followed, any
other is a system header and a leaf. The walk ignores #if, so it errs toward reporting.

Usage: gl_reach_test.py [--root DIR] [--list | --self-test]
  Exit 0 when no file outside the GL layers reaches GL; 1 naming each file that does, with one include chain.
  --list: print every such file and the count, exit 0 (for measuring).
  --self-test: the walk on a small made-up tree, so that the check is seen to fail where it should.
"""

import argparse
import os
import re
import subprocess
import sys

GL_LAYERS = ("render/", "platform/egl/", "platform/openxr/", "platform/output/")
GL_HEADER = re.compile(r"^(GLES\d*|EGL)/")
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]', re.MULTILINE)
SOURCE_SUFFIXES = (".h", ".hpp", ".cpp", ".cc", ".cxx", ".c", ".inl")


def project_files(root):
    """Every C/C++ file of the project, relative to root: git's list where there is one, else a walk."""
    try:
        out = subprocess.run(["git", "-C", root, "ls-files", "--cached", "--others", "--exclude-standard"],
                             check=True, capture_output=True, text=True).stdout
        files = out.split()
    except (OSError, subprocess.CalledProcessError):
        files = []
        for folder, dirs, names in os.walk(root):
            dirs[:] = [d for d in dirs if not d.startswith((".", "build"))]
            files += [os.path.relpath(os.path.join(folder, n), root) for n in names]
    return sorted(f for f in files if f.endswith(SOURCE_SUFFIXES) and os.path.isfile(os.path.join(root, f)))


def is_test(path):
    return path.startswith("tests/") or re.search(r"_test\.(cpp|h)$", path) is not None


def includes(root, path, known):
    """(project file or GL header, is_gl) for each #include of `path` that is one of those."""
    with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
        text = f.read()
    for _, name in INCLUDE.findall(text):
        if GL_HEADER.match(name):
            yield name, True
            continue
        beside = os.path.normpath(os.path.join(os.path.dirname(path), name))
        for candidate in (os.path.normpath(name), beside):
            if candidate in known:
                yield candidate, False
                break


def gl_chains(root, files):
    """file -> the shortest include chain [file, ..., GL header], for every file that reaches one."""
    known = set(files)
    chains = {}
    users = {f: [] for f in files}  # header -> the files that include it
    for path in files:
        for name, is_gl in includes(root, path, known):
            if is_gl:
                chains.setdefault(path, [path, name])
            else:
                users[name].append(path)
    # Breadth first from the files that include GL themselves, up through their users: each chain is a shortest.
    frontier = list(chains)
    while frontier:
        following = []
        for header in frontier:
            for user in users[header]:
                if user not in chains:
                    chains[user] = [user] + chains[header]
                    following.append(user)
        frontier = following
    return chains


def offenders(root):
    files = project_files(root)
    chains = gl_chains(root, files)
    return [chains[f] for f in files if f in chains and not is_test(f) and not f.startswith(GL_LAYERS)]


def self_test():
    """The walk on a tree made for it: a header that includes GL, a source outside the layers that reaches it
    through that header, one inside render/, and a test; only the first two are reported."""
    import tempfile
    with tempfile.TemporaryDirectory() as root:
        tree = {
            "render/gl_user.h": "#include <GLES3/gl3.h>\n",
            "render/plain.h": "#pragma once\n",
            "platform/app/uses_render.cpp": '#include "render/gl_user.h"\n',
            "platform/app/near.h": '#include "../../render/gl_user.h"\n',
            "platform/app/clean.cpp": '#include "render/plain.h"\n#include <vector>\n',
            "platform/output/out.cpp": '#include "render/gl_user.h"\n',
            "tests/render/gl_test.cpp": "#include <GLES3/gl3.h>\n",
        }
        for path, text in tree.items():
            os.makedirs(os.path.join(root, os.path.dirname(path)), exist_ok=True)
            with open(os.path.join(root, path), "w") as f:
                f.write(text)
        found = sorted(chain[0] for chain in offenders(root))
    expected = ["platform/app/near.h", "platform/app/uses_render.cpp"]
    if found != expected:
        print(f"gl_reach_test --self-test: expected {expected}, got {found}", file=sys.stderr)
        return 1
    print("gl_reach_test --self-test: the walk reports what reaches GL outside the layers, and only that")
    return 0


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", default=os.path.normpath(os.path.join(here, "..", "..")))
    parser.add_argument("--list", action="store_true", help="print the files and their count, exit 0")
    parser.add_argument("--self-test", action="store_true", help="check the walk on a small made-up tree")
    args = parser.parse_args()
    if args.self_test:
        return self_test()
    found = offenders(args.root)
    for chain in found:
        print(chain[0] + "  (" + " -> ".join(chain[1:]) + ")")
    print(f"{len(found)} non-test files outside {', '.join(GL_LAYERS)} reach a GL header")
    if found and not args.list:
        print("gl_reach_test: keep GL includes in render/ and the GL back-ends; give the renderer's public headers "
              "render's own types (render/gl_objects.h holds GL names without GL)", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
