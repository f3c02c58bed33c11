#!/usr/bin/python3
"""The README's "What a user does" table, executed: each row's commands run as written, so that a command that
stops working (a renamed option, a moved file, a changed default) fails the build's tests.

Usage: readme_commands_test.py --root SOURCE_DIR --build BUILD_DIR --cache CACHE_DIR [--only TEXT]

The commands run with these substitutions only, each for the reason given:
  - `scripts/run` and a bare `lungar` are BUILD_DIR's platform/lungar: the test runs in a built tree, so no apt and
    no second build, with the arguments exactly as written; `build/X` is BUILD_DIR/X for the same reason (the
    tree scripts/run and scripts/test build), and a `scripts/build ... && ` before a command is dropped. Scripts that build for themselves (scripts/classroom-demo,
    scripts/plot-breathing) are given BUILD_DIR in LUNGAR_BUILD_DIR, their own way to name an existing tree.
  - A runtime run's `--seconds N` becomes `--seconds 1` (added where absent; a lone `lungar` runs 10 s), and
    scripts/classroom-demo gets 4 seconds as its SECONDS argument: the run is checked, not the lesson.
  - `--headless` is added to a runtime run where there is no DISPLAY and no --output is given.
  - A bake's `--nodes N` becomes `--nodes 2000` (added where absent): a 400,000-node bake with its report takes
    minutes on two cores; every option the row gives is still given.
  - `lungar-trk info|dump|...` (a synopsis, not one command) runs each subcommand with --help.
The user's own files a row names (seg.nrrd, lung.stl, trace.csv, pivot.trk, ...) are stand-ins written by
readme_standins.py; files a row writes (stylus.toml, keys/) feed the rows after it, as they would a user.
Everything runs in a temporary folder that mirrors the project root (a symbolic link to each of its top-level
entries), so that relative paths resolve as from the root while what the rows write lands in the temporary folder;
XDG_CONFIG_HOME, XDG_STATE_HOME and HOME are temporary too, and XDG_CACHE_HOME is CACHE_DIR, one folder for the
whole build tree, so the demo's CT lungs are baked once (the first run) and loaded after that.

A row passes when each of its commands exits 0 and what the README promises exists and is not empty: a runtime
run's snapshot and stats in $XDG_STATE_HOME/lungar/, and every --out, --report-json and --record path. A row of the
table that is neither run (RUN) nor skipped with its reason (SKIP) fails the test, so a new row cannot slip by; so
does a name in RUN or SKIP that the table no longer has.
"""
import argparse
import os
import re
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import readme_standins  # noqa: E402

TABLE_HEADING = "## What a user does"

# Rows run, by their "to" cell. The value: seconds each command of the row may take (the first runtime run bakes
# the demo's CT lungs into an empty cache: minutes on a loaded two-core machine).
RUN = {
    "see the demo (window when `DISPLAY` is set, headless otherwise)": 900,
    "teach with a scripted scenario (breathing changes, patient turns)": 300,
    "replay a recorded tracker log": 300,
    "try OpenIGTLink without a tracker: a PlusServer stand-in, then lungar": 300,
    "bake lungs from a CT label map": 300,
    "bake a lung surface (a raw segmentation export too)": 300,
    "draw the procedural pair instead of the CT lungs": 900,
    "show a pathology (a collapsed lung, a consolidated third, emphysema, ARDS)": 300,
    "show where each breath goes (the ventilation map, V toggles it)": 300,
    "turn an ARDS patient prone; drop a tension pneumothorax and decompress it": 300,
    "breathe with a recorded respiratory trace": 300,
    "find the stylus tip (pivot it in a dimple while recording)": 120,
    "register the model onto the simulator": 120,
    "calibrate each eye of an optical see-through HMD (SPAAM)": 120,
    "make a secure classroom's keys": 120,
    "join a secure classroom": 300,
    "withdraw a lost HMD PC's identity": 120,
    "inspect, convert or make tracker logs, serve OpenIGTLink poses": 60,
    "plot breathing curves and a scenario (into `~/.local/state/lungar/breathing.png`)": 300,
    "try a classroom of four stations on this machine": 300,
    "check a machine's set-up (graphics, HMD output, tracker access, asset, disk), with the fixes": 300,
    "build Monado (bookworm has none) and try OpenXR without a headset": 600,
}

