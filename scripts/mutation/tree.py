"""The mutation run's own copy of the project and its build: build-mutate/tree/ and build-mutate/tree/build/.

The copy is what git tracks (with the working tree's edits), refreshed file by file so that an unchanged file keeps
its time stamp and the incremental build stays incremental. The build is RelWithDebInfo at -O1 without debug
information (quick to compile, still optimised as the shipped code is); the libraries keep their unity batches, but
the files being mutated leave them (skip_unity.cmake), so that a mutant recompiles one file.
"""
import os
import shutil
import subprocess
from pathlib import Path

HERE = Path(__file__).resolve().parent


def tracked_files(root):
    """The project's files as git sees them: tracked ones and new ones not ignored."""
    out = subprocess.run(["git", "ls-files", "-z", "--cached", "--others", "--exclude-standard"], cwd=root,
                         check=True, capture_output=True).stdout
    return [f for f in out.decode().split("\0") if f and (Path(root) / f).is_file()]


def sync(root, tree):
    """Makes tree a copy of root's files, rewriting only those whose content differs."""
    tree.mkdir(parents=True, exist_ok=True)
    for rel in tracked_files(root):
        src, dst = Path(root) / rel, tree / rel
        data = src.read_bytes()
        if dst.is_file() and dst.read_bytes() == data:
            continue
        dst.parent.mkdir(parents=True, exist_ok=True)
        dst.write_bytes(data)
        shutil.copymode(src, dst)


def environment(tree):
    env = dict(os.environ)
    env["CCACHE_BASEDIR"] = str(tree)
    env.setdefault("CCACHE_SLOPPINESS", "pch_defines,time_macros")
    return env


def configure(root, tree, skip_unity_files, log):
    """Configures tree/build: once, and again when the files to take out of unity batches grew (the growing set
    keeps the batches stable from run to run)."""
    listing = tree.parent / "skip-unity.txt"
    known = set(listing.read_text().split("\n")) - {""} if listing.exists() else set()
    wanted = known | {str(tree / f) for f in skip_unity_files}
    if wanted == known and (tree / "build" / "CMakeCache.txt").exists():
        return
    listing.write_text("\n".join(sorted(wanted)) + "\n")
    shared = (Path(root) / ".." / "shared").resolve()
    generator = ["-G", "Ninja"] if shutil.which("ninja") and not (tree / "build" / "Makefile").exists() else []
    cmd = ["cmake", "-S", str(tree), "-B", str(tree / "build"), *generator, "-DCMAKE_BUILD_TYPE=RelWithDebInfo",
           "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g0 -DNDEBUG", "-DLUNGAR_UNITY_BUILD=ON", "-DLUNGAR_BENCH=OFF",
           f"-DLUNGAR_SHARED_DIR={shared}", f"-DCMAKE_PROJECT_INCLUDE={HERE / 'skip_unity.cmake'}",
           f"-DLUNGAR_MUTATE_FILES={listing}"]
    if shutil.which("ccache"):
        cmd += ["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache", "-DCMAKE_C_COMPILER_LAUNCHER=ccache"]
    subprocess.run(cmd, check=True, stdout=log, stderr=subprocess.STDOUT, env=environment(tree))


def build(tree, targets, jobs, log, timeout=None):
    """Builds the targets; True when they built."""
    cmd = ["cmake", "--build", str(tree / "build"), f"-j{jobs}", "--target", *sorted(targets)]
    try:
        done = subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT, env=environment(tree), timeout=timeout)
    except subprocess.TimeoutExpired:
        return False
    return done.returncode == 0


def executable(tree, target):
    """The path of a built executable target (found by name under the build folder)."""
    for path in sorted((tree / "build").rglob(target)):
        if path.is_file() and os.access(path, os.X_OK):
            return path
    raise FileNotFoundError(f"scripts/mutate: no executable '{target}' under {tree / 'build'}")
