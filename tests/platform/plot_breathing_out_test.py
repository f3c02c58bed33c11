"""scripts/plot-breathing without -o writes into $XDG_STATE_HOME/lungar/ (~/.local/state/lungar/), never over the
README's tracked .readme/breathing.png, which it used to overwrite. Runs without matplotlib and lungar-breathe
(stand-ins): only where the picture goes is checked. Usage: plot_breathing_out_test.py SCRIPT"""
import collections
import importlib.machinery
import importlib.util
import os
import sys
import tempfile
import types
from unittest import mock

script = sys.argv[1]
root = os.path.dirname(os.path.dirname(os.path.abspath(script)))
pyplot = mock.MagicMock()
matplotlib = types.ModuleType("matplotlib")
matplotlib.use = lambda backend: None
matplotlib.pyplot = pyplot
sys.modules["matplotlib"] = matplotlib
sys.modules["matplotlib.pyplot"] = pyplot
loader = importlib.machinery.SourceFileLoader("plot_breathing", script)
plot = importlib.util.module_from_spec(importlib.util.spec_from_loader("plot_breathing", loader))
loader.exec_module(plot)
plot.find_binary = lambda build_dir: "lungar-breathe"
# lungar-breathe's CSV: every column 0, a row per preset.
plot.breathe = lambda binary, *args: [collections.defaultdict(lambda: "0", preset=name) for name in plot.COLOURS]
followed = []
plot.plot_follow = lambda binary, out, *more: followed.append(out)  # more: a recording to plot, where given

failed = []
with tempfile.TemporaryDirectory() as tmp:
    for state, home, want in [(os.path.join(tmp, "state"), "/nonexistent", os.path.join(tmp, "state", "lungar")),
                              ("", tmp, os.path.join(tmp, ".local", "state", "lungar"))]:
        os.environ["XDG_STATE_HOME"] = state
        os.environ["HOME"] = home
        pyplot.figure.return_value.savefig.reset_mock()
        sys.argv = ["plot-breathing", os.path.join(root, "config", "scenarios", "teaching.toml")]
        plot.main()
        saved = pyplot.figure.return_value.savefig.call_args[0][0]
        if saved != os.path.join(want, "breathing.png"):
            failed.append(f"plot-breathing wrote {saved}, expected {want}/breathing.png")
        sys.argv = ["plot-breathing", "--follow"]
        plot.main()
        if followed[-1] != os.path.join(want, "breath-follow.png"):
            failed.append(f"plot-breathing --follow wrote {followed[-1]}, expected {want}/breath-follow.png")
for line in failed:
    print(line, file=sys.stderr)
sys.exit(1 if failed else 0)