# Rows not run, by their "to" cell, with the reason.
SKIP = {
    "run with a profile, an asset and a tracker": "needs a HID tracker plugged in and the user's own profile and asset",
    "track with PlusServer or 3D Slicer (OpenIGTLink, see below)": "needs a PlusServer or 3D Slicer on a host of the "
    "network (the stand-in row below runs the same option against lungar-trk serve-igtl)",
    "use a shipped tracker profile (OSVR HDK, 3Glasses D3, SparkFun 9DoF Razor)": "needs the HMD's tracker plugged "
    "in (the profiles are parsed by TrackerProfiles.* in lungar_drivers_tests)",
    "record the tracker while running": "needs a HID tracker plugged in",
    "show full-screen on the HMD (extended mode)": "a profile setting, not a command; needs an HMD on a named X output",
    "show on a headset through its OpenXR runtime (Monado, SteamVR, a vendor's)": "needs a headset's OpenXR runtime "
    "installed as the active one (the Monado row runs the same option)",
    "breathe with a chest marker tracked live": "needs a HID tracker plugged in, its stylus sensor on the chest",
    "teach a classroom: one patient, one breath, many HMDs (Cyclone DDS)": "stations on several PCs of a LAN (the "
    "four-station row runs a classroom on this machine)",
    "install it as a Debian package, start it at login full screen on the HMD": "packaging and installing need root",
}

# Row-dependent conditions under which a RUN row is skipped on this machine, with the reason printed.
MONADO_MANIFEST = "build/_deps/monado/share/openxr/1/openxr_monado.json"


def condition_skip(to, root):
    if to.startswith("build Monado") and not os.path.exists(os.path.join(root, MONADO_MANIFEST)):
        return f"Monado is not built here ({MONADO_MANIFEST}; scripts/test runs scripts/setup-openxr first)"
    if to.startswith("plot breathing") and subprocess.run(["/usr/bin/python3", "-c", "import matplotlib"],
                                                          capture_output=True).returncode != 0:
        return "python3-matplotlib is not installed (scripts/test's plotting stack)"
    return None


def split_row(line):
    """The cells of a Markdown table row: split at each '|' not escaped as '\\|' (GitHub splits so, inside code
    spans too), with '\\|' unescaped."""
    cells = re.split(r"(?<!\\)\|", line.strip())
    if cells and cells[0] == "":
        cells = cells[1:]
    if cells and cells[-1] == "":
        cells = cells[:-1]
    return [c.strip().replace("\\|", "|") for c in cells]


def table_rows(readme):
    """(line number, "to" cell, "run" cell) for each row of the table under TABLE_HEADING; errors as lines."""
    with open(readme) as f:
        lines = f.read().split("\n")
    try:
        start = lines.index(TABLE_HEADING)
    except ValueError:
        return [], [f"{readme}: expected a section '{TABLE_HEADING}' with the table of commands, found none"]
    rows, errors, in_table = [], [], False
    for number, line in enumerate(lines[start + 1:], start + 2):
        if not line.startswith("|"):
            if in_table:
                break
            continue
        in_table = True
        cells = split_row(line)
        if cells == ["to", "run"] or all(set(c) <= set("-: ") for c in cells):
            continue
        if len(cells) != 2:
            errors.append(f"{readme}:{number}: expected 2 cells (to | run), got {len(cells)}: a '|' inside a "
                          "command must be written '\\|'")
            continue
        rows.append((number, cells[0], cells[1]))
    return rows, errors


# VAR=value before a command (a value may be a command's output, `$(...)`).
ENV_PREFIX = r"(?:[A-Z_]+=(?:\$\([^)]*\)|\S+)\s+)*"
COMMAND_START = re.compile("^" + ENV_PREFIX + r"(?:scripts/|build/|lungar\b)")


