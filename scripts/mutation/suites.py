"""Which tests a mutant runs (scripts/mutation/tests.txt), and which mutants are known equivalent
(docs/mutants-equivalent.txt)."""


def load_map(path):
    """[(folder, target, gtest filter)] from the map's `FOLDER TARGET FILTER` lines."""
    rows = []
    for n, line in enumerate(path.read_text(encoding="utf-8").split("\n"), start=1):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        parts = line.split()
        if len(parts) != 3:
            raise SystemExit(f"{path}:{n}: expected FOLDER TARGET GTEST_FILTER")
        rows.append((parts[0].rstrip("/"), parts[1], parts[2]))
    return rows


def suites_for(rows, rel):
    """The (target, filter) pairs of the longest folder in the map that holds the file rel."""
    matching = [r for r in rows if rel.startswith(r[0] + "/")]
    if not matching:
        return []
    longest = max(len(r[0]) for r in matching)
    return [(t, f) for folder, t, f in matching if len(folder) == longest]


def load_equivalents(path):
    """The keys (`file:line: mutant`) of the lines `file:line: mutant — why`; '#' starts a comment line."""
    keys = set()
    if not path.exists():
        return keys
    for line in path.read_text(encoding="utf-8").split("\n"):
        if line.strip() and not line.startswith("#") and " — " in line:
            keys.add(line.split(" — ", 1)[0].strip())
    return keys