def commands_of(run_cell):
    """The commands of a "run" cell: its code spans that start as a command does (after any VAR=value)."""
    return [span for span in re.findall(r"`([^`]+)`", run_cell) if COMMAND_START.match(span)]


class Substitution:
    def __init__(self, build):
        self.build = build
        self.lungar = os.path.join(build, "platform", "lungar")

    def __call__(self, command):
        """The command as it runs here (see the module's doc), and whether it is a runtime run."""
        command = re.sub(r"^scripts/build(?: --\w+)* && ", "", command)
        command = re.sub(r"(?<![\w/.-])build/", self.build + "/", command)
        command = re.sub(r"(?<![\w/.-])scripts/run(?![\w-])", self.lungar, command)
        command = re.sub("^(" + ENV_PREFIX + r")lungar(?=\s|$)", lambda m: m.group(1) + self.lungar, command)
        m = re.match("^" + ENV_PREFIX + r"(\S+)(.*)$", command.rstrip(" &"))
        program, args = m.group(1), m.group(2).split()
        runtime = program == self.lungar and not (args and not args[0].startswith("-"))
        if runtime:
            if re.search(r"--seconds\s+\S+", command):
                command = re.sub(r"--seconds\s+\S+", "--seconds 1", command)
            else:
                command += " --seconds 1"
            if not os.environ.get("DISPLAY") and "--output" not in command:
                command += " --headless"
        if program.endswith("/lungar-bake") and args and args[0].startswith("-"):
            if "--nodes" in command:
                command = re.sub(r"--nodes\s+\d+", "--nodes 2000", command)
            else:
                command += " --nodes 2000"
        if program.endswith("scripts/classroom-demo") and not args:
            command += " 4"
        return command, runtime


def synopsis(command):
    """`TOOL a|b|c ...` -> `TOOL a --help`, `TOOL b --help`, ... (None when the command is no synopsis)."""
    m = re.match(r"^(\S+) ((?:[\w-]+\|)+[\w-]+) \.\.\.$", command)
    return [f"{m.group(1)} {sub} --help" for sub in m.group(2).split("|")] if m else None


def promised_files(command):
    """The paths the command says it writes: every --out, --report-json and --record argument."""
    return re.findall(r"--(?:out|report-json|record)\s+(\S+)", command)


def non_empty(path):
    if os.path.isdir(path):
        return any(os.scandir(path))
    return os.path.isfile(path) and os.path.getsize(path) > 0


def mirror_root(root, folder):
    """Links each top-level entry of the project root into `folder` (not out/, which scripts write into)."""
    for name in os.listdir(root):
        if name not in (".git", "out"):
            os.symlink(os.path.join(root, name), os.path.join(folder, name))


def run_row(number, to, run_cell, timeout, ctx):
    """Runs one row's commands in order (a command ending in '&' in the background until the row ends); returns
    the failures as lines naming the row."""
    failures, background = [], []
    where = f"README.md:{number}: row '{to}'"
    commands = commands_of(run_cell)
    if not commands:
        return [f"{where}: expected a command in `backticks` in its run cell, found none"]
    try:
        for written in commands:
            expanded = synopsis(re.sub(r"(?<![\w/.-])build/", ctx["build"] + "/", written))
            for command in expanded or [written]:
                here, runtime = ctx["substitute"](command)
                state = tempfile.mkdtemp(prefix="state-", dir=ctx["work"])
                env = dict(ctx["env"], XDG_STATE_HOME=state)
                started = time.monotonic()
                if here.rstrip().endswith("&"):
                    log = open(os.path.join(state, "background.log"), "w+")  # a file: a pipe could fill and block it
                    background.append((subprocess.Popen(["bash", "-c", here.rstrip(" &")], cwd=ctx["work"], env=env,
                                                        stdout=log, stderr=log, start_new_session=True), log))
                    time.sleep(0.5)  # the server listens before the client starts (the client retries anyway)
                    print(f"  started  {here}", flush=True)
                    continue
                child = subprocess.Popen(["bash", "-c", here], cwd=ctx["work"], env=env, stdout=subprocess.PIPE,
                                         stderr=subprocess.PIPE, text=True, start_new_session=True)
                try:
                    out, err = child.communicate(timeout=timeout)
                except subprocess.TimeoutExpired:
                    os.killpg(child.pid, signal.SIGKILL)  # the whole group: lungar, its bake, a script's children
                    child.communicate()
                    failures.append(f"{where}: `{written}` ran past {timeout} s (ran: {here})")
                    continue
                took = time.monotonic() - started
                print(f"  {took:6.1f} s  exit {child.returncode}  {here}", flush=True)
                if child.returncode != 0:
                    tail = "\n".join(("    " + l) for l in (err or out).strip().split("\n")[-6:])
                    failures.append(f"{where}: `{written}` exited {child.returncode} (ran: {here})\n{tail}")
                    continue
                for path in promised_files(here):
                    if not non_empty(os.path.join(ctx["work"], path)):
                        failures.append(f"{where}: `{written}` exited 0 but wrote no {path} (or an empty one)")
                if runtime:
                    for name in ("snapshot.png", "stats.json"):
                        if not non_empty(os.path.join(state, "lungar", name)):
                            failures.append(f"{where}: `{written}` exited 0 but wrote no {name} into "
                                            "$XDG_STATE_HOME/lungar/ (the README: snapshot and stats there)")
                if to.startswith("plot breathing") and not non_empty(os.path.join(state, "lungar", "breathing.png")):
                    failures.append(f"{where}: `{written}` exited 0 but drew no $XDG_STATE_HOME/lungar/breathing.png")
    finally:
        for p, log in background:
            if p.poll() is not None and p.returncode != 0:
                log.seek(0)
                failures.append(f"{where}: the background command exited {p.returncode}: {log.read().strip()}")
            elif p.poll() is None:
                os.killpg(p.pid, signal.SIGTERM)
                p.wait()
            log.close()
    return failures


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--root", required=True)
    parser.add_argument("--build", required=True)
    parser.add_argument("--cache", required=True)
    parser.add_argument("--only", help="run only the rows whose 'to' cell contains this text")
    a = parser.parse_args()
    root, build, cache = (os.path.abspath(p) for p in (a.root, a.build, a.cache))
    readme = os.path.join(root, "README.md")
    rows, failures = table_rows(readme)
    seen = {to for _, to, _ in rows}
    for number, to, _ in rows:
        if to not in RUN and to not in SKIP:
            failures.append(f"{readme}:{number}: row '{to}' is neither run nor skipped with a reason: add it to RUN "
                            f"or SKIP in {os.path.abspath(__file__)}")
    for to in [*RUN, *SKIP]:
        if to not in seen:
            failures.append(f"{os.path.abspath(__file__)}: row '{to}' (RUN or SKIP) is not in {readme}'s table")
    os.makedirs(cache, exist_ok=True)
    started = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="lungar-readme-") as work:
        mirror_root(root, work)
        readme_standins.write_all(work, root)
        for sub in ("home", "config"):
            os.makedirs(os.path.join(work, ".readme-" + sub))
        env = dict(os.environ, HOME=os.path.join(work, ".readme-home"), XDG_CACHE_HOME=cache,
                   XDG_CONFIG_HOME=os.path.join(work, ".readme-config"), LUNGAR_BUILD_DIR=build)
        ctx = {"build": build, "work": work, "env": env, "substitute": Substitution(build)}
        for number, to, run_cell in rows:
            if a.only and a.only not in to:
                continue
            if to in SKIP:
                print(f"skip  README.md:{number}: {to}: {SKIP[to]}", flush=True)
                continue
            if to not in RUN:
                continue
            reason = condition_skip(to, root)
            if reason:
                print(f"skip  README.md:{number}: {to}: {reason}", flush=True)
                continue
            print(f"run   README.md:{number}: {to}", flush=True)
            failures += run_row(number, to, run_cell, RUN[to], ctx)
    print(f"{len(rows)} rows, {time.monotonic() - started:.0f} s", flush=True)
    for f in failures:
        print("FAIL  " + f, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
